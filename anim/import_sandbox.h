#pragma once
// Private to the importer: external file access confined to the model's folder. tinygltf 2.7
// reads any path a URI names (absolute, "../", percent-encoded, CWD fallback, devices and FIFOs
// without size checks); everything external goes through these functions instead.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "anim/import_context.h"

namespace proxygi::anim::detail {

// The file an external (non data:) URI names inside base_dir, after percent-decoding. Refuses
// empty URIs, absolute paths, URI schemes ("file:", "http:"), ".." segments, NUL bytes, an
// empty base_dir, and paths that leave base_dir through symbolic links.
Result<std::filesystem::path> resolve_external_uri(const std::filesystem::path& base_dir,
                                                   const std::string& uri);

// Reads a resolved external file (regular files only, at most max_bytes).
Result<std::vector<std::uint8_t>> read_external_file(const std::filesystem::path& base_dir,
                                                     const std::string& uri, std::uint64_t max_bytes);

// Filesystem callbacks for tinygltf that only see regular files inside `sandbox->base_dir`.
struct Sandbox {
  std::filesystem::path base_dir;  // canonical, or empty to refuse every file
  std::uint64_t max_bytes = 0;
};
tinygltf::FsCallbacks sandbox_callbacks(Sandbox* sandbox);

// Checks every buffer and image URI of the glTF JSON before tinygltf sees them, so refusals
// name the object ("buffer 1: uri ..."). JSON that does not parse is left to tinygltf.
Status check_uris(std::string_view json, const std::filesystem::path& base_dir);

// The JSON chunk of a GLB, or empty when the header is malformed (tinygltf then reports it).
std::string_view glb_json_chunk(const std::uint8_t* bytes, std::size_t size);

}  // namespace proxygi::anim::detail
