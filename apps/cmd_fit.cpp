// proxygi fit MODEL [-o FILE.proxies.json] [--tolerance T] [--max-spheres N] [--json] [--force]
// Fits sphere proxies per bone (or reuses MODEL.proxies.json while the model's content hash,
// tolerance and sphere cap match), measures their quality, picks the better binding over every
// frame of every clip, and writes the rig atomically.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "anim/gltf_import.h"
#include "anim/mannequin.h"
#include "apps/commands.h"
#include "settings/limits.h"
#include "apps/model_input.h"
#include "proxies/fit.h"
#include "proxies/rig_cache.h"
#include "proxies/rig_file.h"

namespace proxygi::app {
namespace {

struct FitArgs {
  std::string model;
  std::string output;
  float tolerance = proxies::FitOptions{}.tolerance;
  int max_spheres = proxies::FitOptions{}.max_spheres;
  bool json = false;
  bool force = false;
  // Study options (need -o: a cache is keyed by tolerance and cap only).
  proxies::FitOptions study;
  bool studied = false;
};

nlohmann::json report_json(const proxies::ProxyRig& rig, const std::string& model, const std::string& rig_path, bool cached) {
  const proxies::RigSummary summary = proxies::summarize_rig(rig);
  nlohmann::json bones = nlohmann::json::object();
  for (const auto& [bone, count] : summary.spheres_per_bone) bones[bone] = count;
  return {{"model", model},
          {"rig", rig_path},
          {"cache", cached ? "hit" : "miss"},
          {"model_hash", rig.model_hash},
          {"sphere_count", summary.sphere_count},
          {"tolerance", rig.tolerance},
          {"tolerance_m", rig.tolerance * rig.diagonal},
          {"diagonal_m", rig.diagonal},
          {"max_spheres", rig.max_spheres},
          {"fit_seconds", rig.fit_seconds},
          {"coverage", rig.quality.coverage},
          {"outside_volume_ratio", rig.quality.outside_volume_ratio},
          {"hausdorff_surface_to_spheres_m", rig.quality.hausdorff_surface_to_spheres},
          {"hausdorff_spheres_to_surface_m", rig.quality.hausdorff_spheres_to_surface},
          {"mean_surface_to_spheres_m", rig.quality.mean_surface_to_spheres},
          {"binding", proxies::binding_name(rig.binding)},
          {"tracking",
           {{"frames", rig.frames_evaluated},
            {"rigid_worst_poke_out_m", rig.rigid_error.worst_poke_out},
            {"rigid_mean_poke_out_m", rig.rigid_error.mean_poke_out},
            {"blended_worst_poke_out_m", rig.blended_error.worst_poke_out},
            {"blended_mean_poke_out_m", rig.blended_error.mean_poke_out}}},
          {"warnings", rig.warnings},
          {"spheres_per_bone", bones}};
}

void print_text(const proxies::ProxyRig& rig, const std::string& rig_path, bool cached) {
  std::printf("%s %s\n", cached ? "reused" : "wrote", rig_path.c_str());
  std::printf("%s", proxies::format_rig_summary(rig).c_str());
  std::printf("  tracking over %d frames: worst poke-out rigid %.4g m, blended %.4g m (mean %.4g / %.4g m)\n",
              rig.frames_evaluated, double(rig.rigid_error.worst_poke_out), double(rig.blended_error.worst_poke_out),
              double(rig.rigid_error.mean_poke_out), double(rig.blended_error.mean_poke_out));
  std::printf("  fit time %.3f s\n", rig.fit_seconds);
  for (const std::string& w : rig.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

int run_fit(const FitArgs& args) {
  if (!args.output.empty() && !args.output.ends_with(".json"))
    return fail_bad_input("-o '" + args.output + "': a rig is written as JSON; name it *.proxies.json");
  if (args.studied && args.output.empty())
    return fail_bad_input("--surface-slack, --outside-target and --teleport-* change the fit, so they need -o FILE.proxies.json");
  Result<ModelInput> model = open_model(args.model);
  if (!model) return fail_bad_input(model.message());
  const anim::Character& character = model->character;
  for (const std::string& warning : proxies::node_name_warnings(character)) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  const int bones = [&] {
    std::vector<char> bone(character.nodes.size(), 0);
    for (const anim::Skin& skin : character.skins)
      for (int joint : skin.joints) bone[std::size_t(joint)] = 1;
    return int(std::count(bone.begin(), bone.end(), 1));
  }();

  proxies::RigRequest request;
  request.rig_file = args.output.empty() ? model->rig_file : std::filesystem::path(args.output);
  request.fallback = args.output.empty();  // -o FILE: that file or nothing
  request.model_name = model->mannequin ? "mannequin.glb" : model->file.filename().string();
  request.model_hash = model->hash;
  request.options = args.study;
  request.options.tolerance = args.tolerance;
  request.options.max_spheres = args.max_spheres;
  request.force = args.force || args.studied;
  Result<proxies::ObtainedRig> obtained = proxies::load_or_fit_rig(character, request);
  if (!obtained) return fail_bad_input(obtained.message() + " (fix the file or pass --force to refit)");
  for (const std::string& warning : obtained->warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  if (!obtained->write_error.empty()) return fail_runtime(obtained->write_error);
  const proxies::ProxyRig& rig = obtained->rig;
  const std::string where = obtained->file.empty() ? "(not written)" : obtained->file.string();
  if (args.max_spheres < bones && !obtained->cache_hit)
    std::fprintf(stderr,
                 "fit: --max-spheres %d is below one sphere per bone (%d bones with skin weight); fitted %zu spheres, one "
                 "per bone that owns vertices, and skipped the rest of the cap\n",
                 args.max_spheres, bones, rig.spheres.size());
  if (args.json) std::printf("%s\n", report_json(rig, args.model, where, obtained->cache_hit).dump(2).c_str());
  else print_text(rig, where, obtained->cache_hit);
  return kExitOk;
}

}  // namespace

void add_fit_command(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<FitArgs>();
  auto* command = app.add_subcommand("fit", "Fit sphere proxies to each bone of a model");
  command->add_option("model", args->model, "glTF/GLB file, or 'mannequin' / 'builtin:mannequin' for the built-in character")->required();
  command->add_option("-o,--output", args->output, "rig file (default: MODEL.proxies.json next to the model, or in $XDG_CACHE_HOME/proxygi when that folder is not writable)");
  command->add_option("--tolerance", args->tolerance, "allowed protrusion, relative to the bounding-box diagonal, in [0.0001, 1]")
      ->check(CLI::Range(0.0001f, 1.0f));
  command->add_option("--max-spheres", args->max_spheres, "cap on the sphere count, at most 4096 (settings/limits.h)")
      ->check(CLI::Range(1, settings::kMaxProxySpheres));
  const proxies::FitOptions defaults;
  auto study = [&](CLI::Option* option) { option->each([args](const std::string&) { args->studied = true; }); };
  study(command->add_option("--surface-slack", args->study.surface_slack, "study: how far a point may lie outside its sphere, x tolerance, in [0, 0.99] (default " + std::to_string(defaults.surface_slack) + "; needs -o)")
            ->check(CLI::Range(0.0f, 0.99f)));
  study(command->add_option("--outside-target", args->study.outside_target, "study: split while the outside volume share exceeds it, in [0, 1] (1: no outside-volume splits; needs -o)")
            ->check(CLI::Range(0.0f, 1.0f)));
  study(command->add_option("--teleport-rounds", args->study.teleport_rounds, "study: cap on teleport moves, 0: none (needs -o)")
            ->check(CLI::Range(0, 4096)));
  study(command->add_option("--teleport-candidates", args->study.teleport_candidates, "study: splits tried per teleport move (needs -o)")
            ->check(CLI::Range(1, 64)));
  study(command->add_option("--teleport-worsening", args->study.teleport_worsening, "study: worsening teleport moves allowed in a row (needs -o)")
            ->check(CLI::Range(0, 64)));
  command->add_flag("--json", args->json, "print the report as JSON on stdout");
  command->add_flag("--force", args->force, "refit even when the cached rig matches");
  add_quiet_flag(*command);
  command->callback([&runner, args] { runner = [args] { return run_fit(*args); }; });
}

}  // namespace proxygi::app
