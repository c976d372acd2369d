#include "run/gpu_receiver_shader.h"

#include <glm/glm.hpp>

#include "gpu/draw_item.h"
#include "gpu/soft_gi_frame.h"
#include "image/image.h"
#include "scene/camera.h"

namespace proxygi::run {
namespace {

constexpr std::uint32_t kSize = 15;  // odd: the centre pixel's ray passes through the camera's target
constexpr std::uint32_t kCentre = kSize / 2;
constexpr float kReceiverTolerance = 0.0025f;  // m: how far the centre receiver may lie from the origin

class FrameReceiverShader final : public study::GpuReceiverShader {
 public:
  FrameReceiverShader(gpu::Context& context, gpu::StaticMesh ground) : context_(context), ground_(std::move(ground)) {}

  Result<std::vector<study::GpuReceiverShade>> shade(const render::FrameTables& tables, settings::SplatMethod splat,
                                                     std::span<const std::vector<render::Sphere>> frames) override {
    gpu::FrameConfig config;
    config.render = tables.settings;
    config.render.splat = splat;
    config.render.receiver_scale = 1;
    config.render.indirect_method = settings::IndirectMethod::none;
    config.width = config.height = kSize;
    config.frames_in_flight = 1;
    auto frame = gpu::SoftGiFrame::create(context_, config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
    if (!frame) return frame.error();
    const gpu::DrawItem draws[] = {ground_.draw()};
    scene::CameraState camera;
    camera.eye = glm::vec3(0.0f, 2.0f, 0.5f);
    camera.target = glm::vec3(0.0f);
    camera.fov_y_degrees = 2.0f;
    const gpu::FrameView view = gpu::frame_view(camera, 1.0f);
    auto render = [&](std::span<const render::Sphere> spheres) -> Result<double> {
      if (Status written = (*frame)->write_slot(0, view, spheres); !written) return written.error();
      if (Status done = context_.submit_and_wait([&](VkCommandBuffer c) { (*frame)->record(c, 0, draws, gpu::FrameOutput::readback()); }); !done)
        return done.error();
      auto direct = (*frame)->read_direct();
      if (!direct) return direct.error();
      return image::rec709_luminance(direct->at(int(kCentre), int(kCentre)));
    };
    auto open = render({});
    if (!open) return open.error();
    auto positions = (*frame)->read_receiver_positions();
    if (!positions) return positions.error();
    if (glm::length(glm::vec3(positions->at(int(kCentre), int(kCentre)))) > kReceiverTolerance)
      return make_error("gpu receiver: the centre receiver is not at the origin");
    std::vector<study::GpuReceiverShade> out;
    for (const std::vector<render::Sphere>& spheres : frames) {
      auto shadowed = render(spheres);
      if (!shadowed) return shadowed.error();
      out.push_back({*shadowed, *open});
    }
    return out;
  }

 private:
  gpu::Context& context_;
  gpu::StaticMesh ground_;
};

}  // namespace

Result<std::unique_ptr<study::GpuReceiverShader>> make_gpu_receiver_shader(gpu::Context& context) {
  const glm::vec3 positions[] = {{-10.0f, 0.0f, -10.0f}, {10.0f, 0.0f, -10.0f}, {10.0f, 0.0f, 10.0f}, {-10.0f, 0.0f, 10.0f}};
  const glm::vec3 normals[] = {{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  const std::uint32_t indices[] = {0, 3, 1, 1, 3, 2};  // the winding of the GPU tests' ground grid
  auto ground = gpu::upload_static_mesh(context, positions, normals, indices, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f));
  if (!ground) return ground.error();
  return std::unique_ptr<study::GpuReceiverShader>(std::make_unique<FrameReceiverShader>(context, std::move(*ground)));
}

}  // namespace proxygi::run
