// Cameras: evaluation of each kind, the Vulkan projection conventions, and primary rays.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera.h"
#include "scene/character_motion.h"

namespace proxygi::scene {
namespace {

constexpr float kPixelTolerance = 2e-3f;

Camera fixed_camera(glm::vec3 position, glm::vec3 target, float fov = 45.0f) {
  Camera c;
  c.kind = FixedCamera{position, target, glm::vec3(0, 1, 0), fov};
  return c;
}

TEST(Camera, FixedCameraProjectsTheTargetToTheImageCenter) {
  const Camera camera = fixed_camera(glm::vec3(1.0f, 2.5f, 4.0f), glm::vec3(-0.5f, 0.7f, 0.3f), 38.0f);
  const CameraState state = evaluate_camera(camera, 1.25);
  EXPECT_EQ(state.eye, glm::vec3(1.0f, 2.5f, 4.0f));
  EXPECT_EQ(state.target, glm::vec3(-0.5f, 0.7f, 0.3f));
  EXPECT_FLOAT_EQ(state.fov_y_degrees, 38.0f);
  EXPECT_FLOAT_EQ(state.near_m, camera.near_m);
  EXPECT_FLOAT_EQ(state.far_m, camera.far_m);
  for (const auto& [w, h] : {std::pair{512, 512}, std::pair{640, 360}, std::pair{17, 1000}}) {
    const glm::vec2 px = project_to_pixel(state, w, h, state.target);
    EXPECT_NEAR(px.x, 0.5f * w, kPixelTolerance * w);
    EXPECT_NEAR(px.y, 0.5f * h, kPixelTolerance * h);
    for (DepthRange depth : {DepthRange::standard, DepthRange::reversed}) {
      const glm::vec4 clip = projection_matrix(state, float(w) / float(h), depth) * view_matrix(state) *
                             glm::vec4(state.target, 1.0f);
      EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-5f);
      EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-5f);
    }
  }
}

TEST(Camera, VulkanClipSpaceYDownDepthZeroToOne) {
  CameraState s;
  s.eye = glm::vec3(0, 0, 5);
  s.target = glm::vec3(0, 0, 0);
  s.near_m = 0.5f;
  s.far_m = 50.0f;
  const glm::mat4 view = view_matrix(s);
  auto depth_of = [&](float distance, DepthRange range) {
    const glm::vec4 clip = projection_matrix(s, 1.0f, range) * view * glm::vec4(0, 0, 5.0f - distance, 1);
    return clip.z / clip.w;
  };
  EXPECT_NEAR(depth_of(0.5f, DepthRange::standard), 0.0f, 1e-6f);
  EXPECT_NEAR(depth_of(50.0f, DepthRange::standard), 1.0f, 1e-5f);
  EXPECT_NEAR(depth_of(0.5f, DepthRange::reversed), 1.0f, 1e-6f);
  EXPECT_NEAR(depth_of(50.0f, DepthRange::reversed), 0.0f, 1e-5f);
  EXPECT_LT(depth_of(2.0f, DepthRange::standard), depth_of(3.0f, DepthRange::standard));
  EXPECT_GT(depth_of(2.0f, DepthRange::reversed), depth_of(3.0f, DepthRange::reversed));

  // World up is toward row 0, world +X (the camera's right here) toward larger px.
  const glm::vec2 up = project_to_pixel(s, 100, 100, glm::vec3(0, 1, 0));
  const glm::vec2 right = project_to_pixel(s, 100, 100, glm::vec3(1, 0, 0));
  EXPECT_LT(up.y, 50.0f);
  EXPECT_NEAR(up.x, 50.0f, 1e-3f);
  EXPECT_GT(right.x, 50.0f);
  EXPECT_NEAR(right.y, 50.0f, 1e-3f);

  // A triangle counter-clockwise as seen from the camera has positive Vulkan area
  // a = -1/2 sum(x_i y_{i+1} - x_{i+1} y_i) in framebuffer coordinates: front face CCW.
  const glm::vec2 p[3] = {project_to_pixel(s, 100, 100, glm::vec3(0, 0, 0)),
                          project_to_pixel(s, 100, 100, glm::vec3(1, 0, 0)),
                          project_to_pixel(s, 100, 100, glm::vec3(0, 1, 0))};
  float sum = 0.0f;
  for (int i = 0; i < 3; ++i) sum += p[i].x * p[(i + 1) % 3].y - p[(i + 1) % 3].x * p[i].y;
  EXPECT_GT(-0.5f * sum, 0.0f);
}

