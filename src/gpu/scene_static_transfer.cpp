// SceneRenderer's static receivers' PRT (render.static_transfer): loaded (computed or read from
// the cache) when a level other than l0 is first asked for in a scene with static meshes, again
// when the SH order changes; its records re-baked whenever the tables (the lighting) change.
#include <chrono>
#include <cstdio>
#include <string>

#include "base/log.h"
#include "gpu/scene_renderer.h"

namespace proxygi::gpu {

std::string describe(const StaticTransferReport& r) {
  const std::string level(settings::name_of(r.level));
  if (r.level == settings::StaticTransfer::l0) return "PRT: off (render.static_transfer l0)";
  if (!r.active) return "PRT (render.static_transfer " + level + "): no static meshes, nothing to precompute";
  char rays[64] = "";
  if (!r.from_cache) std::snprintf(rays, sizeof rays, " (%.1f Mrays)", double(r.rays) / 1e6);
  char grid_rays[64] = "";
  if (!r.grid_from_cache) std::snprintf(grid_rays, sizeof grid_rays, " (%.1f Mrays)", double(r.grid_rays) / 1e6);
  char line[1024];
  std::snprintf(line, sizeof line,
                "PRT (render.static_transfer %s): %s %s in %.2f s%s, %zu vertices, %zu triangles, %.2f MiB CPU, "
                "%.2f MiB GPU, records baked in %.1f ms; visibility grid %s %s in %.2f s%s, %zu points, %.2f MiB",
                level.c_str(), r.from_cache ? "read" : "computed and wrote", r.file.c_str(), r.load_seconds,
                rays, r.vertices,
                r.triangles, double(r.cpu_bytes) / 1048576.0, double(r.gpu_bytes) / 1048576.0, r.bake_ms,
                r.grid_from_cache ? "read" : "computed and wrote", r.grid_file.c_str(), r.grid_seconds, grid_rays,
                r.grid_points, double(r.grid_bytes) / 1048576.0);
  return line;
}

Status SceneRenderer::update_static_transfer(const settings::RenderSettings& settings,
                                             const render::FrameTables& tables) {
  static_report_.level = settings.static_transfer;
  if (settings.static_transfer == settings::StaticTransfer::l0) {
    static_records_.clear();
    static_report_.active = false;
    static_report_.gpu_bytes = 0;
    return frame_->set_static_transfer(nullptr, {}, nullptr);
  }
  if (!static_field_ || static_field_->order != settings.sh_order) {
    auto loaded = prt::load_static_field(*world_, settings.sh_order, static_options_);
    if (!loaded) return make_error("render.static_transfer " + std::string(settings::name_of(settings.static_transfer)) +
                                   ": " + loaded.message());
    static_field_ = loaded->field;
    static_visibility_ = loaded->visibility;
    static_report_.grid_from_cache = loaded->grid_from_cache;
    static_report_.grid_file = loaded->grid_file;
    static_report_.grid_seconds = loaded->grid_seconds;
    static_report_.grid_rays = loaded->grid_rays;
    static_report_.grid_points = static_visibility_ ? static_visibility_->points() : 0;
    static_report_.grid_bytes = static_visibility_ ? static_visibility_->bytes() : 0;
    static_report_.from_cache = loaded->from_cache;
    static_report_.file = loaded->file;
    static_report_.load_seconds = loaded->seconds;
    static_report_.rays = loaded->rays;
    static_report_.vertices = static_field_ ? static_field_->positions.size() : 0;
    static_report_.triangles = static_field_ ? static_field_->triangles.size() : 0;
    static_report_.cpu_bytes = static_field_ ? static_field_->bytes() : 0;
    if (!static_field_) log_info("render.static_transfer: the scene has no static meshes; every receiver shades as l0");
  }
  const auto start = std::chrono::steady_clock::now();
  static_records_ = static_field_ ? prt::bake_static_records(*static_field_, tables.lighting) : std::vector<float>{};
  if (Status s = frame_->set_static_transfer(static_field_.get(), static_records_, static_visibility_.get()); !s) return s;
  static_report_.bake_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  static_report_.active = static_field_ != nullptr;
  static_report_.gpu_bytes = static_field_ ? frame_->static_transfer_bytes() : 0;
  return {};
}

}  // namespace proxygi::gpu
