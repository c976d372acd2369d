#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace proxygi::scene {

glm::quat Rotation::to_quat() const {
  if (form == Form::quaternion) return glm::normalize(quaternion);
  const glm::vec3 r = glm::radians(euler_degrees);
  const glm::quat qx = glm::angleAxis(r.x, glm::vec3(1.0f, 0.0f, 0.0f));
  const glm::quat qy = glm::angleAxis(r.y, glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::quat qz = glm::angleAxis(r.z, glm::vec3(0.0f, 0.0f, 1.0f));
  return qz * qy * qx;  // extrinsic XYZ: X is applied first
}

glm::mat4 Transform::to_matrix() const {
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), translation);
  const glm::mat4 r = glm::mat4_cast(rotation.to_quat());
  const glm::mat4 s = glm::scale(glm::mat4(1.0f), scale);
  return t * r * s;
}

double frame_time_s(const Output& output, int frame) { return frame / output.fps; }

int last_frame(const Output& output) { return output.first_frame + output.frame_count - 1; }

std::filesystem::path resolve_scene_path(const Scene& scene, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || scene.base_dir.empty()) return p;
  return scene.base_dir / p;
}

bool is_builtin_mannequin(std::string_view model) { return model == kBuiltinMannequin; }

bool names_the_mannequin(const std::string& argument) {
  std::error_code error;
  return (argument == "mannequin" || is_builtin_mannequin(argument)) && !std::filesystem::exists(argument, error);
}

std::filesystem::path resolve_model_path(const Scene& scene, const std::string& model,
                                         const std::filesystem::path& assets_dir) {
  if (is_builtin_mannequin(model)) return assets_dir / "mannequin.glb";
  return resolve_scene_path(scene, model);
}

std::filesystem::path default_proxy_path(const std::filesystem::path& model_file) {
  std::filesystem::path rig = model_file;
  rig.replace_extension(".proxies.json");
  return rig;
}

std::filesystem::path resolve_proxy_path(const Scene& scene, const Character& character,
                                         const std::filesystem::path& assets_dir) {
  if (character.proxies) return resolve_scene_path(scene, *character.proxies);
  return default_proxy_path(resolve_model_path(scene, character.model, assets_dir));
}

}  // namespace proxygi::scene