TEST(Camera, VerticalFovSpansTheImageHeight) {
  CameraState s;
  s.eye = glm::vec3(0, 0, 0);
  s.target = glm::vec3(0, 0, -1);
  s.fov_y_degrees = 60.0f;
  // A point at half the vertical fov above the axis lands on the top edge.
  const float half = glm::radians(30.0f);
  const glm::vec2 top = project_to_pixel(s, 300, 200, glm::vec3(0, std::tan(half), -1));
  EXPECT_NEAR(top.y, 0.0f, 1e-3f);
  // Horizontal extent follows the aspect ratio: x = tan(half) * aspect lands on the right edge.
  const glm::vec2 edge = project_to_pixel(s, 300, 200, glm::vec3(std::tan(half) * 1.5f, 0, -1));
  EXPECT_NEAR(edge.x, 300.0f, 1e-2f);
}

TEST(Camera, OrbitReturnsToItsStartAfterOneTurn) {
  Camera camera;
  camera.kind = OrbitCamera{glm::vec3(0.5f, 1.0f, -2.0f), 6.0f, 25.0f, 40.0f, 36.0f, 45.0f};
  const CameraState start = evaluate_camera(camera, 0.0);
  const CameraState turned = evaluate_camera(camera, 360.0 / 36.0);
  EXPECT_NEAR(glm::length(turned.eye - start.eye), 0.0f, 1e-4f);
  for (double t : {0.0, 1.3, 4.0, 7.7}) {
    const CameraState s = evaluate_camera(camera, t);
    EXPECT_NEAR(glm::length(s.eye - s.target), 6.0f, 1e-4f);
    EXPECT_NEAR(std::asin((s.eye.y - s.target.y) / 6.0f), glm::radians(25.0f), 1e-4f);
    EXPECT_EQ(s.target, glm::vec3(0.5f, 1.0f, -2.0f));
  }
  // Half a turn puts the camera on the other side.
  const CameraState half = evaluate_camera(camera, 5.0);
  EXPECT_NEAR(half.eye.x - 0.5f, -(start.eye.x - 0.5f), 1e-4f);
  EXPECT_NEAR(half.eye.z + 2.0f, -(start.eye.z + 2.0f), 1e-4f);
}

TEST(Camera, OrbitAzimuthConvention) {
  Camera camera;
  camera.kind = OrbitCamera{glm::vec3(0.0f), 2.0f, 0.0f, 0.0f, 90.0f, 45.0f};
  const CameraState at0 = evaluate_camera(camera, 0.0);
  EXPECT_NEAR(glm::length(at0.eye - glm::vec3(0, 0, 2)), 0.0f, 1e-5f);  // azimuth 0: +Z side
  const CameraState at90 = evaluate_camera(camera, 1.0);
  EXPECT_NEAR(glm::length(at90.eye - glm::vec3(2, 0, 0)), 0.0f, 1e-5f);  // azimuth 90: +X side
}

KeyframedCamera three_keys(KeyframedCamera::Interpolation interpolation) {
  KeyframedCamera k;
  k.interpolation = interpolation;
  k.keys = {CameraKey{1.0f, glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), 40.0f},
            CameraKey{2.0f, glm::vec3(4, 2, 3), glm::vec3(1, 1, 0), 50.0f},
            CameraKey{4.0f, glm::vec3(5, 1, -2), glm::vec3(0, 0, 0), 30.0f}};
  return k;
}

