#include "apps/record_output.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <system_error>

namespace proxygi::app {
namespace {

std::string frame_stem(int frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%05d", frame);
  return name;
}

// Scalar (O_p)_0 from the direct buffer's alpha, shown in rgb.
image::ImageF alpha_as_gray(const image::ImageF& source) {
  image::ImageF out(source.width, source.height);
  for (std::size_t i = 0; i < source.pixels.size(); ++i) {
    const float a = source.pixels[i].a;
    out.pixels[i] = glm::vec4(a, a, a, 1.0f);
  }
  return out;
}

// RGB kept, alpha forced to 1 so viewers show the color (the alpha channels carry other data).
image::ImageF opaque(image::ImageF image) {
  for (glm::vec4& p : image.pixels) p.a = 1.0f;
  return image;
}

}  // namespace

std::filesystem::path frame_file(const std::filesystem::path& dir, int frame, std::string_view extension) {
  return dir / (frame_stem(frame) + "." + std::string(extension));
}

std::filesystem::path aov_file(const std::filesystem::path& dir, int frame, std::string_view name,
                               std::string_view extension) {
  return dir / "aov" / (frame_stem(frame) + "_" + std::string(name) + "." + std::string(extension));
}

bool frame_done(const std::filesystem::path& dir, int frame, bool exr, bool aov) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(frame_file(dir, frame, "png"), error)) return false;
  if (exr && !std::filesystem::is_regular_file(frame_file(dir, frame, "exr"), error)) return false;
  return !aov || std::filesystem::is_regular_file(aov_file(dir, frame, "proxies", "png"), error);
}

image::ImageF ldr_to_linear(std::span<const std::uint8_t> rgba8, int width, int height) {
  std::array<float, 256> to_linear{};
  for (int code = 0; code < 256; ++code) to_linear[std::size_t(code)] = image::srgb_to_linear(float(code) / 255.0f);
  image::ImageF out(width, height);
  for (std::size_t i = 0; i < out.pixels.size() && 4 * i + 3 < rgba8.size(); ++i) {
    const std::uint8_t* p = &rgba8[4 * i];
    out.pixels[i] = glm::vec4(to_linear[p[0]], to_linear[p[1]], to_linear[p[2]], float(p[3]) / 255.0f);
  }
  return out;
}

Status write_frame_files(const std::filesystem::path& dir, int frame, std::span<const std::uint8_t> ldr,
                         const image::ImageF& hdr, int width, int height, bool exr) {
  if (ldr.size() != std::size_t(width) * std::size_t(height) * 4)
    return make_error("frame " + std::to_string(frame) + ": LDR readback has " + std::to_string(ldr.size()) +
                      " bytes, expected " + std::to_string(std::size_t(width) * std::size_t(height) * 4));
  // EXR first: the PNG is what a quick look (and ffmpeg) sees, so it appears last.
  if (exr)
    if (Status s = image::write_exr(frame_file(dir, frame, "exr"), hdr); !s) return s;
  return image::write_png_rgba8(frame_file(dir, frame, "png"), ldr, width, height);
}

void draw_sphere_outlines(image::ImageF& image, std::span<const render::Sphere> spheres,
                          const scene::CameraState& camera) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
  const glm::vec4 color(1.0f, 0.85f, 0.0f, 1.0f);
  for (const render::Sphere& sphere : spheres) {
    const float depth = glm::dot(sphere.center - camera.eye, forward);
    if (depth <= camera.near_m || depth <= sphere.radius) continue;  // behind or around the eye
    const glm::vec2 center = scene::project_to_pixel(camera, image.width, image.height, sphere.center);
    const float radius_px = sphere.radius / (depth * tan_half) * 0.5f * float(image.height);
    const int steps = std::max(16, int(std::ceil(2.0f * std::numbers::pi_v<float> * radius_px * 1.5f)));
    for (int s = 0; s < steps; ++s) {
      const float angle = 2.0f * std::numbers::pi_v<float> * float(s) / float(steps);
      const int x = int(std::floor(center.x + radius_px * std::cos(angle)));
      const int y = int(std::floor(center.y + radius_px * std::sin(angle)));
      if (x >= 0 && y >= 0 && x < image.width && y < image.height) image.at(x, y) = color;
    }
  }
}

Status write_aovs(const std::filesystem::path& dir, int frame, const gpu::SoftGiFrame& frame_buffers,
                  const image::ImageF& final_frame, std::span<const render::Sphere> spheres,
                  const scene::CameraState& camera) {
  std::error_code error;
  std::filesystem::create_directories(dir / "aov", error);
  if (error) return make_error((dir / "aov").string() + ": " + error.message());

  auto receivers = frame_buffers.read_receiver_positions();
  if (!receivers) return receivers.error();
  if (Status s = image::write_exr(aov_file(dir, frame, "receivers", "exr"), *receivers); !s) return s;
  auto direct = frame_buffers.read_direct();
  if (!direct) return direct.error();
  if (Status s = image::write_exr(aov_file(dir, frame, "occlusion_dc", "exr"), alpha_as_gray(*direct)); !s) return s;
  if (Status s = image::write_exr(aov_file(dir, frame, "direct", "exr"), opaque(*direct)); !s) return s;
  auto indirect = frame_buffers.read_indirect();
  if (!indirect) return indirect.error();
  if (Status s = image::write_exr(aov_file(dir, frame, "indirect", "exr"), opaque(*indirect)); !s) return s;
  auto irradiance = frame_buffers.read_irradiance();
  if (!irradiance) return irradiance.error();
  if (Status s = image::write_exr(aov_file(dir, frame, "upsampled", "exr"), opaque(*irradiance)); !s) return s;

  image::ImageF overlay = final_frame;
  draw_sphere_outlines(overlay, spheres, camera);
  return image::write_png(aov_file(dir, frame, "proxies", "png"), overlay);
}

}  // namespace proxygi::app
