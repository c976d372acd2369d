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
  return trace_gbuffer(SweepGeometry{{spheres.begin(), spheres.end()}, {}, {}}, camera, size);
}

namespace {

// The nearest hit so far along one ray.
struct Hit {
  float t = INFINITY;
  int label = -1;
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  void take(float candidate, int candidate_label, const glm::vec3& candidate_normal) {
    if (candidate > 0.0f && candidate < t) t = candidate, label = candidate_label, normal = candidate_normal;
  }
};

void hit_sphere(Hit& hit, const glm::vec3& eye, const glm::vec3& d, const render::Sphere& s, int label) {
  const glm::vec3 o = eye - s.center;
  const float half_b = glm::dot(o, d), c = glm::dot(o, o) - s.radius * s.radius;
  const float disc = half_b * half_b - c;
  if (disc < 0.0f) return;
  const float t = -half_b - std::sqrt(disc);
  if (t > 0.0f && t < hit.t) hit.take(t, label, glm::normalize(eye + t * d - s.center));
}

void hit_pole(Hit& hit, const glm::vec3& eye, const glm::vec3& d, const SweepPole& pole, int label) {
  // The side: |(eye + t d).xz − foot|² = r², the near root, 0 ≤ y ≤ height.
  const glm::vec2 o = glm::vec2(eye.x, eye.z) - pole.foot_xz, dxz(d.x, d.z);
  const float a = glm::dot(dxz, dxz), half_b = glm::dot(o, dxz), c = glm::dot(o, o) - pole.radius * pole.radius;
  const float disc = half_b * half_b - a * c;
  if (a > 0.0f && disc >= 0.0f) {
    const float t = (-half_b - std::sqrt(disc)) / a;
    const float y = eye.y + t * d.y;
    if (y >= 0.0f && y <= pole.height) {
      const glm::vec2 n = (o + t * dxz) / pole.radius;
      hit.take(t, label, glm::vec3(n.x, 0.0f, n.y));
    }
  }
  if (d.y < 0.0f && eye.y > pole.height) {  // the top cap
    const float t = (pole.height - eye.y) / d.y;
    const glm::vec2 q = glm::vec2(eye.x, eye.z) + t * dxz - pole.foot_xz;
    if (glm::dot(q, q) <= pole.radius * pole.radius) hit.take(t, label, glm::vec3(0.0f, 1.0f, 0.0f));
  }
}

void hit_wall(Hit& hit, const glm::vec3& eye, const glm::vec3& d, const SweepWall& wall, int label) {
  const float facing = glm::dot(wall.normal, d);
  if (facing >= 0.0f) return;  // seen from behind or edge-on
  const float t = glm::dot(wall.normal, wall.base_center - eye) / facing;
  const glm::vec3 p = eye + t * d;
  const glm::vec3 across = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), wall.normal);
  if (p.y >= 0.0f && p.y <= wall.height && std::abs(glm::dot(p - wall.base_center, across)) <= wall.half_width)
    hit.take(t, label, wall.normal);
}

}  // namespace

float eye_depth(const SweepCamera& camera, const glm::vec3& point) {
  return glm::dot(point - camera.eye, camera_basis(camera).forward);
}

float pixel_size_at(const SweepCamera& camera, int size, float depth) {
  return 2.0f * depth * camera_basis(camera).tangent / float(size);
}

SweepGBuffer trace_gbuffer(const SweepGeometry& geometry, const SweepCamera& camera, int size) {
  const Basis b = camera_basis(camera);
  SweepGBuffer g;
  g.size = size;
  g.spheres = int(geometry.spheres.size());
  g.poles = int(geometry.poles.size());
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
      Hit hit;
      if (d.y < 0.0f) hit.take(-camera.eye.y / d.y, 0, glm::vec3(0.0f, 1.0f, 0.0f));
      for (std::size_t i = 0; i < geometry.spheres.size(); ++i) hit_sphere(hit, camera.eye, d, geometry.spheres[i], 1 + int(i));
      for (std::size_t i = 0; i < geometry.poles.size(); ++i) hit_pole(hit, camera.eye, d, geometry.poles[i], g.pole_label(int(i)));
      for (std::size_t i = 0; i < geometry.walls.size(); ++i) hit_wall(hit, camera.eye, d, geometry.walls[i], g.wall_label(int(i)));
      if (hit.label < 0) continue;
      const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
      g.position[i] = camera.eye + hit.t * d;
      g.normal[i] = hit.normal;
      g.depth.values[i] = hit.t * glm::dot(d, b.forward);
      g.label[i] = hit.label;
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
  SweepImage image{ref::Plane(size, size), std::vector<bool>(std::size_t(size) * std::size_t(size), false), ref::Plane(size, size),
                   ref::Plane(size, size)};
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
      const render::Upsampled both = render::upsample_with_match(std::span<const render::UpsampleTap, 4>(taps), g.position[i],
                                                                 g.depth.values[i], g.normal[i], upsampling, depth_epsilon);
      image.shade.values[i] = both.value.x;
      image.unshadowed.values[i] = both.value.y;
      image.no_match[i] = both.best_match < render::kUpsampleMatchFactor;
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
