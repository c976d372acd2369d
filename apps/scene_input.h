#pragma once
// The SCENE argument of record and reference, read one way: empty or "default" / "crowd" for a
// built-in scene, a scene JSON file, or a model (a .glb / .gltf file, "mannequin" or
// "builtin:mannequin"), around which the default stage is built (world/model_stage.h): render
// your own character without writing JSON. A file of that name wins over a built-in name.
//   --clip NAME|INDEX   the model's clip (default 0); only with a model
//   -f, --frame-count N frames of the built scene (default: one pass of the clip); only with a model
//   --write-scene FILE  also write the scene as JSON, to edit and render again
#include <string>

#include <CLI/CLI.hpp>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::app {

struct SceneArgs {
  std::string scene;        // as given (empty: default)
  std::string clip;
  int frame_count = 0;      // 0: one pass of the clip
  std::string write_scene;
};

// Adds the positional SCENE and --clip / --write-scene (and -f when `frame_count`).
void add_scene_options(CLI::App& command, SceneArgs& args, bool frame_count);
// True when the argument names a model rather than a scene.
bool names_a_model(const std::string& argument);
// The scene to render; errors are bad input (exit 2). Writes --write-scene when given.
Result<scene::Scene> open_scene(const SceneArgs& args);

}  // namespace proxygi::app
