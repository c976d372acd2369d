#pragma once
// A small CPU frame for the image sweeps (S5 silhouettes, S7 camera crawl): a ground plane y = 0,
// sphere "characters" (receivers and proxies at once) and receiver-only poles and walls ray-cast
// into a G-buffer, receivers at
// 1/k chosen and shaded by the frame's CPU twins (select_receiver, accumulate_log_occlusion,
// exponentiate_and_shade) and upsampled by the composite's twin (render::upsample, the taps as
// upsample_composite.comp gathers them). Direct light only (luminance), square images.
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_tables.h"
#include "render/shading.h"
#include "study/stability_metrics.h"

namespace proxygi::study {

struct SweepCamera {
  glm::vec3 eye{0.0f, 1.0f, 3.0f};
  glm::vec3 target{0.0f, 0.5f, 0.0f};
  float fov_y_degrees = 40.0f;
};

// Receivers that are not proxies (they cast no shadow; S5's thin features and their backdrop).
// A vertical pole (capped cylinder) standing on the ground, world m.
struct SweepPole {
  glm::vec2 foot_xz{0.0f};
  float radius = 0.01f;
  float height = 1.0f;
};
// A finite vertical wall standing on the ground, seen from the side its horizontal `normal` faces.
struct SweepWall {
  glm::vec3 base_center{0.0f};  // on the ground, m
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  float half_width = 1.0f, height = 1.0f;
};
struct SweepGeometry {
  std::vector<render::Sphere> spheres;  // proxies and receivers
  std::vector<SweepPole> poles;
  std::vector<SweepWall> walls;
};

struct SweepGBuffer {
  int size = 0;
  std::vector<glm::vec3> position;  // world, m
  std::vector<glm::vec3> normal;
  ref::Plane depth;                 // eye depth, m; 0 = background
  // -1 background, 0 ground, 1 + i sphere i, then pole_label(j), then wall_label(j).
  std::vector<int> label;
  int spheres = 0, poles = 0;
  int pole_label(int pole) const { return 1 + spheres + pole; }
  int wall_label(int wall) const { return 1 + spheres + poles + wall; }
  bool is_pole(int value) const { return value > spheres && value <= spheres + poles; }
};
SweepGBuffer trace_gbuffer(std::span<const render::Sphere> spheres, const SweepCamera& camera, int size);
SweepGBuffer trace_gbuffer(const SweepGeometry& geometry, const SweepCamera& camera, int size);
// Eye depth of a world point seen by `camera`, m; and the world size of one pixel at eye depth z.
float eye_depth(const SweepCamera& camera, const glm::vec3& point);
float pixel_size_at(const SweepCamera& camera, int size, float depth);

struct SweepImage {
  ref::Plane shade;             // luminance of E (0 on background)
  std::vector<bool> no_match;   // k > 1: no tap matches the pixel's surface (render::Upsampled::best_match < kUpsampleMatchFactor)
  ref::Plane unshadowed;        // the same frame without proxies: the receivers' unshadowed shade, same taps
  ref::Plane pixel_unshadowed;  // the unshadowed shade at the pixel's own point and normal (sets its u)
};
// k = 1 shades every pixel; k > 1 shades receivers at 1/k and upsamples.
SweepImage render_sweep_frame(const render::FrameTables& tables, std::span<const render::Sphere> spheres,
                              const SweepGBuffer& gbuffer, int k, settings::Upsampling upsampling, float depth_epsilon);

// Exact reprojection: for each pixel of `from` (seen by `from_camera`... its G-buffer positions),
// the pixel of `to` (seen by to_camera) showing the same surface point, or -1 (off screen or hidden:
// a different label or an eye depth more than 2 % off at that pixel).
Reprojection reproject(const SweepGBuffer& from, const SweepCamera& to_camera, const SweepGBuffer& to);

}  // namespace proxygi::study
