#pragma once
// glTF 2.0 import: reads a .gltf (with external .bin files or data URIs) or a .glb, validates
// everything proxygi relies on, and returns a Character (anim/character.h). No tinygltf type
// crosses this header.
//
//   auto character = proxygi::anim::import_gltf("hero.glb");
//   if (!character) return fail_bad_input(character.message());  // one line, names file + object
//
// What the result guarantees (checked on every import, tinygltf 2.7 checks none of it):
//  - every node/mesh/skin/material/image/accessor index is in range; the node graph is a forest
//    (no cycles, at most one parent); evaluation_order lists parents before children;
//  - every accessor fits its bufferView and buffer (64-bit offset math, byteStride honoured,
//    sparse substitution applied, bufferView-less accessors read as zeros);
//  - primitives are triangle lists with 32-bit indices < vertex count (strips and fans are
//    converted; POINTS and LINES* modes are refused); normals exist and are unit length
//    (computed with OpenMesh when absent); all float data used is finite;
//  - skinned primitives carry 4 * (number of JOINTS_n/WEIGHTS_n sets) influences per vertex, joint
//    indices < the joint count of every skin the mesh is drawn with (zero weights included),
//    weights decoded (normalized integers as c/255, c/65535) and renormalized to sum 1;
//  - skins have one inverse bind matrix per joint (identity when the file gives none);
//  - channels have strictly increasing key times >= 0, 1x (3x for CUBICSPLINE) outputs, quantized
//    rotations decoded; clip duration = last key time over its channels;
//  - external files resolve only inside the model's folder (no absolute paths, URI schemes or
//    escaping "..", also after percent-decoding), are regular files and respect the size limits;
//  - base color textures are decoded (PNG/JPEG) to RGBA8 under the image limits; images no
//    material uses as base color stay empty (name only).
// Any violation returns an Error "<file name>: <object> <index>: <what>".
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "anim/character.h"
#include "base/result.h"
#include "settings/limits.h"

namespace proxygi::anim {

// Caps that keep hostile or broken files from exhausting memory or time.
struct ImportLimits {
  std::uint64_t max_file_bytes = settings::kMaxModelFileBytes;  // the model file and each external file
  std::uint64_t max_accessor_elements = 1ull << 24;    // elements in one accessor
  std::uint64_t max_total_elements = 1ull << 27;       // elements decoded over the whole import
  std::uint32_t max_objects = 1u << 16;                // nodes, meshes, primitives, skins, ... each
  std::uint32_t max_image_dimension = 16384;           // width or height of a decoded texture
  std::uint64_t max_image_pixels = 1ull << 26;         // width * height of one texture
  std::uint64_t max_total_image_pixels = 1ull << 28;   // over all decoded textures
};

// Imports a .gltf or .glb file (chosen by content: GLB magic, else JSON). External files are
// looked up in the folder of `path` only.
Result<Character> import_gltf(const std::filesystem::path& path, const ImportLimits& limits = {});

// Imports from memory. `name` prefixes error messages and becomes Character::source; external
// URIs resolve inside `base_dir` (an empty base_dir refuses every external URI).
Result<Character> import_gltf_bytes(std::span<const std::uint8_t> bytes, const std::string& name,
                                    const std::filesystem::path& base_dir,
                                    const ImportLimits& limits = {});

}  // namespace proxygi::anim
