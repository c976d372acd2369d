#include "prt/transfer_cache.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>

#include "base/atomic_file.h"
#include "base/log.h"

namespace proxygi::prt {
namespace {

constexpr char kMagic[8] = {'P', 'G', 'P', 'R', 'T', '0', '0', '1'};
constexpr char kGridMagic[8] = {'P', 'G', 'P', 'R', 'T', 'V', '0', '1'};
constexpr std::uint64_t kMaxFileBytes = std::uint64_t(8) << 30;

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof(v));
  }
  template <class T>
  void vector(const std::vector<T>& v) {
    value(std::uint64_t(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
};

class Writer {
 public:
  template <class T>
  void value(const T& v) {
    append(&v, sizeof(v));
  }
  void append(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    bytes.insert(bytes.end(), p, p + size);
  }
  std::vector<std::uint8_t> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<std::uint8_t>& b, std::size_t start = 0) : bytes_(b), pos_(start) {}
  bool read(void* out, std::size_t size) {
    if (size > bytes_.size() - pos_) return false;
    std::memcpy(out, bytes_.data() + pos_, size);
    pos_ += size;
    return true;
  }
  template <class T>
  bool value(T& v) {
    return read(&v, sizeof(v));
  }
  std::size_t position() const { return pos_; }

 private:
  const std::vector<std::uint8_t>& bytes_;
  std::size_t pos_ = 0;
};

// Both cache files: magic (8 bytes), key (u64), SH order (i32), the payload, then the FNV-1a
// checksum (u64) of everything before it.
void begin_file(Writer& w, const char (&magic)[8], std::uint64_t key, int order) {
  w.append(magic, sizeof(magic));
  w.value(key);
  w.value(std::int32_t(order));
}

Status finish_file(Writer& w, const std::filesystem::path& file) {
  Fnv fnv;
  fnv.bytes(w.bytes.data(), w.bytes.size());
  w.value(fnv.h);
  return write_file_atomically(file, std::span<const std::uint8_t>(w.bytes));
}

struct OpenedFile {
  std::vector<std::uint8_t> bytes;
  std::string where;  // "FILE: ", the prefix of every error
  int order = 0;
  std::size_t payload = 0;  // offset of the payload
};

// Reads `file` and checks its checksum, magic (`what` names the kind in the error), key and order.
Result<OpenedFile> open_file(const std::filesystem::path& file, const char (&magic)[8], const char* what,
                             std::uint64_t key) {
  auto bytes = read_file(file, kMaxFileBytes);
  if (!bytes) return bytes.error();
  OpenedFile out{std::move(*bytes), file.string() + ": "};
  const std::string& where = out.where;
  if (out.bytes.size() < sizeof(magic) + 8) return make_error(where + "truncated");
  Fnv fnv;
  fnv.bytes(out.bytes.data(), out.bytes.size() - 8);
  std::uint64_t stored_sum = 0;
  std::memcpy(&stored_sum, out.bytes.data() + out.bytes.size() - 8, 8);
  if (stored_sum != fnv.h) return make_error(where + "checksum mismatch (corrupt or truncated)");
  Reader r(out.bytes);
  char stored_magic[8];
  std::uint64_t stored_key = 0;
  std::int32_t order = 0;
  if (!r.read(stored_magic, 8) || std::memcmp(stored_magic, magic, 8) != 0)
    return make_error(where + "not a proxygi " + what + " (bad magic)");
  if (!r.value(stored_key) || stored_key != key) return make_error(where + "key mismatch");
  if (!r.value(order) || order < 1 || order > 8) return make_error(where + "bad SH order");
  out.order = order;
  out.payload = r.position();
  return out;
}

Status check_end(const Reader& r, const OpenedFile& opened) {
  if (r.position() != opened.bytes.size() - 8) return make_error(opened.where + "trailing bytes");
  return {};
}

// The cached value when `file` holds a valid one (read), else computed and written to `file`
// (a bad file is warned about and replaced). Returns the value and whether it came from the cache.
template <class Value, class Read, class Compute, class Write>
Result<std::pair<Value, bool>> load_or_compute(const std::filesystem::path& file, const std::filesystem::path& dir,
                                               const char* what, Read read, Compute compute, Write write) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) {
    Result<Value> cached = read();
    if (cached) return std::pair<Value, bool>{std::move(*cached), true};
    log_warning(cached.message() + "; recomputing the PRT " + what);
  }
  Result<Value> computed = compute();
  if (!computed) return computed.error();
  std::filesystem::create_directories(dir, ec);
  if (ec) return make_error(dir.string() + ": cannot create the PRT cache folder: " + ec.message());
  if (Status written = write(*computed); !written) return written.error();
  return std::pair<Value, bool>{std::move(*computed), false};
}

