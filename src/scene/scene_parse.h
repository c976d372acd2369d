#pragma once
// Reading scene files. The format (schema version 1) is documented field by field in scene.h
// and in the README; in short, a JSON object
//   { "schema_version": 1, "description", "characters": [...], "environment": {...},
//     "ground": {...}, "static_meshes": [...], "camera": {...}, "render": {...}, "output": {...} }
// where everything except schema_version is optional and takes the defaults in scene.h.
//
// Errors are one line: "<scene file>: <field path>: <problem>", e.g.
//   "shots/a.json: characters[1].clip: expected a string or an integer, got a boolean".
// Unknown keys are refused (with a "did you mean" hint), as are duplicate keys, unknown
// schema versions, and every value validate_scene() rejects.
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "base/result.h"
#include "scene/scene.h"
#include "settings/limits.h"

namespace proxygi::scene {

// Largest scene file load_scene reads (settings/limits.h); scenes are small, this guards
// against wrong paths.
inline constexpr std::uint64_t kMaxSceneFileBytes = settings::kMaxSceneFileBytes;

// Parses and validates scene JSON. `scene_file` names the file in messages and its parent
// folder becomes Scene::base_dir (it is not opened).
Result<Scene> parse_scene(std::string_view json_text, const std::filesystem::path& scene_file);

// Reads (at most kMaxSceneFileBytes) and parses a scene file.
Result<Scene> load_scene(const std::filesystem::path& scene_file);

}  // namespace proxygi::scene
