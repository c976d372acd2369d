#pragma once
// The small test scene of the path tracer's render tests: a 6 m ground under two spheres, and a
// camera looking at them.
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/scene_geometry.h"
#include "scene/camera.h"

namespace proxygi::ref::test_scenes {

inline EmbreeScene small_scene() {
  std::vector<TriangleMesh> meshes = ground_meshes(scene::Ground{true, 6.0f, glm::vec3(0.8f)});
  const SphereShape spheres[] = {{{0.0f, 0.6f, 0.0f}, 0.5f, SurfaceMaterial{glm::vec3(0.9f, 0.2f, 0.2f), nullptr}},
                                 {{1.0f, 0.3f, 0.5f}, 0.3f, SurfaceMaterial{glm::vec3(0.2f, 0.9f, 0.2f), nullptr}}};
  auto scene = EmbreeScene::build(std::move(meshes), spheres);
  EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
  return std::move(*scene);
}

inline scene::CameraState small_camera() {
  scene::CameraState camera;
  camera.eye = glm::vec3(0.5f, 2.0f, 4.0f);
  camera.target = glm::vec3(0.0f, 0.4f, 0.0f);
  camera.fov_y_degrees = 50.0f;
  return camera;
}

}  // namespace proxygi::ref::test_scenes
