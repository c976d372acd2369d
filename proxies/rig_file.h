#pragma once
// `*.proxies.json`: the proxy rig on disk, cached next to its model as MODEL.proxies.json
// (CesiumMan.glb -> CesiumMan.proxies.json) and reused while the model's content hash matches.
// People hand-edit it (move, scale, delete, add spheres), so the writer puts one sphere per line
// and the loader validates everything and names the line of a bad sphere:
//   "hero.proxies.json:14: sphere 7: radius must be > 0".
//
// Schema (version 2; version 1 files, with weights by node name, still load):
// {
//   "schema": "proxygi.proxies", "version": 2,
//   "model": "CesiumMan.glb", "model_hash": "fnv1a64:<16 hex>",
//   "binding": "rigid" | "blended", "tolerance": 0.05, "max_spheres": 96, "diagonal_m": 1.91,
//   "spheres": [
//     {"bone": "<node name>", "node": 3, "center": [x, y, z], "radius": r, "albedo": [r, g, b],
//      "weights": [[<node index>, w], ...]},
//     ...
//   ],
//   "fit": {...}   // informational: seconds, quality, tracking errors, warnings (ignored on load)
// }
// Spheres are bound by node index, never by name: glTF node names may be empty or repeated.
// Required per sphere: node (a node index; the writer always gives it) or, for hand-added
// spheres, bone alone (then it must name exactly one node); center (3 finite numbers, bone space,
// meters); radius (finite, > 0). bone next to node is a check: it must be that node's name
// (a model whose nodes were renamed or reordered fails loudly instead of binding wrong bones).
// Optional: albedo (3 finite numbers >= 0, default white), weights (at most 4 [node index,
// weight] pairs, or {"unique node name": weight}, with finite weights >= 0 and a positive sum;
// renormalized; absent = follow the bone only).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

// FNV-1a, 64-bit, over the bytes: "fnv1a64:" + 16 lowercase hex digits.
std::string content_hash(std::span<const std::uint8_t> bytes);
Result<std::string> hash_file(const std::filesystem::path& path);

// Warnings for bone nodes (skin joints, mesh nodes) without a name or sharing one: rigs bind by
// index, so these render right, but a person reading the rig cannot tell the bones apart. Each
// names the model (character.source) and the nodes. Printed by fit, info and record.
std::vector<std::string> node_name_warnings(const anim::Character& character);

// MODEL.proxies.json next to the model.
std::filesystem::path default_rig_path(const std::filesystem::path& model);

// The file text (one sphere per line; floats with 7 significant digits).
std::string rig_to_json(const ProxyRig& rig, const anim::Character& character);
Status write_rig(const std::filesystem::path& path, const ProxyRig& rig, const anim::Character& character);

// Parses and validates against the character (bone names). `file_name` prefixes messages.
Result<ProxyRig> parse_rig(std::string_view text, const std::string& file_name, const anim::Character& character);
Result<ProxyRig> read_rig(const std::filesystem::path& path, const anim::Character& character);

}  // namespace proxygi::proxies
