#pragma once
// What `proxygi view NAME` and a file dropped on the window open, as a scene:
//  - "default", "crowd" (or nothing): the built-in scenes (a file of that name wins);
//  - *.json: a scene file;
//  - *.glb / *.gltf: the model on the default stage (ground, sky, sun), standing on the ground
//    at its own size (centered over the origin, lowest point at y = 0), playing its first clip,
//    framed by a fixed camera; the frame range covers the clip;
//  - *.hdr / *.exr: `current` with that image as its environment.
// No GPU here: models are imported to measure them (the world loads them again).
#include <filesystem>
#include <string>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::view {

enum class OpenKind { scene, model, environment };
OpenKind open_kind(const std::string& name);

Result<scene::Scene> open_scene(const std::string& name, const scene::Scene* current);

// The default stage around one model file (see above). Errors name the file.
Result<scene::Scene> stage_model(const std::filesystem::path& model);

}  // namespace proxygi::view
