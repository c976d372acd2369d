#include "prt/static_frame.h"

#include <unistd.h>

#include <chrono>
#include <system_error>

#include "proxies/rig_cache.h"
#include "prt/surfaces.h"
#include "prt/transfer_cache.h"
#include "render/shading.h"
#include "sh/basis.h"
#include "sh/product.h"
#include "sh/exponential.h"

namespace proxygi::prt {
namespace {

bool writable_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return !ec && ::access(dir.c_str(), W_OK) == 0;
}

}  // namespace

std::filesystem::path default_cache_dir(const scene::Scene& scene) {
  if (!scene.base_dir.empty() && writable_folder(scene.base_dir / "prt-cache")) return scene.base_dir / "prt-cache";
  return proxies::user_cache_dir() / "prt";
}

Result<LoadedStaticField> load_static_field(const world::World& world, int order, const StaticFieldOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LoadedStaticField loaded;
  auto receivers = static_receivers(world, options.spacing_m, options.ground_margin_m);
  if (!receivers) return receivers.error();
  if (receivers->surfaces.empty()) return loaded;
  const std::filesystem::path dir = options.cache_dir.empty() ? default_cache_dir(world.scene()) : options.cache_dir;
  if (!writable_folder(dir)) return make_error(dir.string() + ": cannot create or write the PRT cache folder");
  TransferSettings settings = options.transfer;
  settings.order = order;
  auto transfer = load_or_compute_transfer(*receivers, settings, dir, {}, options.threads);
  if (!transfer) return transfer.error();
  auto field = make_static_field(*receivers, transfer->transfer, options.spacing_m);
  if (!field) return field.error();
  const auto grid_start = std::chrono::steady_clock::now();
  VisibilityGridSettings grid_settings = options.grid;
  grid_settings.margin_m = options.ground_margin_m;
  grid_settings.directions = settings.directions;
  auto grid = load_or_compute_visibility_grid(*receivers, order, grid_settings, dir, options.threads);
  if (!grid) return grid.error();
  loaded.grid_from_cache = grid->from_cache;
  loaded.grid_file = grid->file;
  loaded.grid_rays = grid->from_cache ? 0 : grid->grid.rays;
  loaded.visibility = std::make_shared<const VisibilityGrid>(std::move(grid->grid));
  loaded.grid_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - grid_start).count();
  loaded.field = std::move(*field);
  loaded.from_cache = transfer->from_cache;
  loaded.file = transfer->file;
  loaded.rays = transfer->from_cache ? 0 : transfer->transfer.rays;
  loaded.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return loaded;
}

std::optional<glm::vec3> static_receiver_direct(const render::FrameTables& tables, const StaticTransferField& field,
                                                std::span<const float> records, StaticTransferLevel level,
                                                std::span<const float> log_occlusion, float tau, const glm::vec3& p,
                                                const glm::vec3& normal) {
  if (level == StaticTransferLevel::l0) return std::nullopt;
  const std::optional<StaticHit> hit = find_static_hit(field, p, normal);
  if (!hit) return std::nullopt;
  const int order = field.order;
  const std::size_t nn = std::size_t(order * order);
  std::vector<float> visibility(nn);
  sh::exp_hybrid(order, log_occlusion, tables.optimal_linear, tau, visibility);
  std::array<std::vector<float>, 3> lh;
  for (int c = 0; c < 3; ++c) {
    lh[std::size_t(c)].resize(nn);
    render::lookup_lighting_cube(tables.lighting_cube[std::size_t(c)], normal, lh[std::size_t(c)]);
  }
  const std::vector<float> record = interpolate_record(field, records, *hit);
  return shade_static_direct(order, level, record, visibility, lh);
}

std::optional<glm::vec3> character_receiver_direct(const render::FrameTables& tables, const VisibilityGrid& grid,
                                                   StaticTransferLevel level, std::span<const float> log_occlusion,
                                                   float tau, const glm::vec3& p, const glm::vec3& normal) {
  if (level == StaticTransferLevel::l0) return std::nullopt;
  const int order = grid.order;
  const std::size_t nn = std::size_t(order * order);
  std::vector<float> static_visibility(nn);
  if (!sample_visibility(grid, p, static_visibility)) return std::nullopt;
  std::vector<float> occlusion(nn), visibility(nn);
  sh::exp_hybrid(order, log_occlusion, tables.optimal_linear, tau, occlusion);
  sh::product(order, occlusion, static_visibility, visibility);
  std::vector<float> lh(nn);
  const int set = render::lighting_cube_set(p);
  glm::vec3 e(0.0f);
  for (int c = 0; c < 3; ++c) {
    render::lookup_lighting_cube(tables.lighting_cube[std::size_t(set + c)], normal, lh);
    float sum = 0.0f;
    for (std::size_t i = 0; i < nn; ++i) sum += visibility[i] * lh[i];
    e[c] = std::clamp(sum, 0.0f, std::max(float(sh::kSqrtFourPi) * lh[0], 0.0f));
  }
  return e;
}

}  // namespace proxygi::prt
