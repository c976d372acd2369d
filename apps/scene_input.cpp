#include "apps/scene_input.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "apps/commands.h"
#include "settings/limits.h"
#include "apps/model_input.h"
#include "base/atomic_file.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "scene/scene_write.h"
#include "world/model_stage.h"

namespace proxygi::app {

void add_scene_options(CLI::App& command, SceneArgs& args, bool frame_count) {
  command.add_option("scene", args.scene,
                     "Scene JSON file, 'default' / 'crowd' for a built-in scene, or a model (.glb / .gltf, 'mannequin') "
                     "to render on the default stage (default: 'default')");
  command.add_option("--clip", args.clip, "With a model: its clip, by name or index (default: 0)");
  if (frame_count)
    command.add_option("-f,--frame-count", args.frame_count, "With a model: frames to render (default: one pass of the clip)")
        ->check(CLI::Range(1, settings::kMaxFrameCount));
  command.add_option("--write-scene", args.write_scene, "Also write the scene as JSON to FILE (to edit and render again)");
}

bool names_a_model(const std::string& argument) {
  std::string lower = argument;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return names_the_mannequin(argument) || lower.ends_with(".glb") || lower.ends_with(".gltf");
}

Result<scene::Scene> open_scene(const SceneArgs& args) {
  const std::string& name = args.scene;
  std::error_code error;
  const bool is_file = !name.empty() && std::filesystem::exists(name, error);
  const bool model = names_a_model(name);
  if (!model && !args.clip.empty()) return make_error("--clip is for a model (.glb, .gltf, mannequin), not the scene '" + name + "'");
  if (!model && args.frame_count > 0)
    return make_error("-f/--frame-count is for a model; for a scene, choose frames with --frames A:B");
  Result<scene::Scene> scene = make_error("");
  if (model) {
    if (!names_the_mannequin(name) && !is_file) return make_error(name + ": no such model file");
    world::StageOptions options;
    if (!args.clip.empty()) {
      if (std::all_of(args.clip.begin(), args.clip.end(), [](unsigned char c) { return std::isdigit(c); }) && args.clip.size() < 9)
        options.clip = std::stoi(args.clip);
      else
        options.clip = args.clip;
    }
    if (args.frame_count > 0) options.frame_count = args.frame_count;
    scene = world::stage_scene(names_the_mannequin(name) ? std::string("builtin:mannequin") : name, assets_dir(), options);
  } else if (!is_file && (name.empty() || name == "default")) {
    scene = scene::default_scene();
  } else if (!is_file && name == "crowd") {
    scene = scene::crowd_scene();
  } else {
    scene = scene::load_scene(name);
  }
  if (!scene) return scene;
  if (!args.write_scene.empty()) {
    auto text = scene::to_json(*scene);
    if (!text) return text.error();
    if (Status written = write_file_atomically(args.write_scene, *text + "\n"); !written) return written.error();
    if (!quiet()) std::fprintf(stderr, "wrote %s\n", args.write_scene.c_str());
  }
  return scene;
}

}  // namespace proxygi::app
