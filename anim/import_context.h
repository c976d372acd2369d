#pragma once
// Private to anim/'s importer (never include from a public header): tinygltf declarations with
// the same configuration as anim/tinygltf_implementation.cpp, and the state shared by the
// import steps (accessors, hierarchy, meshes, skins, animations, images).
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_USE_CPP14
#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "anim/character.h"
#include "anim/gltf_import.h"
#include "base/result.h"

// Propagates a failed Status from an import step.
#define PROXYGI_IMPORT_TRY(expression)            \
  do {                                            \
    if (auto status_ = (expression); !status_) {  \
      return status_.error();                     \
    }                                             \
  } while (0)

namespace proxygi::anim::detail {

struct ImportContext {
  const tinygltf::Model& model;
  const ImportLimits& limits;
  std::filesystem::path base_dir;   // external files resolve inside it; empty = none allowed
  std::uint64_t elements_decoded = 0;
  std::uint64_t image_pixels_decoded = 0;
};

// "what: message" with the one-line error convention.
inline Error error_at(const std::string& what, const std::string& message) {
  return make_error(what + ": " + message);
}

// tinygltf parses `bytes` (GLB or JSON) into `model` with sandboxed file access (external files
// only inside base_dir, which becomes `root`, canonical) and images kept encoded; `warning` gets
// tinygltf's warnings (lines). Fails with tinygltf's error as one line (gltf_import.cpp).
Status load_model(std::span<const std::uint8_t> bytes, const std::filesystem::path& base_dir, const ImportLimits& limits,
                  tinygltf::Model& model, std::filesystem::path& root, std::string& warning);

// Each step fills its part of `character` from ctx.model; steps run in the order listed in
// gltf_import.cpp and may rely on the checks of earlier steps.
Status import_hierarchy(ImportContext& ctx, Character& character);   // import_hierarchy.cpp
Status import_materials(ImportContext& ctx, Character& character);   // import_images.cpp
Status import_meshes(ImportContext& ctx, Character& character);      // import_mesh.cpp
Status import_skins(ImportContext& ctx, Character& character);       // import_skin.cpp
Status import_animations(ImportContext& ctx, Character& character);  // import_animation.cpp

// Vertex normals from triangles with OpenMesh (import_normals.cpp): unit length, the normalized
// sum of the incident triangles' normals; vertices without a usable triangle get +Y.
std::vector<glm::vec3> compute_vertex_normals(const std::vector<glm::vec3>& positions,
                                              const std::vector<std::uint32_t>& indices);

}  // namespace proxygi::anim::detail
