#pragma once
// The PRT cache: a TransferSet in one binary file, keyed by a hash of the receivers' geometry
// (positions, normals, indices, albedo, outer ground) and the TransferSettings, so any change to
// either misses. Written atomically (base/atomic_file.h). A file that cannot be read, is
// truncated, fails its checksum or does not match the receivers is recomputed with a warning.
//
// File: DIR/prt-<key hex>.bin = "PGPRT001", u64 key, i32 order, u32 surfaces, per surface u32
// vertex count, then per surface T_DS and T_DI floats (little endian, transfer.h layout), then a
// u64 FNV-1a checksum of all preceding bytes.
// The visibility grid (prt/visibility_grid.h) beside it: DIR/prt-grid-<key hex>.bin = "PGPRTV01",
// u64 key (the same receivers' hash with the order and VisibilityGridSettings), i32 order, vec3
// origin, f32 spacing, uvec3 size, the values (visibility_grid.h layout), u64 FNV-1a checksum.
#include <cstdint>
#include <filesystem>

#include "base/result.h"
#include "prt/transfer.h"
#include "prt/visibility_grid.h"

namespace proxygi::prt {

std::uint64_t transfer_key(const StaticReceivers& receivers, const TransferSettings& settings);
std::filesystem::path transfer_cache_file(const std::filesystem::path& dir, std::uint64_t key);

struct CachedTransfer {
  TransferSet transfer;
  bool from_cache = false;
  std::filesystem::path file;
};

// Reads DIR's cache file for (receivers, settings), or computes and writes it (creating DIR).
// Fails only when computing fails or the file cannot be written ("DIR/prt-….bin: ...").
Result<CachedTransfer> load_or_compute_transfer(const StaticReceivers& receivers, const TransferSettings& settings,
                                                const std::filesystem::path& dir, const Progress& progress = {},
                                                int threads = 0);

// The file's transfer when it is intact and matches (key, vertex counts); else an error naming why.
Result<TransferSet> read_transfer_file(const std::filesystem::path& file, std::uint64_t key,
                                       const StaticReceivers& receivers);
Status write_transfer_file(const std::filesystem::path& file, std::uint64_t key, const TransferSet& transfer);

std::uint64_t visibility_grid_key(const StaticReceivers& receivers, int order, const VisibilityGridSettings& settings);
std::filesystem::path visibility_grid_cache_file(const std::filesystem::path& dir, std::uint64_t key);

struct CachedVisibilityGrid {
  VisibilityGrid grid;
  bool from_cache = false;
  std::filesystem::path file;
};

// As load_or_compute_transfer, for the visibility grid (a bad file is recomputed with a warning).
Result<CachedVisibilityGrid> load_or_compute_visibility_grid(const StaticReceivers& receivers, int order,
                                                             const VisibilityGridSettings& settings,
                                                             const std::filesystem::path& dir, int threads = 0);
Result<VisibilityGrid> read_visibility_grid_file(const std::filesystem::path& file, std::uint64_t key);
Status write_visibility_grid_file(const std::filesystem::path& file, std::uint64_t key, const VisibilityGrid& grid);

}  // namespace proxygi::prt
