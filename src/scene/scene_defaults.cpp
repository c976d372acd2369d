#include "scene/scene_defaults.h"

#include <string>

namespace proxygi::scene {
namespace {

// Sky and sun shared by both scenes: ground irradiance is about 3 (sun 2 + sky 1) so a white
// surface comes out near 1 at exposure 0.
Environment daylight() {
  Environment e;
  e.type = Environment::Type::sky;
  e.sun.elevation_degrees = 40.0f;
  e.sun.azimuth_degrees = 150.0f;
  e.sun.angular_radius_degrees = 2.0f;
  e.sun.color = glm::vec3(1.0f, 0.93f, 0.82f);
  e.sun.irradiance = 3.0f;
  e.sky.zenith_color = glm::vec3(0.25f, 0.45f, 0.85f);
  e.sky.horizon_color = glm::vec3(0.75f, 0.85f, 1.0f);
  e.sky.below_horizon_color = glm::vec3(0.3f, 0.28f, 0.25f);
  e.sky.radiance = 0.5f;
  return e;
}

// The parts both built-ins share: a 2 km ground reaching the horizon, a far plane beyond it,
// and 512×512 at 24 fps from frame 0.
void set_outdoor_stage(Scene& scene, int frame_count) {
  scene.ground = Ground{true, kHorizonGroundSize, glm::vec3(0.8f, 0.8f, 0.8f)};
  scene.camera.near_m = 0.1f;
  scene.camera.far_m = kHorizonFarM;  // beyond the ground edge, so the ground meets the horizon
  scene.output.width = 512;
  scene.output.height = 512;
  scene.output.fps = 24.0;
  scene.output.first_frame = 0;
  scene.output.frame_count = frame_count;
}

}  // namespace

Scene default_scene() {
  Scene scene;
  scene.description =
      "Built-in default: the mannequin walks 4.4 m across a light gray ground under a blue sky "
      "and a warm sun; a fixed camera frames the whole walk.";

  Character walker;
  walker.model = std::string(kBuiltinMannequin);
  walker.clip = std::string("walk");
  // 1.1 m/s is the mannequin walk's stride speed (anim::kWalkSpeed): the feet stay planted.
  walker.path = WalkPath{glm::vec3(-2.2f, 0.0f, 0.0f), glm::vec3(2.2f, 0.0f, 0.0f), 1.1f,
                         WalkPath::Repeat::none};
  scene.characters.push_back(walker);

  scene.environment = daylight();

  FixedCamera camera;
  camera.position = glm::vec3(0.0f, 1.9f, 7.2f);
  camera.target = glm::vec3(0.0f, 0.9f, 0.0f);
  camera.fov_degrees = 50.0f;
  scene.camera.kind = camera;
  set_outdoor_stage(scene, 96);
  return scene;
}

Scene crowd_scene() {
  Scene scene;
  scene.description =
      "Built-in crowd: 20 mannequins on a 5 x 4 grid, rows alternately walking and running "
      "ping-pong along X, seen by an orbiting camera (benchmark scene).";

  constexpr int kColumns = 5;
  constexpr int kRows = 4;
  constexpr float kSpacing = 2.0f;     // meters between characters in a row
  constexpr float kLane = 6.0f;        // meters each character travels before turning
  for (int row = 0; row < kRows; ++row) {
    const bool running = row % 2 == 1;
    const bool reversed = row >= kRows / 2;  // two rows head +X first, two head -X first
    const float z = -3.0f + 2.0f * static_cast<float>(row);
    for (int column = 0; column < kColumns; ++column) {
      Character c;
      c.model = std::string(kBuiltinMannequin);
      c.clip = std::string(running ? "run" : "walk");
      // Phases spread over about a second so feet do not move in unison.
      c.time_offset_s = 0.13f * static_cast<float>((column * 3 + row * 7) % 8);
      const float start_x = -7.0f + kSpacing * static_cast<float>(column);
      WalkPath path;
      path.start = glm::vec3(reversed ? -start_x : start_x, 0.0f, z);
      path.end = glm::vec3(reversed ? -start_x - kLane : start_x + kLane, 0.0f, z);
      path.speed = running ? 3.0f : 1.1f;  // the clips' stride speeds (anim::kRunSpeed, kWalkSpeed)
      path.repeat = WalkPath::Repeat::ping_pong;
      c.path = path;
      scene.characters.push_back(c);
    }
  }

  scene.environment = daylight();
  OrbitCamera camera;
  camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
  camera.distance = 18.0f;
  camera.elevation_degrees = 30.0f;
  camera.start_azimuth_degrees = 0.0f;
  camera.degrees_per_second = 12.0f;
  camera.fov_degrees = 50.0f;
  scene.camera.kind = camera;
  set_outdoor_stage(scene, 120);
  return scene;
}

}  // namespace proxygi::scene
