// proxygi prt SCENE [--cache DIR] [--spacing M] [--directions K] [--bounces B] [--order N]
//                   [--grid-spacing M] [--threads T] [--json] [--quiet]
// Precomputes the PRT transfer (T_DS, T_DI) of the scene's static meshes and the ground patch
// around them (src/prt), or reads it from the cache: next to the scene file in prt-cache/, or
// the user cache ($XDG_CACHE_HOME/proxygi/prt) when that folder is not writable or the scene is
// built in. Prints counts, rays, time and memory. Bad input exits 2.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/commands.h"
#include "apps/scene_input.h"
#include "proxies/rig_cache.h"
#include "prt/static_frame.h"
#include "prt/surfaces.h"
#include "prt/transfer_cache.h"
#include "settings/render_settings.h"
#include "world/world.h"

namespace proxygi::app {
namespace {

struct PrtArgs {
  SceneArgs scene;
  std::string cache;
  float spacing_m = 0.1f;
  float ground_margin_m = 2.0f;
  float grid_spacing_m = prt::VisibilityGridSettings{}.spacing_m;
  prt::TransferSettings transfer;
  int order = 0;  // 0: the scene's render.sh_order
  int threads = 0;
  bool json = false;
};

bool writable_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return !ec && ::access(dir.c_str(), W_OK) == 0;
}

std::filesystem::path cache_dir(const PrtArgs& args, const scene::Scene& scene) {
  if (!args.cache.empty()) return args.cache;
  return prt::default_cache_dir(scene);  // the frame's rule too (render.static_transfer)
}

int run_prt(PrtArgs& args) {
  auto scene = open_scene(args.scene);
  if (!scene) return fail_bad_input(scene.message());
  auto world = world::World::load(*scene, {.assets_dir = assets_dir(), .load_rigs = false});
  if (!world) return fail_bad_input(world.message());
  auto receivers = prt::static_receivers(**world, args.spacing_m, args.ground_margin_m);
  if (!receivers) return fail_bad_input(receivers.message());
  args.transfer.order = args.order > 0 ? args.order : scene->render.sh_order;
  std::size_t vertices = 0, triangles = 0;
  for (const prt::StaticSurface& s : receivers->surfaces) {
    vertices += s.positions.size();
    triangles += s.indices.size() / 3;
  }
  if (receivers->surfaces.empty()) {
    if (!quiet()) std::printf("no static meshes: nothing to precompute\n");
    return kExitOk;
  }
  const std::filesystem::path dir = cache_dir(args, *scene);
  if (!writable_folder(dir)) return fail_runtime(dir.string() + ": cannot create or write the PRT cache folder");
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  std::string last_stage;
  const prt::Progress progress = [&](std::string_view stage, std::size_t done, std::size_t total) {
    if (quiet()) return;
    if (terminal) {
      std::fprintf(stderr, "\rprt %.*s: %zu / %zu vertices", int(stage.size()), stage.data(), done, total);
      if (done == total) std::fprintf(stderr, "\n");
    } else if (done == total) {
      std::fprintf(stderr, "prt %.*s: %zu vertices done\n", int(stage.size()), stage.data(), total);
    }
  };
  auto result = prt::load_or_compute_transfer(*receivers, args.transfer, dir, progress, args.threads);
  if (!result) return fail_bad_input(result.message());
  const prt::TransferSet& t = result->transfer;
  // The static meshes' visibility grid the frame shades characters with (as load_static_field).
  prt::VisibilityGridSettings grid_settings;
  grid_settings.spacing_m = args.grid_spacing_m;
  grid_settings.margin_m = args.ground_margin_m;
  grid_settings.directions = args.transfer.directions;
  auto grid = prt::load_or_compute_visibility_grid(*receivers, t.order, grid_settings, dir, args.threads);
  if (!grid) return fail_bad_input(grid.message());
  const prt::VisibilityGrid& g = grid->grid;
  if (args.json) {
    nlohmann::json out = {{"surfaces", receivers->surfaces.size()},
                          {"vertices", vertices},
                          {"triangles", triangles},
                          {"spacing_m", args.spacing_m},
                          {"order", t.order},
                          {"directions", args.transfer.directions},
                          {"bounces", args.transfer.bounces},
                          {"from_cache", result->from_cache},
                          {"cache_file", result->file.string()},
                          {"bytes", t.bytes()}};
    if (!result->from_cache) out.update({{"rays", t.rays}, {"seconds", t.seconds}});
    nlohmann::json grid_json = {{"spacing_m", g.spacing}, {"points", g.points()}, {"size", {g.size.x, g.size.y, g.size.z}},
                                {"from_cache", grid->from_cache}, {"cache_file", grid->file.string()},
                                {"bytes", g.bytes()}};
    if (!grid->from_cache) grid_json.update({{"rays", g.rays}, {"seconds", g.seconds}});
    out["visibility_grid"] = grid_json;
    std::printf("%s\n", out.dump(2).c_str());
  } else if (!quiet()) {
    std::printf(
        "prt: %zu surfaces, %zu vertices, %zu triangles (spacing %.3g m), order %d, %d directions, %d bounces\n",
        receivers->surfaces.size(), vertices, triangles, double(args.spacing_m), t.order, args.transfer.directions,
        args.transfer.bounces);
    if (result->from_cache)
      std::printf("read %s (%.2f MiB)\n", result->file.c_str(), double(t.bytes()) / 1048576.0);
    else
      std::printf("computed %.1f Mrays in %.2f s (%.2f Mrays/s), %.2f MiB, wrote %s\n", double(t.rays) / 1e6, t.seconds,
                  double(t.rays) / 1e6 / t.seconds, double(t.bytes()) / 1048576.0, result->file.c_str());
    std::printf("visibility grid: %u×%u×%u points (spacing %.3g m), ", g.size.x, g.size.y, g.size.z, double(g.spacing));
    if (grid->from_cache)
      std::printf("read %s (%.2f MiB)\n", grid->file.c_str(), double(g.bytes()) / 1048576.0);
    else
      std::printf("computed %.1f Mrays in %.2f s, %.2f MiB, wrote %s\n", double(g.rays) / 1e6, g.seconds,
                  double(g.bytes()) / 1048576.0, grid->file.c_str());
  }
  return kExitOk;
}

}  // namespace

