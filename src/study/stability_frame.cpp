#include "study/stability_frame.h"

#include <array>
#include <cmath>

#include "study/stability_shading.h"

namespace proxygi::study {
namespace {

struct Basis {
  glm::vec3 forward, right, up;
  float tangent;
};

Basis camera_basis(const SweepCamera& camera) {
  Basis b;
  b.forward = glm::normalize(camera.target - camera.eye);
  b.right = glm::normalize(glm::cross(b.forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  b.up = glm::cross(b.right, b.forward);
  b.tangent = std::tan(0.5f * glm::radians(camera.fov_y_degrees));
  return b;
}

}  // namespace

SweepGBuffer trace_gbuffer(std::span<const render::Sphere> spheres, const SweepCamera& camera, int size) {
  const Basis b = camera_basis(camera);
  SweepGBuffer g;
  g.size = size;
  const std::size_t n = std::size_t(size) * std::size_t(size);
  g.position.assign(n, glm::vec3(0.0f));
  g.normal.assign(n, glm::vec3(0.0f, 1.0f, 0.0f));
  g.depth = ref::Plane(size, size, 0.0f);
  g.label.assign(n, -1);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float sx = (2.0f * (float(x) + 0.5f) / float(size) - 1.0f) * b.tangent;
      const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(size)) * b.tangent;
      const glm::vec3 d = glm::normalize(b.forward + sx * b.right + sy * b.up);
      float best = INFINITY;
      int label = -1;
      glm::vec3 normal(0.0f, 1.0f, 0.0f);
      if (d.y < 0.0f) best = -camera.eye.y / d.y, label = 0;
      for (std::size_t index = 0; index < spheres.size(); ++index) {
        const render::Sphere& s = spheres[index];
        const glm::vec3 o = camera.eye - s.center;
        const float half_b = glm::dot(o, d), c = glm::dot(o, o) - s.radius * s.radius;
        const float disc = half_b * half_b - c;
        if (disc < 0.0f) continue;
        const float t = -half_b - std::sqrt(disc);
        if (t > 0.0f && t < best) best = t, label = 1 + int(index), normal = glm::normalize(camera.eye + t * d - s.center);
      }
      if (label < 0) continue;
      const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
      g.position[i] = camera.eye + best * d;
      g.normal[i] = normal;
      g.depth.values[i] = best * glm::dot(d, b.forward);
      g.label[i] = label;
    }
  return g;
}

SweepImage render_sweep_frame(const render::FrameTables& tables, std::span<const render::Sphere> spheres,
                              const SweepGBuffer& g, int k, settings::Upsampling upsampling, float depth_epsilon) {
  const int size = g.size;
  const int receivers = (size + k - 1) / k;
  auto at = [&](int x, int y) { return std::size_t(y) * std::size_t(size) + std::size_t(x); };
  struct Receiver {
    float value = 0.0f, unshadowed = 0.0f, depth = 0.0f;
    glm::vec3 position{0.0f}, normal{0.0f, 1.0f, 0.0f};
  };
  std::vector<Receiver> shaded(std::size_t(receivers) * std::size_t(receivers));
  for (int ry = 0; ry < receivers; ++ry)
    for (int rx = 0; rx < receivers; ++rx) {
      const glm::ivec2 texel = render::select_receiver(rx, ry, k, size, size, [&](int x, int y) { return g.depth.at(x, y); });
      if (texel.x < 0) continue;
      const std::size_t i = at(texel.x, texel.y);
      Receiver& r = shaded[std::size_t(ry) * std::size_t(receivers) + std::size_t(rx)];
      const MethodShade shade = shade_method(tables, 0.25f, g.position[i], g.normal[i], spheres);
      r.value = float(shade.value), r.unshadowed = float(shade.unshadowed);
      r.depth = g.depth.values[i], r.position = g.position[i], r.normal = g.normal[i];
    }
  SweepImage image{ref::Plane(size, size), ref::Plane(size, size), ref::Plane(size, size)};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const std::size_t i = at(x, y);
      if (g.label[i] < 0) continue;
      image.pixel_unshadowed.values[i] = float(shade_method(tables, 0.25f, g.position[i], g.normal[i], {}).unshadowed);
      if (k == 1) {
        image.shade.values[i] = shaded[i].value;
        image.unshadowed.values[i] = shaded[i].unshadowed;
        continue;
      }
      const render::UpsampleFootprint footprint = render::upsample_footprint(x, y, k, glm::ivec2(receivers));
      std::array<render::UpsampleTap, 4> taps;
      for (std::size_t tap = 0; tap < 4; ++tap) {
        const glm::ivec2 source = footprint.source[tap];
        const Receiver& r = shaded[std::size_t(source.y) * std::size_t(receivers) + std::size_t(source.x)];
        render::UpsampleTap& t = taps[tap];
        t.value = glm::vec3(r.value, r.unshadowed, 0.0f);  // upsampled with the same taps
        t.position = r.position, t.depth = r.depth, t.normal = r.normal;
        t.bilinear_weight = footprint.bilinear_weight[tap];
      }
      const glm::vec3 both =
          render::upsample(std::span<const render::UpsampleTap, 4>(taps), g.position[i], g.depth.values[i], g.normal[i], upsampling, depth_epsilon);
      image.shade.values[i] = both.x;
      image.unshadowed.values[i] = both.y;
    }
  return image;
}

Reprojection reproject(const SweepGBuffer& from, const SweepCamera& to_camera, const SweepGBuffer& to) {
  const Basis b = camera_basis(to_camera);
  Reprojection r{from.size, from.size, std::vector<int>(from.label.size(), -1)};
  for (std::size_t i = 0; i < from.label.size(); ++i) {
    if (from.label[i] < 0) continue;
    const glm::vec3 v = from.position[i] - to_camera.eye;
    const float z = glm::dot(v, b.forward);
    if (z <= 0.0f) continue;
    const float nx = glm::dot(v, b.right) / (z * b.tangent), ny = glm::dot(v, b.up) / (z * b.tangent);
    const int x = int(std::floor((nx + 1.0f) * 0.5f * float(to.size))), y = int(std::floor((1.0f - ny) * 0.5f * float(to.size)));
    if (x < 0 || y < 0 || x >= to.size || y >= to.size) continue;
    const std::size_t j = std::size_t(y) * std::size_t(to.size) + std::size_t(x);
    if (to.label[j] != from.label[i] || std::abs(to.depth.values[j] - z) > 0.02f * z) continue;
    r.source[i] = int(j);
  }
  return r;
}

}  // namespace proxygi::study