// The receivers' geometry, albedos and outer ground (both cache keys).
void hash_receivers(Fnv& fnv, const StaticReceivers& receivers) {
  fnv.value(std::uint64_t(receivers.surfaces.size()));
  for (const StaticSurface& s : receivers.surfaces) {
    fnv.vector(s.positions);
    fnv.vector(s.normals);
    fnv.vector(s.indices);
    fnv.value(s.albedo);
  }
  const OuterGround& g = receivers.outer_ground;
  fnv.value(g.enabled);
  fnv.value(g.half_size);
  fnv.value(g.patch_min);
  fnv.value(g.patch_max);
  fnv.value(g.albedo);
}

}  // namespace

std::uint64_t transfer_key(const StaticReceivers& receivers, const TransferSettings& settings) {
  Fnv fnv;
  fnv.bytes(kMagic, sizeof(kMagic));
  fnv.value(settings.order);
  fnv.value(settings.directions);
  fnv.value(settings.bounces);
  fnv.value(settings.seed);
  hash_receivers(fnv, receivers);
  return fnv.h;
}

std::filesystem::path transfer_cache_file(const std::filesystem::path& dir, std::uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof(name), "prt-%016llx.bin", static_cast<unsigned long long>(key));
  return dir / name;
}

Status write_transfer_file(const std::filesystem::path& file, std::uint64_t key, const TransferSet& transfer) {
  Writer w;
  begin_file(w, kMagic, key, transfer.order);
  w.value(std::uint32_t(transfer.surfaces.size()));
  const std::size_t nn = std::size_t(transfer.order * transfer.order);
  for (const SurfaceTransfer& s : transfer.surfaces) w.value(std::uint32_t(s.shadowed.size() / nn));
  for (const SurfaceTransfer& s : transfer.surfaces) {
    w.append(s.shadowed.data(), s.shadowed.size() * sizeof(float));
    w.append(s.interreflected.data(), s.interreflected.size() * sizeof(float));
  }
  return finish_file(w, file);
}

Result<TransferSet> read_transfer_file(const std::filesystem::path& file, std::uint64_t key,
                                       const StaticReceivers& receivers) {
  auto opened = open_file(file, kMagic, "PRT cache", key);
  if (!opened) return opened.error();
  const std::string& where = opened->where;
  const int order = opened->order;
  Reader r(opened->bytes, opened->payload);
  std::uint32_t surfaces = 0;
  if (!r.value(surfaces) || surfaces != receivers.surfaces.size())
    return make_error(where + "surface count " + std::to_string(surfaces) + ", expected " +
                      std::to_string(receivers.surfaces.size()));
  TransferSet out;
  out.order = order;
  out.surfaces.resize(surfaces);
  const std::size_t nn = std::size_t(order * order);
  std::vector<std::uint32_t> vertices(surfaces);
  for (std::uint32_t s = 0; s < surfaces; ++s)
    if (!r.value(vertices[s]) || vertices[s] != receivers.surfaces[s].positions.size())
      return make_error(where + "surface " + std::to_string(s) + ": vertex count mismatch");
  for (std::uint32_t s = 0; s < surfaces; ++s) {
    out.surfaces[s].shadowed.resize(vertices[s] * nn);
    out.surfaces[s].interreflected.resize(vertices[s] * 3 * nn);
    if (!r.read(out.surfaces[s].shadowed.data(), out.surfaces[s].shadowed.size() * sizeof(float)) ||
        !r.read(out.surfaces[s].interreflected.data(), out.surfaces[s].interreflected.size() * sizeof(float)))
      return make_error(where + "surface " + std::to_string(s) + ": truncated");
  }
  if (Status end = check_end(r, *opened); !end) return end.error();
  return out;
}

