#pragma once
// glTF 2.0 writer for a Character: what the importer reads comes back unchanged (nodes with
// TRS or matrix, names, meshes with positions/normals/uvs/JOINTS_n/WEIGHTS_n/morph targets,
// materials, skins with inverse bind matrices, clips with STEP/LINEAR/CUBICSPLINE samplers).
// Images are written as uncompressed RGBA8 PNGs embedded in the buffer.
//
// Encoding: float positions/normals/uvs/weights; uint16 joints (JOINTS_0, JOINTS_1, ... four
// influences per set; a primitive with I influences writes ceil(I / 4) sets, zero-padded); uint32
// indices; one buffer; GLB with the buffer as BIN chunk, .gltf with the buffer as a base64 data
// URI. Output bytes are a pure function of the Character (deterministic). Files are written
// atomically (temporary file in the same folder, then rename).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "anim/character.h"
#include "base/result.h"

namespace proxygi::anim {

// Writes a binary .glb.
Status write_glb(const Character& character, const std::filesystem::path& path);
// Writes a text .gltf with an embedded (data URI) buffer.
Status write_gltf(const Character& character, const std::filesystem::path& path);
// Chooses by extension: ".glb" → binary, ".gltf" → text; anything else is an error.
Status write_character(const Character& character, const std::filesystem::path& path);

// The bytes write_glb would write (for tests and in-memory round trips).
Result<std::vector<std::uint8_t>> encode_glb(const Character& character);

}  // namespace proxygi::anim
