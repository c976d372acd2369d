#pragma once
// The static receivers' PRT as the frame loads and applies it (render.static_transfer ratio, l1):
// where the transfer comes from when a scene is loaded (computed with prt/transfer.h or read from
// the cache, prt/transfer_cache.h), and the CPU twin of one receiver of exponentiate.comp's
// static-transfer variants (static_transfer.glsl), which the GPU twin test compares against.
//
//   auto loaded = prt::load_static_field(world, settings.sh_order, {});   // seconds (or the cache)
//   records = prt::bake_static_records(*loaded->field, tables.lighting);  // per lighting
//   e = prt::static_receiver_direct(tables, *loaded->field, records, level, f, tau, p, n);
//   if (!e) e = prt::character_receiver_direct(tables, *loaded->visibility, level, f, tau, p, n);
#include <filesystem>
#include <memory>
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "base/result.h"
#include "prt/static_field.h"
#include "prt/transfer.h"
#include "prt/visibility_grid.h"
#include "render/frame_tables.h"
#include "scene/scene.h"
#include "world/world.h"

namespace proxygi::prt {

// How the frame's PRT is made (the `proxygi prt` defaults; its options change them there).
struct StaticFieldOptions {
  float spacing_m = 0.1f;        // longest edge of the subdivided receivers (prt/surfaces.h)
  float ground_margin_m = 2.0f;  // the ground patch around the static meshes
  TransferSettings transfer;     // its order is replaced by the frame's SH order
  // Static geometry shadowing the characters: its spacing and seed (margin and directions are
  // ground_margin_m and transfer.directions, as `proxygi prt` makes it).
  VisibilityGridSettings grid;
  std::filesystem::path cache_dir;  // empty: default_cache_dir(the world's scene)
  int threads = 0;                  // precompute threads, <= 0: all
};

// prt-cache/ next to the scene file when that folder can be written, else the user cache's
// prt/ folder ($XDG_CACHE_HOME/proxygi/prt; also for built-in scenes).
std::filesystem::path default_cache_dir(const scene::Scene& scene);

struct LoadedStaticField {
  std::shared_ptr<const StaticTransferField> field;  // null: the scene has no static meshes
  bool from_cache = false;
  std::filesystem::path file;  // the cache file read or written
  double seconds = 0.0;        // wall time to subdivide, compute or read, and build the lookup grid
  std::uint64_t rays = 0;      // traced (0 when read from the cache)
  // The static meshes' visibility grid (prt/visibility_grid.h; null with the field), its cache file.
  std::shared_ptr<const VisibilityGrid> visibility;
  bool grid_from_cache = false;
  std::filesystem::path grid_file;
  double grid_seconds = 0.0;      // wall time to compute or read it (included in `seconds`)
  std::uint64_t grid_rays = 0;    // traced (0 when read from the cache)
};

// The world's static meshes and ground patch subdivided, their transfer at `order` computed or
// read from the cache, and the lookup field over them. Fails when the cache folder cannot be
// written or the transfer fails (messages name the file or surface).
Result<LoadedStaticField> load_static_field(const world::World& world, int order, const StaticFieldOptions& options);

// CPU twin of exponentiate.comp's static-transfer variant for one receiver (p, N) with log
// occlusion f: O_p = HYB(f) (sh::exp_hybrid, as render::exponentiate_and_shade), the PRT hit
// (find_static_hit), its interpolated record and shade_static_direct with LH(N) from the
// environment's own cubes (tables.lighting_cube[0..2]). Nothing when (p, N) is not static, or for
// l0. `records` are bake_static_records(field, tables.lighting).
std::optional<glm::vec3> static_receiver_direct(const render::FrameTables& tables, const StaticTransferField& field,
                                                std::span<const float> records, StaticTransferLevel level,
                                                std::span<const float> log_occlusion, float tau, const glm::vec3& p,
                                                const glm::vec3& normal);

// CPU twin of the same variants for a receiver that is not static (static_receiver_direct gave
// nothing) at (p, N): O_p = HYB(f), V_s = sample_visibility(grid, p), E = clamp((O_p ∗ V_s) ·
// LH(N), 0, √4π LH_0) per channel with LH from the cube set of p (render::lighting_cube_set, as
// l0). Nothing for l0, or when p lies outside the grid (the receiver keeps l0's E).
std::optional<glm::vec3> character_receiver_direct(const render::FrameTables& tables, const VisibilityGrid& grid,
                                                   StaticTransferLevel level, std::span<const float> log_occlusion,
                                                   float tau, const glm::vec3& p, const glm::vec3& normal);

}  // namespace proxygi::prt
