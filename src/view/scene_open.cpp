#include "view/scene_open.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "anim/gltf_import.h"
#include "anim/posed_character.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"

namespace proxygi::view {
namespace {

std::string lower_extension(const std::string& name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

}  // namespace

OpenKind open_kind(const std::string& name) {
  const std::string extension = lower_extension(name);
  if (extension == ".glb" || extension == ".gltf") return OpenKind::model;
  if (extension == ".hdr" || extension == ".exr") return OpenKind::environment;
  return OpenKind::scene;
}

Result<scene::Scene> stage_model(const std::filesystem::path& model) {
  auto character = anim::import_gltf(model);
  if (!character) return character.error();
  // Bounds of the rest pose (or the first clip's first key): what stands on the ground.
  const int clip = character->clips.empty() ? -1 : 0;
  anim::PoseBuffers pose;
  if (Status s = anim::evaluate_pose(*character, clip, 0.0f, anim::WrapMode::loop, pose); !s) return s.error();
  auto primitives = anim::pose_meshes(*character, pose);
  if (!primitives) return primitives.error();
  glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (const auto& primitive : *primitives)
    for (const glm::vec3& p : primitive.positions) low = glm::min(low, p), high = glm::max(high, p);
  if (!(low.x <= high.x)) return make_error(model.string() + ": the model has no mesh to show");

  scene::Scene scene = scene::default_scene();
  scene.description = "the default stage around " + model.filename().string();
  scene::Character placed;
  placed.model = std::filesystem::absolute(model).string();
  placed.clip = scene::ClipRef{std::in_place_type<int>, 0};  // without clips the world shows the rest pose
  const glm::vec3 center = 0.5f * (low + high);
  placed.transform.translation = {-center.x, -low.y, -center.z};
  scene.characters = {placed};

  const glm::vec3 size = high - low;
  const float radius = std::max(0.5f * glm::length(size), 1e-3f);
  scene::FixedCamera camera;
  camera.target = {0.0f, 0.5f * size.y, 0.0f};
  const float distance = radius / std::sin(glm::radians(camera.fov_degrees) * 0.5f) * 1.1f;
  camera.position = camera.target + distance * glm::normalize(glm::vec3(0.35f, 0.3f, 1.0f));
  scene.camera.kind = camera;
  scene.camera.near_m = std::max(distance * 0.01f, 1e-3f);
  scene.camera.far_m = std::max(distance * 20.0f, scene.ground.size * 2.0f);
  scene.ground.size = std::max(scene.ground.size, radius * 20.0f);
  if (clip >= 0) {
    const float duration = character->clips[0].duration;
    scene.output.frame_count = std::max(1, int(std::ceil(duration * scene.output.fps)));
  } else {
    scene.output.frame_count = 1;
  }
  return scene;
}

Result<scene::Scene> open_scene(const std::string& name, const scene::Scene* current) {
  std::error_code error;
  const bool is_file = !name.empty() && std::filesystem::exists(name, error);
  if (!is_file && (name.empty() || name == "default")) return scene::default_scene();
  if (!is_file && name == "crowd") return scene::crowd_scene();
  if (!is_file) return make_error(name + ": no such file (and not \"default\" or \"crowd\")");
  switch (open_kind(name)) {
    case OpenKind::model: return stage_model(name);
    case OpenKind::environment: {
      scene::Scene scene = current ? *current : scene::default_scene();
      scene.environment.type = scene::Environment::Type::map;
      scene.environment.map_path = std::filesystem::absolute(name).string();
      return scene;
    }
    case OpenKind::scene: return scene::load_scene(name);
  }
  return make_error(name + ": cannot open");
}

}  // namespace proxygi::view
