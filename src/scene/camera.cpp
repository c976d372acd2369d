#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "base/check.h"
#include "scene/character_motion.h"

namespace proxygi::scene {
namespace {

CameraState with_clip(const Camera& camera, CameraState state) {
  state.near_m = camera.near_m;
  state.far_m = camera.far_m;
  return state;
}

glm::vec3 orbit_offset(float distance, float elevation_degrees, double azimuth_degrees) {
  const double e = glm::radians(static_cast<double>(elevation_degrees));
  const double a = glm::radians(azimuth_degrees);
  const glm::dvec3 direction(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
  return glm::vec3(direction * static_cast<double>(distance));
}

// Hermite tangent (units per second) at key i from its neighbours' positions.
template <class Get>
glm::vec3 key_tangent(const std::vector<CameraKey>& keys, std::size_t i, Get get) {
  const std::size_t lo = i == 0 ? 0 : i - 1;
  const std::size_t hi = std::min(i + 1, keys.size() - 1);
  return (get(keys[hi]) - get(keys[lo])) / (keys[hi].time_s - keys[lo].time_s);
}

CameraState evaluate_keyframed(const KeyframedCamera& k, double t) {
  PROXYGI_CHECK(!k.keys.empty(), "keyframed camera without keys");
  CameraState state;
  state.up = k.up;
  const std::vector<CameraKey>& keys = k.keys;
  auto hold = [&state](const CameraKey& key) {
    state.eye = key.position;
    state.target = key.target;
    state.fov_y_degrees = key.fov_degrees;
    return state;
  };
  if (keys.size() == 1 || t <= static_cast<double>(keys.front().time_s)) return hold(keys.front());
  if (t >= static_cast<double>(keys.back().time_s)) return hold(keys.back());

  // First key strictly after t; the segment is [i, i + 1].
  const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                      [](double time, const CameraKey& key) { return time < key.time_s; });
  const std::size_t i = static_cast<std::size_t>(after - keys.begin()) - 1;
  const CameraKey& a = keys[i];
  const CameraKey& b = keys[i + 1];
  const float span = b.time_s - a.time_s;
  const float u = static_cast<float>((t - static_cast<double>(a.time_s)) / static_cast<double>(span));
  state.fov_y_degrees = a.fov_degrees + (b.fov_degrees - a.fov_degrees) * u;
  if (k.interpolation == KeyframedCamera::Interpolation::linear) {
    state.eye = glm::mix(a.position, b.position, u);
    state.target = glm::mix(a.target, b.target, u);
    return state;
  }
  const float u2 = u * u;
  const float u3 = u2 * u;
  const float h00 = 2.0f * u3 - 3.0f * u2 + 1.0f;
  const float h10 = u3 - 2.0f * u2 + u;
  const float h01 = -2.0f * u3 + 3.0f * u2;
  const float h11 = u3 - u2;
  auto hermite = [&](auto get) {
    return h00 * get(a) + h10 * span * key_tangent(keys, i, get) + h01 * get(b) +
           h11 * span * key_tangent(keys, i + 1, get);
  };
  state.eye = hermite([](const CameraKey& key) { return key.position; });
  state.target = hermite([](const CameraKey& key) { return key.target; });
  return state;
}

}  // namespace

CameraState evaluate_camera(const Camera& camera, double t, const RootTrack& followed_root) {
  CameraState state;
  if (const auto* f = std::get_if<FixedCamera>(&camera.kind)) {
    state.eye = f->position;
    state.target = f->target;
    state.up = f->up;
    state.fov_y_degrees = f->fov_degrees;
  } else if (const auto* o = std::get_if<OrbitCamera>(&camera.kind)) {
    const double azimuth = static_cast<double>(o->start_azimuth_degrees) +
                           static_cast<double>(o->degrees_per_second) * t;
    state.target = o->target;
    state.eye = o->target + orbit_offset(o->distance, o->elevation_degrees, azimuth);
    state.fov_y_degrees = o->fov_degrees;
  } else if (const auto* w = std::get_if<FollowCamera>(&camera.kind)) {
    PROXYGI_CHECK(static_cast<bool>(followed_root), "follow camera evaluated without a root track");
    constexpr int kSamples = 16;
    glm::dvec3 root(0.0);
    if (w->smoothing_s > 0.0f) {
      for (int s = 0; s < kSamples; ++s) {
        const double back = static_cast<double>(w->smoothing_s) * s / (kSamples - 1);
        root += glm::dvec3(followed_root(t - back));
      }
      root /= static_cast<double>(kSamples);
    } else {
      root = glm::dvec3(followed_root(t));
    }
    state.eye = glm::vec3(root) + w->offset;
    state.target = glm::vec3(root) + glm::vec3(0.0f, w->look_at_height, 0.0f);
    state.fov_y_degrees = w->fov_degrees;
  } else {
    state = evaluate_keyframed(std::get<KeyframedCamera>(camera.kind), t);
  }
  return with_clip(camera, state);
}

CameraState evaluate_scene_camera(const Scene& scene, double t) {
  RootTrack track;
  if (const auto* w = std::get_if<FollowCamera>(&scene.camera.kind)) {
    PROXYGI_CHECK(w->character >= 0 && w->character < static_cast<int>(scene.characters.size()),
                  "follow camera character out of range (validate the scene first)");
    const Character& followed = scene.characters[static_cast<std::size_t>(w->character)];
    track = [&followed](double time) { return character_root_position(followed, time); };
  }
  return evaluate_camera(scene.camera, t, track);
}

glm::mat4 view_matrix(const CameraState& camera) {
  return glm::lookAtRH(camera.eye, camera.target, camera.up);
}

glm::mat4 projection_matrix(const CameraState& camera, float aspect, DepthRange depth) {
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(camera.fov_y_degrees), aspect, camera.near_m,
                                      camera.far_m);
  p[1][1] = -p[1][1];  // Vulkan clip y points down
  if (depth == DepthRange::reversed) {
    // z' = w - z maps near (z = 0) to 1 and far (z = w) to 0.
    glm::mat4 flip(1.0f);
    flip[2][2] = -1.0f;
    flip[3][2] = 1.0f;
    p = flip * p;
  }
  return p;
}

glm::mat4 inverse_view_projection(const CameraState& camera, float aspect, DepthRange depth) {
  return glm::inverse(projection_matrix(camera, aspect, depth) * view_matrix(camera));
}

Ray ray_through_pixel(const CameraState& camera, int width, int height, float px, float py) {
  // Built from the camera basis in double rather than by inverting the matrix: same rays,
  // without the precision lost in the far-plane terms.
  const glm::dvec3 eye(camera.eye);
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_half = std::tan(glm::radians(static_cast<double>(camera.fov_y_degrees)) * 0.5);
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  const double ndc_x = 2.0 * static_cast<double>(px) / width - 1.0;
  const double ndc_y = 2.0 * static_cast<double>(py) / height - 1.0;  // down
  const glm::dvec3 direction = forward + right * (ndc_x * tan_half * aspect) - up * (ndc_y * tan_half);
  return Ray{camera.eye, glm::vec3(glm::normalize(direction))};
}

glm::vec2 project_to_pixel(const CameraState& camera, int width, int height, const glm::vec3& world) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::vec4 clip = projection_matrix(camera, aspect) * view_matrix(camera) * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return glm::vec2((ndc.x + 1.0f) * 0.5f * static_cast<float>(width),
                   (ndc.y + 1.0f) * 0.5f * static_cast<float>(height));
}

}  // namespace proxygi::scene
