#include "apps/model_input.h"

#include "anim/gltf_import.h"
#include "anim/gltf_writer.h"
#include "anim/mannequin.h"
#include "apps/commands.h"
#include "proxies/rig_file.h"
#include "scene/scene.h"

namespace proxygi::app {

bool names_the_mannequin(const std::string& argument) { return scene::names_the_mannequin(argument); }

Result<ModelInput> open_model(const std::string& argument) {
  ModelInput out;
  out.argument = argument;
  out.mannequin = names_the_mannequin(argument);
  out.file = out.mannequin ? assets_dir() / "mannequin.glb" : std::filesystem::path(argument);
  std::error_code error;
  if (out.mannequin && !std::filesystem::exists(out.file, error)) {
    out.built_in_code = true;
    out.character = anim::build_mannequin();
    auto bytes = anim::encode_glb(out.character);
    if (!bytes) return make_error("mannequin: " + bytes.message());
    out.hash = proxies::content_hash(*bytes);
  } else {
    auto character = anim::import_gltf(out.file);
    if (!character) return character.error();
    out.character = std::move(*character);
    auto hash = proxies::hash_file(out.file);
    if (!hash) return hash.error();
    out.hash = *hash;
  }
  out.rig_file = proxies::default_rig_path(out.file);
  return out;
}

}  // namespace proxygi::app