void add_prt_command(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<PrtArgs>();
  CLI::App* command = app.add_subcommand("prt", "Precompute PRT transfer of the scene's static meshes (cached)");
  add_scene_options(*command, args->scene, false);
  command->add_option("--cache", args->cache,
                      "Cache folder (default: prt-cache/ next to the scene, else the user cache)");
  command->add_option("--spacing", args->spacing_m, "Largest edge of the subdivided receivers, m (default 0.1)")
      ->check(CLI::Range(0.005f, 10.0f));
  command
      ->add_option("--ground-margin", args->ground_margin_m,
                   "Ground patch margin around the static meshes, m (default 2)")
      ->check(CLI::Range(0.0f, 100.0f));
  command->add_option("--grid-spacing", args->grid_spacing_m,
                      "Spacing of the static meshes' visibility grid that shadows characters, m (default 0.2)")
      ->check(CLI::Range(0.02f, 10.0f));
  command->add_option("--directions", args->transfer.directions,
                      "Directions per vertex and pass, and per visibility grid point (default 1024)")
      ->check(CLI::Range(prt::kMinDirections, prt::kMaxDirections));
  command->add_option("--bounces", args->transfer.bounces, "Interreflection passes (default 2)")
      ->check(CLI::Range(0, prt::kMaxBounces));
  command->add_option("--order", args->order, "SH order (default: the scene's render.sh_order)")
      ->check(CLI::Range(settings::kMinShOrder, settings::kMaxShOrder));
  command->add_option("--threads", args->threads, "Worker threads (default: all)")->check(CLI::Range(0, 1024));
  command->add_flag("--json", args->json, "Print the summary as JSON on stdout");
  add_quiet_flag(*command);
  command->callback([args, &runner] { runner = [args] { return run_prt(*args); }; });
}

}  // namespace proxygi::app
