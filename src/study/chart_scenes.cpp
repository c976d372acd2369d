#include "study/chart_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/log.h"
#include "scene/scene_defaults.h"
#include "world/world.h"

namespace proxygi::study {
namespace {

struct SharedCharacter {
  const char* name;
  const char* file;
  scene::ClipRef clip;
};

// Bounds of the world's one character posed at scene time 0 (its transform still identity).
Result<std::pair<glm::vec3, glm::vec3>> posed_bounds(const world::World& world) {
  world::WorldState state;
  if (Status evaluated = world.evaluate(0.0, std::nullopt, state); !evaluated) return evaluated.error();
  auto primitives = world.pose_instance(state, 0);
  if (!primitives) return primitives.error();
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const anim::PosedPrimitive& primitive : *primitives)
    for (const glm::vec3& p : primitive.positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  if (!(low.x <= high.x)) return make_error(world.scene().characters.front().model + ": no geometry to frame");
  return std::make_pair(low, high);
}

Result<ChartScene> character_scene(const SharedCharacter& shared, const ChartSceneOptions& options) {
  ChartScene chart;
  chart.name = shared.name;
  chart.scene = scene::default_scene();
  chart.scene.description = std::string("Chart scene: ") + shared.name + " walking in place on the default stage.";
  scene::Character character;
  character.model = (options.shared_dir / "assets" / "gltf" / shared.file).string();
  character.clip = shared.clip;
  character.proxies = (options.rig_cache_dir / (std::string(shared.name) + ".proxies.json")).string();
  chart.scene.characters = {character};

  // The model is imported once: for its bounds here and its clip's duration below.
  auto world = world::World::load(chart.scene, {.assets_dir = options.assets_dir, .load_rigs = false});
  if (!world) return world.error();
  auto bounds = posed_bounds(**world);
  if (!bounds) return bounds.error();
  const glm::vec3 extent = bounds->second - bounds->first;
  const float scale = 1.7f / std::max({extent.x, extent.y, extent.z});
  const glm::vec3 center = 0.5f * (bounds->first + bounds->second);
  character.transform.scale = glm::vec3(scale);
  character.transform.translation = glm::vec3(-center.x * scale, -bounds->first.y * scale, -center.z * scale);
  chart.scene.characters = {character};

  scene::FixedCamera camera;
  camera.position = glm::vec3(1.6f, 1.5f, 3.4f);
  camera.target = glm::vec3(0.0f, 0.6f, 0.0f);
  camera.fov_degrees = 50.0f;
  chart.scene.camera.kind = camera;

  // One pass over the clip: the frames of motion are spread over its duration.
  const world::CharacterInstance& instance = (*world)->instances().front();
  const auto& clips = instance.model->character.clips;
  const int clip = instance.clip;
  const float duration = clip >= 0 && std::size_t(clip) < clips.size() ? clips[std::size_t(clip)].duration : 1.0f;
  chart.scene.output.frame_count = std::max(1, int(std::floor(duration * chart.scene.output.fps)));
  return chart;
}

}  // namespace

std::vector<int> spread_frames(int first, int count, int frame_count) {
  std::vector<int> frames;
  for (int i = 0; i < frame_count; ++i) frames.push_back(first + (i + 1) * count / (frame_count + 1));
  return frames;
}

Result<std::vector<ChartScene>> chart_scenes(const ChartSceneOptions& options) {
  auto wanted = [&](const std::string& name) {
    return options.only.empty() || std::find(options.only.begin(), options.only.end(), name) != options.only.end();
  };
  std::vector<ChartScene> scenes;
  if (wanted("default")) scenes.push_back({"default", scene::default_scene(), {}});
  const SharedCharacter shared[] = {{"CesiumMan", "CesiumMan.glb", scene::ClipRef(0)},
                                    {"Fox", "Fox.glb", scene::ClipRef(std::string("Walk"))},
                                    {"RiggedSimple", "RiggedSimple.glb", scene::ClipRef(0)}};
  for (const SharedCharacter& character : shared) {
    if (!wanted(character.name)) continue;
    const std::filesystem::path file = options.shared_dir / "assets" / "gltf" / character.file;
    std::error_code error;
    if (options.shared_dir.empty() || !std::filesystem::is_regular_file(file, error)) {
      log_warning(std::string("bench chart: ") + file.string() + " not found; scene " + character.name + " skipped");
      continue;
    }
    auto scene = character_scene(character, options);
    if (!scene) return scene.error();
    scenes.push_back(std::move(*scene));
  }
  for (ChartScene& chart : scenes) {
    chart.scene.output.width = chart.scene.output.height = options.size;
    chart.frames = spread_frames(chart.scene.output.first_frame, chart.scene.output.frame_count, options.frame_count);
  }
  return scenes;
}

}  // namespace proxygi::study
