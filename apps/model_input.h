#pragma once
// The model argument every command takes the same way: a glTF/GLB file, or `mannequin` /
// `builtin:mannequin` (a file of that name wins) for the bundled figure, read from
// assets_dir()/mannequin.glb, or built in code when that file is absent (same bytes, same hash,
// world/world.h). Its rig cache is MODEL.proxies.json next to the model (for the mannequin: next
// to assets_dir()/mannequin.glb, never the current folder), with the user-cache fallback of
// proxies/rig_cache.h.
#include <filesystem>
#include <string>
#include <vector>

#include "anim/character.h"
#include "base/result.h"

namespace proxygi::app {

struct ModelInput {
  std::string argument;            // as the user gave it
  std::filesystem::path file;      // the glTF file (the mannequin's may not exist: built_in_code)
  bool mannequin = false;          // the bundled figure
  bool built_in_code = false;      // built by anim::build_mannequin (no file)
  anim::Character character;
  std::string hash;                // proxies::content_hash of the model bytes
  std::filesystem::path rig_file;  // the cache next to the model
};

// True for "mannequin" and "builtin:mannequin" when no file of that name exists.
bool names_the_mannequin(const std::string& argument);
// Reads and validates the model; every error is bad input (exit 2) and names the argument.
Result<ModelInput> open_model(const std::string& argument);

}  // namespace proxygi::app