Result<CachedTransfer> load_or_compute_transfer(const StaticReceivers& receivers, const TransferSettings& settings,
                                                const std::filesystem::path& dir, const Progress& progress,
                                                int threads) {
  const std::uint64_t key = transfer_key(receivers, settings);
  CachedTransfer out;
  out.file = transfer_cache_file(dir, key);
  auto loaded = load_or_compute<TransferSet>(
      out.file, dir, "transfer", [&] { return read_transfer_file(out.file, key, receivers); },
      [&] { return compute_transfer(receivers, settings, progress, threads); },
      [&](const TransferSet& transfer) { return write_transfer_file(out.file, key, transfer); });
  if (!loaded) return loaded.error();
  out.transfer = std::move(loaded->first);
  out.from_cache = loaded->second;
  return out;
}

std::uint64_t visibility_grid_key(const StaticReceivers& receivers, int order, const VisibilityGridSettings& settings) {
  Fnv fnv;
  fnv.bytes(kGridMagic, sizeof(kGridMagic));
  fnv.value(std::int32_t(order));
  fnv.value(settings.spacing_m);
  fnv.value(settings.margin_m);
  fnv.value(settings.directions);
  fnv.value(settings.seed);
  hash_receivers(fnv, receivers);
  return fnv.h;
}

std::filesystem::path visibility_grid_cache_file(const std::filesystem::path& dir, std::uint64_t key) {
  char name[40];
  std::snprintf(name, sizeof(name), "prt-grid-%016llx.bin", static_cast<unsigned long long>(key));
  return dir / name;
}

Status write_visibility_grid_file(const std::filesystem::path& file, std::uint64_t key, const VisibilityGrid& grid) {
  Writer w;
  begin_file(w, kGridMagic, key, grid.order);
  w.value(grid.origin);
  w.value(grid.spacing);
  w.value(grid.size);
  w.append(grid.values.data(), grid.values.size() * sizeof(float));
  return finish_file(w, file);
}

Result<VisibilityGrid> read_visibility_grid_file(const std::filesystem::path& file, std::uint64_t key) {
  auto opened = open_file(file, kGridMagic, "PRT visibility grid", key);
  if (!opened) return opened.error();
  const std::string& where = opened->where;
  const int order = opened->order;
  Reader r(opened->bytes, opened->payload);
  VisibilityGrid grid;
  grid.order = order;
  if (!r.value(grid.origin) || !r.value(grid.spacing) || !r.value(grid.size)) return make_error(where + "truncated");
  if (double(grid.size.x) * grid.size.y * grid.size.z > double(kMaxVisibilityGridPoints))
    return make_error(where + "too many grid points");
  grid.values.resize(grid.points() * std::size_t(order * order));
  if (!r.read(grid.values.data(), grid.values.size() * sizeof(float))) return make_error(where + "truncated");
  if (Status end = check_end(r, *opened); !end) return end.error();
  return grid;
}

Result<CachedVisibilityGrid> load_or_compute_visibility_grid(const StaticReceivers& receivers, int order,
                                                             const VisibilityGridSettings& settings,
                                                             const std::filesystem::path& dir, int threads) {
  const std::uint64_t key = visibility_grid_key(receivers, order, settings);
  CachedVisibilityGrid out;
  out.file = visibility_grid_cache_file(dir, key);
  auto loaded = load_or_compute<VisibilityGrid>(
      out.file, dir, "visibility grid", [&] { return read_visibility_grid_file(out.file, key); },
      [&] { return compute_visibility_grid(receivers, order, settings, threads); },
      [&](const VisibilityGrid& grid) { return write_visibility_grid_file(out.file, key, grid); });
  if (!loaded) return loaded.error();
  out.grid = std::move(loaded->first);
  out.from_cache = loaded->second;
  return out;
}

}  // namespace proxygi::prt
