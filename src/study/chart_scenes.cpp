#include "study/chart_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/log.h"
#include "scene/scene_defaults.h"
#include "world/model_stage.h"
#include "world/world.h"

namespace proxygi::study {
namespace {

struct SharedCharacter {
  const char* name;
  const char* file;
  scene::ClipRef clip;
};

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
  auto bounds = world::posed_bounds(**world, 0.0);  // the first frame (world/model_stage.h)
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
  const std::vector<std::string> only = expand_scene_groups(options.only);
  auto wanted = [&](const std::string& name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  auto named = [&](const std::string& name) { return !only.empty() && wanted(name); };
  std::vector<ChartScene> scenes;
  if (wanted("default")) scenes.push_back({"default", scene::default_scene(), {}});
  // Only when named: the default scene with a second mannequin walking 1.5 m behind the first
  // (bounce between characters beyond the proxies' sphere of influence: where VSGL should win).
  if (named("pair")) {
    ChartScene pair{"pair", scene::default_scene(), {}};
    scene::Character second = pair.scene.characters.front();
    scene::WalkPath& path = *second.path;
    path.start.z = path.end.z = -1.5f;
    second.time_offset_s = 0.4f;
    pair.scene.characters.push_back(second);
    pair.scene.description = "Chart scene: two mannequins walking side by side 1.5 m apart.";
    scenes.push_back(std::move(pair));
  }
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
  auto study = bounce_study_scenes(options, named);
  if (!study) return study.error();
  for (ChartScene& chart : *study) scenes.push_back(std::move(chart));
  for (ChartScene& chart : scenes) {
    chart.scene.output.width = chart.scene.output.height = options.size;
    chart.frames = spread_frames(chart.scene.output.first_frame, chart.scene.output.frame_count, options.frame_count);
  }
  return scenes;
}

}  // namespace proxygi::study
