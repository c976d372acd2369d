#pragma once
// Cameras: evaluate a scene camera at a time into a CameraState, then build the matrices the
// rasterizer uses and the primary rays the path tracer uses from the same state, so both see
// the same image.
//
// Conventions
//  - World: glTF space, right-handed, +Y up, meters. View space: right-handed, the camera looks
//    down -Z with +Y up and +X right (glm::lookAtRH).
//  - Clip space is Vulkan's: x right, y DOWN, depth in [0, 1]. The projection flips y itself
//    (P[1][1] < 0), so use an ordinary viewport (x = 0, y = 0, width, height; no negative
//    height) and world +Y appears toward framebuffer row 0 (the top). Triangles that are
//    counter-clockwise in world space seen from the camera stay counter-clockwise in the
//    framebuffer, i.e. front faces are VK_FRONT_FACE_COUNTER_CLOCKWISE.
//  - Depth: DepthRange::standard maps near -> 0, far -> 1 (compare LESS, clear 1);
//    DepthRange::reversed maps near -> 1, far -> 0 (compare GREATER, clear 0; better precision).
//  - Framebuffer coordinates: px in [0, width] left to right, py in [0, height] top to bottom;
//    the center of pixel (i, j) is (i + 0.5, j + 0.5). NDC = (2 px / width - 1, 2 py / height - 1).
//  - fov is vertical, in degrees; aspect = width / height.
//
// Usage:
//   CameraState cam = evaluate_scene_camera(scene, frame_time_s(scene.output, frame));
//   glm::mat4 view_proj = projection_matrix(cam, aspect) * view_matrix(cam);
//   Ray r = ray_through_pixel(cam, width, height, x + 0.5f, y + 0.5f);
#include <functional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace proxygi::scene {

struct CameraState {
  glm::vec3 eye{0.0f, 0.0f, 1.0f};     // meters, world
  glm::vec3 target{0.0f};              // the point the camera looks at; != eye
  glm::vec3 up{0.0f, 1.0f, 0.0f};      // world up hint, not parallel to target - eye
  float fov_y_degrees = 45.0f;         // vertical, (0, 180)
  float near_m = 0.05f;                // > 0
  float far_m = 200.0f;                // > near_m
};

// World position (meters) of the followed character's root at a scene time (seconds).
using RootTrack = std::function<glm::vec3(double scene_time_s)>;

// Evaluates `camera` at scene time t (seconds); see scene.h for each kind's formula.
// Follow cameras need `followed_root` (the tracked root of Scene::characters[camera.character]);
// calling with an empty one for a follow camera is a contract violation. Follow smoothing is
// the mean of 16 root samples evenly spaced over [t - smoothing, t] (both ends included).
CameraState evaluate_camera(const Camera& camera, double t, const RootTrack& followed_root = {});

// evaluate_camera with the follow track taken from the scene itself (character_root_position:
// transform plus walk path; clips whose root joint travels need the renderer's own track).
CameraState evaluate_scene_camera(const Scene& scene, double t);

enum class DepthRange { standard, reversed };

// World -> view (right-handed, looking down -Z).
glm::mat4 view_matrix(const CameraState& camera);
// View -> Vulkan clip space (y down, depth per `depth`). aspect = width / height > 0.
glm::mat4 projection_matrix(const CameraState& camera, float aspect,
                            DepthRange depth = DepthRange::standard);
// Clip -> world: inverse(projection * view), for reconstructing positions from depth.
glm::mat4 inverse_view_projection(const CameraState& camera, float aspect,
                                  DepthRange depth = DepthRange::standard);

struct Ray {
  glm::vec3 origin{0.0f};     // the eye (pinhole), meters
  glm::vec3 direction{0.0f};  // unit length
};

// The primary ray through framebuffer position (px, py) (pixel centers at +0.5, y down, as
// above). The ray hits exactly the world points that projection * view maps to that position.
Ray ray_through_pixel(const CameraState& camera, int width, int height, float px, float py);

// Framebuffer position (px, py) of a world point in front of the camera (inverse of
// ray_through_pixel up to the distance along the ray).
glm::vec2 project_to_pixel(const CameraState& camera, int width, int height, const glm::vec3& world);

}  // namespace proxygi::scene