TEST(Camera, KeyframesInterpolateLinearlyAndClamp) {
  Camera camera;
  camera.kind = three_keys(KeyframedCamera::Interpolation::linear);
  const auto& keys = std::get<KeyframedCamera>(camera.kind).keys;
  const CameraState before = evaluate_camera(camera, -3.0);
  EXPECT_EQ(before.eye, keys[0].position);
  EXPECT_EQ(before.target, keys[0].target);
  EXPECT_FLOAT_EQ(before.fov_y_degrees, 40.0f);
  const CameraState after = evaluate_camera(camera, 100.0);
  EXPECT_EQ(after.eye, keys[2].position);
  EXPECT_FLOAT_EQ(after.fov_y_degrees, 30.0f);
  const CameraState mid = evaluate_camera(camera, 1.5);
  EXPECT_NEAR(glm::length(mid.eye - glm::vec3(2, 1.5f, 4)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(mid.target - glm::vec3(0.5f, 1, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(mid.fov_y_degrees, 45.0f, 1e-4f);
  const CameraState quarter = evaluate_camera(camera, 2.5);  // a quarter into the second segment
  EXPECT_NEAR(glm::length(quarter.eye - glm::mix(keys[1].position, keys[2].position, 0.25f)), 0.0f, 1e-5f);
  EXPECT_NEAR(quarter.fov_y_degrees, 45.0f, 1e-4f);  // 50 + (30 - 50) / 4
}

TEST(Camera, CatmullRomPassesThroughKeysAndIsSmooth) {
  Camera camera;
  camera.kind = three_keys(KeyframedCamera::Interpolation::catmull_rom);
  const auto& keys = std::get<KeyframedCamera>(camera.kind).keys;
  for (const CameraKey& key : keys) {
    const CameraState s = evaluate_camera(camera, key.time_s);
    EXPECT_NEAR(glm::length(s.eye - key.position), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(s.target - key.target), 0.0f, 1e-5f);
    EXPECT_NEAR(s.fov_y_degrees, key.fov_degrees, 1e-4f);
  }
  // C1 at the interior key: velocities on both sides agree, and equal the central difference.
  const double h = 1e-3;
  const glm::vec3 left = (evaluate_camera(camera, 2.0).eye - evaluate_camera(camera, 2.0 - h).eye) / float(h);
  const glm::vec3 right = (evaluate_camera(camera, 2.0 + h).eye - evaluate_camera(camera, 2.0).eye) / float(h);
  const glm::vec3 tangent = (keys[2].position - keys[0].position) / (keys[2].time_s - keys[0].time_s);
  EXPECT_NEAR(glm::length(left - tangent), 0.0f, 0.02f);
  EXPECT_NEAR(glm::length(right - tangent), 0.0f, 0.02f);
  // Clamps like the linear camera.
  EXPECT_EQ(evaluate_camera(camera, 0.0).eye, keys[0].position);
  EXPECT_EQ(evaluate_camera(camera, 9.0).eye, keys[2].position);
}

TEST(Camera, CatmullRomReproducesConstantVelocityWithUnevenKeys) {
  KeyframedCamera k;
  const glm::vec3 velocity(1.5f, -0.25f, 0.5f);
  for (float t : {0.0f, 0.5f, 2.0f, 2.25f, 5.0f}) {
    k.keys.push_back(CameraKey{t, glm::vec3(0, 2, 8) + velocity * t, glm::vec3(0, 1, 0), 45.0f});
  }
  Camera camera;
  camera.kind = k;
  for (double t = 0.0; t <= 5.0; t += 0.123) {
    const CameraState s = evaluate_camera(camera, t);
    EXPECT_NEAR(glm::length(s.eye - (glm::vec3(0, 2, 8) + velocity * float(t))), 0.0f, 1e-4f) << t;
  }
}

TEST(Camera, SingleKeyHolds) {
  KeyframedCamera k;
  k.keys = {CameraKey{2.0f, glm::vec3(1, 2, 3), glm::vec3(0, 1, 0), 33.0f}};
  Camera camera;
  camera.kind = k;
  for (double t : {-1.0, 2.0, 5.0}) EXPECT_EQ(evaluate_camera(camera, t).eye, glm::vec3(1, 2, 3));
}

TEST(Camera, FollowCameraTracksTheRootWithABoxFilter) {
  Camera camera;
  camera.kind = FollowCamera{0, glm::vec3(0.0f, 1.5f, 4.0f), 1.2f, 0.0f, 50.0f};
  const glm::vec3 velocity(2.0f, 0.0f, -1.0f);
  const RootTrack track = [velocity](double t) { return glm::vec3(3, 0, 1) + velocity * float(t); };
  const CameraState sharp = evaluate_camera(camera, 2.0, track);
  EXPECT_NEAR(glm::length(sharp.eye - (track(2.0) + glm::vec3(0.0f, 1.5f, 4.0f))), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(sharp.target - (track(2.0) + glm::vec3(0.0f, 1.2f, 0.0f))), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(sharp.fov_y_degrees, 50.0f);
  // The mean of a linear track over [t - s, t] is its value at t - s / 2.
  std::get<FollowCamera>(camera.kind).smoothing_s = 0.8f;
  const CameraState smooth = evaluate_camera(camera, 2.0, track);
  EXPECT_NEAR(glm::length(smooth.eye - (track(1.6) + glm::vec3(0.0f, 1.5f, 4.0f))), 0.0f, 1e-4f);
  // A standing character is unaffected by smoothing.
  const RootTrack still = [](double) { return glm::vec3(1, 0, 1); };
  EXPECT_NEAR(glm::length(evaluate_camera(camera, 2.0, still).eye - glm::vec3(1, 1.5f, 5)), 0.0f, 1e-5f);
}

TEST(Camera, SceneFollowCameraUsesTheWalkPath) {
  Scene scene;
  Character c;
  c.model = "a.glb";
  c.path = WalkPath{glm::vec3(0, 0, 0), glm::vec3(10, 0, 0), 2.0f, WalkPath::Repeat::none};
  scene.characters = {c, c};
  scene.characters[1].path->start = glm::vec3(0, 0, 5);
  scene.characters[1].path->end = glm::vec3(10, 0, 5);
  scene.camera.kind = FollowCamera{1, glm::vec3(0, 1, 3), 1.0f, 0.0f, 45.0f};
  const CameraState s = evaluate_scene_camera(scene, 1.5);
  EXPECT_NEAR(glm::length(s.target - glm::vec3(3, 1, 5)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(s.eye - glm::vec3(3, 1, 8)), 0.0f, 1e-5f);
}

// ray_through_pixel and the projection are inverses at the corners, the center and pixel
// centers, for square and wide images.
TEST(Camera, RayThroughPixelInvertsTheProjection) {
  CameraState s;
  s.eye = glm::vec3(1.0f, 1.7f, 4.0f);
  s.target = glm::vec3(-0.3f, 0.8f, -0.5f);
  s.up = glm::vec3(0.1f, 1.0f, 0.0f);
  s.fov_y_degrees = 52.0f;
  s.near_m = 0.1f;
  s.far_m = 80.0f;
  for (const auto& [w, h] : {std::pair{256, 256}, std::pair{640, 360}}) {
    const float aspect = float(w) / float(h);
    const glm::vec2 points[] = {{0, 0}, {float(w), 0}, {0, float(h)}, {float(w), float(h)},
                                {0.5f * w, 0.5f * h}, {0.5f, 0.5f}, {w - 0.5f, h - 0.5f}};
    for (const glm::vec2& p : points) {
      const Ray ray = ray_through_pixel(s, w, h, p.x, p.y);
      EXPECT_EQ(ray.origin, s.eye);
      EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
      for (float distance : {0.5f, 3.0f, 40.0f}) {
        const glm::vec2 back = project_to_pixel(s, w, h, ray.origin + ray.direction * distance);
        EXPECT_NEAR(back.x, p.x, 2e-3f * w) << p.x << "," << p.y;
        EXPECT_NEAR(back.y, p.y, 2e-3f * h) << p.x << "," << p.y;
      }
      // The same ray from the inverse matrix, for both depth conventions.
      const glm::vec2 ndc(2.0f * p.x / w - 1.0f, 2.0f * p.y / h - 1.0f);
      for (DepthRange depth : {DepthRange::standard, DepthRange::reversed}) {
        const glm::vec4 world = inverse_view_projection(s, aspect, depth) * glm::vec4(ndc, 0.5f, 1.0f);
        const glm::vec3 direction = glm::normalize(glm::vec3(world) / world.w - s.eye);
        EXPECT_GT(glm::dot(direction, ray.direction), 1.0f - 1e-6f);
      }
    }
  }
  // The center ray looks at the target.
  const Ray center = ray_through_pixel(s, 256, 256, 128.0f, 128.0f);
  EXPECT_GT(glm::dot(center.direction, glm::normalize(s.target - s.eye)), 1.0f - 1e-6f);
}

}  // namespace
}  // namespace proxygi::scene
