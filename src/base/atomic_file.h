#pragma once
// Writes that never leave a half-written file: data goes to "<path>.tmp-<pid>" in the same
// folder, is flushed, and is renamed over <path> (rename is atomic on one POSIX file system).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "base/result.h"

namespace proxygi {

// Writes bytes to path atomically. Errors name the path and the failing system call.
Status write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
Status write_file_atomically(const std::filesystem::path& path, std::string_view text);

// For writers that need a file name (ffmpeg, tinyexr, stb): `write` gets a temporary path in
// the destination folder; when it succeeds the temporary is renamed to path, else removed.
Status write_via_temporary(const std::filesystem::path& path,
                           const std::function<Status(const std::filesystem::path& temporary)>& write);

// Reads a whole regular file, refusing anything larger than max_bytes.
Result<std::vector<std::uint8_t>> read_file(const std::filesystem::path& path, std::uint64_t max_bytes);

}  // namespace proxygi
