// A hand-written scene without ground.size gets a ground reaching the horizon: no pixel below
// the horizon sees past the ground's edge or the far plane (where the frame would show a band of
// the sky's below-horizon colour), except the one pixel per column the horizon itself crosses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/camera.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"

namespace proxygi::scene {
namespace {

// A scene a user writes: a fixed camera looking slightly down, the horizon in view.
std::string user_scene(const std::string& ground) {
  return R"({"schema_version": 1, )" + ground +
         R"("characters": [{"model": "builtin:mannequin", "clip": "walk"}],
            "camera": {"type": "fixed", "position": [0, 1.6, 4.5], "target": [0, 0.8, 0]},
            "output": {"width": 512, "height": 512, "frames": {"count": 1}}})";
}

struct Band {
  int widest = 0;         // most pixels in one column below the horizon that miss the ground
  int horizon_rows = 0;   // columns in which the horizon is in view
};

// Per column, pixel-center rays below the horizon that leave the ground square or pass the far
// plane (eye depth) before reaching it.
Band below_horizon_band(const Scene& scene) {
  const CameraState camera = evaluate_scene_camera(scene, 0.0);
  const int width = scene.output.width, height = scene.output.height;
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  const float half = 0.5f * scene.ground.size;
  Band band;
  for (int x = 0; x < width; ++x) {
    int misses = 0;
    bool sky_above = false;
    for (int y = 0; y < height; ++y) {
      const Ray ray = ray_through_pixel(camera, width, height, float(x) + 0.5f, float(y) + 0.5f);
      if (ray.direction.y >= 0.0f) {
        sky_above = true;
        continue;
      }
      const float t = -ray.origin.y / ray.direction.y;
      const glm::vec3 hit = ray.origin + t * ray.direction;
      const bool off_ground = std::fabs(hit.x) > half || std::fabs(hit.z) > half;
      const bool beyond_far = glm::dot(hit - camera.eye, forward) > camera.far_m;
      if (off_ground || beyond_far) ++misses;
    }
    if (sky_above) ++band.horizon_rows;
    band.widest = std::max(band.widest, misses);
  }
  return band;
}

TEST(HorizonGround, SceneWithoutGroundSizeReachesTheHorizon) {
  auto scene = parse_scene(user_scene(""), "user.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_FLOAT_EQ(scene->ground.size, kHorizonGroundSize);
  EXPECT_FLOAT_EQ(scene->camera.far_m, kHorizonFarM);
  const Band band = below_horizon_band(*scene);
  EXPECT_EQ(band.horizon_rows, scene->output.width);  // the horizon is in view in every column
  EXPECT_LE(band.widest, 1);
}

TEST(HorizonGround, GroundWithoutSizeStillReachesTheHorizon) {
  auto scene = parse_scene(user_scene(R"("ground": {"albedo": [0.5, 0.5, 0.5]}, )"), "user.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_FLOAT_EQ(scene->ground.size, kHorizonGroundSize);
  EXPECT_LE(below_horizon_band(*scene).widest, 1);
}

// The old 20 m default, now only when the file says so, shows its edge: a band dozens of pixels
// high, which is what the horizon default removes. Its far plane stays Camera's default.
TEST(HorizonGround, ExplicitSizeIsKept) {
  auto scene = parse_scene(user_scene(R"("ground": {"size": 20}, )"), "user.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_FLOAT_EQ(scene->ground.size, 20.0f);
  EXPECT_FLOAT_EQ(scene->camera.far_m, Camera{}.far_m);
  EXPECT_GT(below_horizon_band(*scene).widest, 10);
}

TEST(HorizonGround, BuiltInScenesUseTheSameGround) {
  EXPECT_FLOAT_EQ(default_scene().ground.size, kHorizonGroundSize);
  EXPECT_FLOAT_EQ(default_scene().camera.far_m, kHorizonFarM);
  EXPECT_LE(below_horizon_band(default_scene()).widest, 1);
}

}  // namespace
}  // namespace proxygi::scene
