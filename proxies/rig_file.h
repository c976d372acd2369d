#pragma once
// `*.proxies.json`: the proxy rig on disk, cached next to its model as MODEL.proxies.json
// (CesiumMan.glb -> CesiumMan.proxies.json) and reused while the model's content hash matches.
// People hand-edit it (move, scale, delete, add spheres), so the writer puts one sphere per line
// and the loader validates everything and names the line of a bad sphere:
//   "hero.proxies.json:14: sphere 7: radius must be > 0".
//
// Schema (version 1):
// {
//   "schema": "proxygi.proxies", "version": 1,
//   "model": "CesiumMan.glb", "model_hash": "fnv1a64:<16 hex>",
//   "binding": "rigid" | "blended", "tolerance": 0.05, "max_spheres": 96, "diagonal_m": 1.91,
//   "spheres": [
//     {"bone": "<node name>", "node": 3, "center": [x, y, z], "radius": r, "albedo": [r, g, b],
//      "weights": {"<node name>": w, ...}},
//     ...
//   ],
//   "fit": {...}   // informational: seconds, quality, tracking errors, warnings (ignored on load)
// }
// Required per sphere: bone (a node name), center (3 finite numbers, bone space, meters),
// radius (finite, > 0). Optional: node (must be the index of a node with that name; picks among
// equal names), albedo (3 finite numbers >= 0, default white), weights (at most 4 node names
// with finite weights >= 0 and a positive sum; renormalized; absent = follow the bone only).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

// FNV-1a, 64-bit, over the bytes: "fnv1a64:" + 16 lowercase hex digits.
std::string content_hash(std::span<const std::uint8_t> bytes);
Result<std::string> hash_file(const std::filesystem::path& path);

// MODEL.proxies.json next to the model.
std::filesystem::path default_rig_path(const std::filesystem::path& model);

// The file text (one sphere per line; floats with 7 significant digits).
std::string rig_to_json(const ProxyRig& rig, const anim::Character& character);
Status write_rig(const std::filesystem::path& path, const ProxyRig& rig, const anim::Character& character);

// Parses and validates against the character (bone names). `file_name` prefixes messages.
Result<ProxyRig> parse_rig(std::string_view text, const std::string& file_name, const anim::Character& character);
Result<ProxyRig> read_rig(const std::filesystem::path& path, const anim::Character& character);

}  // namespace proxygi::proxies
