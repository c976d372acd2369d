#pragma once
// A small test scene for the soft-GI frame: a 20 m ground plane at y = 0, proxy spheres above it,
// a camera looking down at the origin, and a constant white sky (radiance 1), so the closed form
// E = π − π (r/d)² cos β holds for a sphere fully above a receiver's horizon.
#include <cmath>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "gpu/context.h"
#include "gpu/soft_gi_frame.h"
#include "render/frame_tables.h"
#include "sh/environment.h"

namespace proxygi::gpu::testing {

inline sh::RgbSh constant_sky_sh(int order, double radiance) {
  sh::RgbSh sky;
  sky.order = order;
  for (auto& channel : sky.channels) {
    channel.assign(std::size_t(order * order), 0.0);
    channel[0] = radiance * 3.5449077018110318;  // projection of a constant: c · √4π
  }
  return sky;
}

inline FrameView look_at(const glm::vec3& eye, const glm::vec3& target, float fov_degrees, float aspect) {
  FrameView view;
  view.eye = eye;
  view.forward = glm::normalize(target - eye);
  view.view = glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
  view.projection = glm::perspectiveRH_ZO(glm::radians(fov_degrees), aspect, 0.05f, 100.0f);
  view.projection[1][1] *= -1.0f;  // Vulkan framebuffer y points down
  return view;
}

struct GroundMesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
};

// A grid so the plane has interior vertices (not needed for shading, but keeps depth precise).
inline GroundMesh ground_plane(float size, int cells) {
  GroundMesh mesh;
  for (int z = 0; z <= cells; ++z)
    for (int x = 0; x <= cells; ++x) {
      mesh.positions.emplace_back(size * (float(x) / cells - 0.5f), 0.0f, size * (float(z) / cells - 0.5f));
      mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  for (int z = 0; z < cells; ++z)
    for (int x = 0; x < cells; ++x) {
      const std::uint32_t i = std::uint32_t(z * (cells + 1) + x);
      const std::uint32_t row = std::uint32_t(cells + 1);
      mesh.indices.insert(mesh.indices.end(), {i, i + row, i + 1, i + 1, i + row, i + row + 1});
    }
  return mesh;
}

// One frame of the fixture scene, rendered and finished: `ground` (any mesh with positions,
// normals, indices; albedo 0.8) under `lighting` at SH order `order`, the camera at `eye` looking
// at the origin, `config` as given (one frame in flight; the vertex method gets receivers for
// every ground vertex). `ground_input`: the ground the tables light receivers above it with (none
// by default). Failures are reported through gtest; `frame` is null after one.
struct RenderedFrame {
  std::unique_ptr<SoftGiFrame> frame;
  render::FrameTables tables;
};
template <class Ground>
RenderedFrame render_fixture_frame(Context& context, FrameConfig config, const sh::RgbSh& lighting, int order,
                                   const Ground& ground, const std::vector<render::Sphere>& spheres,
                                   const glm::vec3& eye = {0.0f, 4.0f, 3.0f},
                                   const render::GroundInput& ground_input = {}) {
  RenderedFrame out;
  config.render.sh_order = order;
  out.tables = render::make_frame_tables(lighting, config.render, ground_input);
  auto mesh = upload_static_mesh(context, ground.positions, ground.normals, ground.indices, glm::vec4(0.8f, 0.8f, 0.8f, 1));
  EXPECT_TRUE(mesh.ok());
  if (!mesh.ok()) return out;
  const DrawItem draws[] = {mesh->draw()};
  config.frames_in_flight = 1;
  if (config.render.method == settings::ShadingMethod::vertex) config.vertex_receivers = vertex_receiver_count(draws);
  auto frame = SoftGiFrame::create(context, config, out.tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  EXPECT_TRUE(frame.ok()) << (frame.ok() ? "" : frame.message());
  if (!frame.ok()) return out;
  out.frame = std::move(*frame);
  EXPECT_TRUE(out.frame->write_slot(0, look_at(eye, {0.0f, 0.0f, 0.0f}, 60.0f, 1.0f), spheres).ok());
  EXPECT_TRUE(context.submit_and_wait([&](VkCommandBuffer commands) { out.frame->record(commands, 0, draws, FrameOutput::readback()); }).ok());
  return out;
}

// One receiver of a finished frame: its texel (receiver resolution), its index in the receiver
// buffers (y · width + x), and its world-space position and unit normal.
struct ReceiverSample {
  int x = 0, y = 0;
  std::size_t index = 0;
  glm::vec3 position{0.0f}, normal{0.0f};
};

// Calls visit(sample) for every receiver with a position (w > 0) on a grid of `stride` texels.
// The twin tests walk the receivers this way; the reads are reported through gtest.
template <class Visit>
void for_each_receiver(const SoftGiFrame& frame, int stride, Visit&& visit) {
  auto positions = frame.read_receiver_positions();
  auto normals = frame.read_receiver_normals();
  ASSERT_TRUE(positions.ok() && normals.ok());
  for (int y = 0; y < positions->height; y += stride)
    for (int x = 0; x < positions->width; x += stride) {
      const glm::vec4 p = positions->at(x, y);
      if (p.w <= 0.0f) continue;
      visit(ReceiverSample{x, y, std::size_t(y) * std::size_t(positions->width) + std::size_t(x), glm::vec3(p),
                           glm::vec3(normals->at(x, y))});
    }
}

// |gpu − cpu| and |cpu| of one receiver's log-occlusion vector, read from the frame's
// receiver-major buffer (n² floats per receiver).
struct VectorError {
  float difference = 0.0f, norm = 0.0f;
};
inline VectorError log_occlusion_error(const std::vector<float>& gpu_buffer, std::size_t receiver,
                                       const std::vector<float>& cpu) {
  double difference = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    const double gpu = gpu_buffer[receiver * cpu.size() + i];
    difference += (gpu - cpu[i]) * (gpu - cpu[i]);
    norm += double(cpu[i]) * cpu[i];
  }
  return {float(std::sqrt(difference)), float(std::sqrt(norm))};
}

}  // namespace proxygi::gpu::testing
