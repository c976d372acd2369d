#pragma once
// Writing scenes back to JSON (schema version 1), e.g. to export the built-in scenes as
// assets/scenes/*.json. Every field is written, defaults included, so a written file documents
// the whole schema. Numbers are written as the shortest decimal that reads back to the same
// float, so parse_scene(to_json(s)) == s exactly (with base_dir set to the file's folder).
// Paths are written as stored (relative to the original scene folder). Only the fields of the
// chosen environment type are written (sun and sky for "sky", the path for "map"), so the
// round trip holds for scenes whose unused environment fields are at their defaults.
#include <filesystem>
#include <string>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::scene {

// Validates the scene (refusing what parse_scene would refuse) and returns JSON text: two-space
// indentation, keys in schema order, arrays of numbers on one line, a trailing newline.
Result<std::string> to_json(const Scene& scene);

// to_json, then written atomically to path (see base/atomic_file.h).
Status save_scene(const Scene& scene, const std::filesystem::path& path);

}  // namespace proxygi::scene
