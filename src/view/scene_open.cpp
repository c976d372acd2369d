#include "view/scene_open.h"

#include <algorithm>

#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "world/model_stage.h"

namespace proxygi::view {
namespace {

std::string lower_extension(const std::string& name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

}  // namespace

OpenKind open_kind(const std::string& name) {
  if (scene::names_the_mannequin(name)) return OpenKind::model;
  const std::string extension = lower_extension(name);
  if (extension == ".glb" || extension == ".gltf") return OpenKind::model;
  if (extension == ".hdr" || extension == ".exr") return OpenKind::environment;
  return OpenKind::scene;
}

Result<scene::Scene> open_scene(const std::string& name, const scene::Scene* current,
                                const std::filesystem::path& assets_dir) {
  if (scene::names_the_mannequin(name)) return world::stage_scene(std::string(scene::kBuiltinMannequin), assets_dir);
  std::error_code error;
  const bool is_file = !name.empty() && std::filesystem::exists(name, error);
  if (!is_file && (name.empty() || name == "default")) return scene::default_scene();
  if (!is_file && name == "crowd") return scene::crowd_scene();
  if (!is_file) return make_error(name + ": no such file (and not \"default\", \"crowd\" or \"mannequin\")");
  switch (open_kind(name)) {
    case OpenKind::model: return world::stage_scene(name, assets_dir);
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
