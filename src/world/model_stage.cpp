#include "world/model_stage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/scene_defaults.h"

namespace proxygi::world {

Result<Bounds> posed_bounds(const World& world, double t, std::size_t instance) {
  WorldState state;
  if (Status evaluated = world.evaluate(t, std::nullopt, state); !evaluated) return evaluated.error();
  auto primitives = world.pose_instance(state, instance);
  if (!primitives) return primitives.error();
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const anim::PosedPrimitive& primitive : *primitives)
    for (const glm::vec3& p : primitive.positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  if (!(low.x <= high.x)) return make_error(world.scene().characters.at(world.instances().at(instance).scene_character).model +
                                            ": no geometry to frame");
  return Bounds{low, high};
}

Result<Bounds> bounds_over_time(const World& world, double first_s, double last_s, int samples, std::size_t instance) {
  samples = std::max(samples, 1);
  Bounds all{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
  for (int i = 0; i < samples; ++i) {
    const double t = samples == 1 ? first_s : first_s + (last_s - first_s) * double(i) / double(samples - 1);
    auto bounds = posed_bounds(world, t, instance);
    if (!bounds) return bounds.error();
    all.first = glm::min(all.first, bounds->first);
    all.second = glm::max(all.second, bounds->second);
  }
  return all;
}

scene::FixedCamera frame_bounds(const Bounds& bounds, float fov_degrees, const glm::vec3& direction) {
  const glm::vec3 center = 0.5f * (bounds.first + bounds.second);
  const float radius = std::max(0.5f * glm::length(bounds.second - bounds.first), 1e-3f);
  const float half_fov = glm::radians(0.5f * fov_degrees) * 0.8f;
  scene::FixedCamera camera;
  camera.target = center;
  camera.position = center + glm::normalize(direction) * (radius / std::sin(half_fov));
  camera.fov_degrees = fov_degrees;
  return camera;
}

Result<scene::Scene> stage_scene(const std::string& model, const std::filesystem::path& assets_dir, const StageOptions& options) {
  scene::Scene scene = scene::default_scene();
  const std::string name = scene::is_builtin_mannequin(model) ? std::string("the mannequin") : std::filesystem::path(model).filename().string();
  scene.description = "Built by proxygi around " + name + ": the default stage, the character at its own size on the ground, "
                      "a fixed camera framing its clip.";
  scene::Character character;
  character.model = scene::is_builtin_mannequin(model) ? model : std::filesystem::absolute(model).string();
  character.clip = options.clip;
  scene.characters = {character};

  auto world = World::load(scene, {.assets_dir = assets_dir, .load_rigs = false});
  if (!world) return world.error();
  const CharacterInstance& instance = (*world)->instances().front();
  const auto& clips = instance.model->character.clips;
  const float duration = instance.clip >= 0 ? clips[std::size_t(instance.clip)].duration : 0.0f;
  const int pass = std::max(1, int(std::floor(double(duration) * scene.output.fps)));
  scene.output.first_frame = 0;
  scene.output.frame_count = options.frame_count.value_or(pass);
  const double last_s = scene::frame_time_s(scene.output, scene.output.frame_count - 1);
  auto bounds = bounds_over_time(**world, 0.0, last_s, std::clamp(scene.output.frame_count, 1, 24));
  if (!bounds) return bounds.error();

  const glm::vec3 center = 0.5f * (bounds->first + bounds->second);
  const glm::vec3 offset(-center.x, -bounds->first.y, -center.z);
  scene.characters[0].transform.translation = offset;
  scene.camera.kind = frame_bounds({bounds->first + offset, bounds->second + offset});
  return scene;
}

}  // namespace proxygi::world
