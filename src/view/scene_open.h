#pragma once
// What `proxygi view NAME` and a file dropped on the window open, as a scene:
//  - "default", "crowd" (or nothing): the built-in scenes (a file of that name wins);
//  - *.json: a scene file;
//  - *.glb / *.gltf, "mannequin", "builtin:mannequin": the model on the default stage of
//    world::stage_scene, the one `record MODEL.glb` renders (ground, sky, sun; the character at
//    its own size standing on the ground over its clip, a fixed camera framing the clip's
//    bounds, one pass of the clip);
//  - *.hdr / *.exr: `current` (or the default scene) with that image as its environment.
// No GPU here: staging a model imports it to measure its bounds (the world loads it again).
#include <filesystem>
#include <string>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::view {

enum class OpenKind { scene, model, environment };
OpenKind open_kind(const std::string& name);

// `assets_dir`: where assets/mannequin.glb lives (world::WorldOptions). Errors name the file.
Result<scene::Scene> open_scene(const std::string& name, const scene::Scene* current,
                                const std::filesystem::path& assets_dir);

}  // namespace proxygi::view
