#include "proxies/rig_cache.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "proxies/binding_eval.h"
#include "proxies/quality.h"
#include "proxies/rig_file.h"

namespace proxygi::proxies {
namespace {

bool settings_match(const ProxyRig& rig, const RigRequest& request) {
  return rig.model_hash == request.model_hash && rig.tolerance == request.options.tolerance &&
         rig.max_spheres == request.options.max_spheres && rig.fit_version == kFitVersion;
}

Result<ProxyRig> fit_rig(const anim::Character& character, const RigRequest& request) {
  FitResult fit;
  FitProxiesJob job;
  job.character = &character;
  job.options = request.options;
  job.result = &fit;
  if (Status fitted = job.run(); !fitted) return fitted.error();
  ProxyRig& rig = fit.rig;
  rig.model = request.model_name;
  rig.model_hash = request.model_hash;

  rig.quality = measure_fit_quality(character, fit);
  rig.has_quality = true;
  Result<BindingEvaluation> tracking = evaluate_bindings(character, fit);
  if (!tracking) return tracking.error();
  rig.frames_evaluated = tracking->frames;
  rig.rigid_error = tracking->rigid;
  rig.blended_error = tracking->blended;
  rig.binding = tracking->better;
  return std::move(rig);
}

}  // namespace

std::filesystem::path user_cache_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "proxygi";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "proxygi";
  return {};
}

std::filesystem::path user_cache_file(const std::filesystem::path& dir, const std::string& model_hash,
                                      const FitOptions& options) {
  std::string key = model_hash;
  if (const auto colon = key.find(':'); colon != std::string::npos) key = key.substr(colon + 1);
  for (char& c : key)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  char settings[64];
  std::snprintf(settings, sizeof settings, "-t%.6g-s%d", double(options.tolerance), options.max_spheres);
  return dir / (key + settings + ".proxies.json");
}

Result<ObtainedRig> load_or_fit_rig(const anim::Character& character, const RigRequest& request) {
  ObtainedRig out;
  std::error_code missing;
  const std::filesystem::path fallback_dir = request.fallback_dir.empty() ? user_cache_dir() : request.fallback_dir;
  const std::filesystem::path fallback =
      request.user_file || !request.fallback || fallback_dir.empty() ? std::filesystem::path() : user_cache_file(fallback_dir, request.model_hash, request.options);
  bool keep_user_file = false;  // the user's file exists and must not be overwritten

  if (request.user_file && std::filesystem::exists(request.rig_file, missing)) {
    Result<ProxyRig> named = read_rig(request.rig_file, character);
    if (!named) return named.error();
    if (!request.force && (named->model_hash.empty() || named->model_hash == request.model_hash)) {
      out.rig = std::move(*named);
      out.cache_hit = true;
      out.file = request.rig_file;
      return out;
    }
    keep_user_file = !request.force;
    if (keep_user_file)
      out.warnings.push_back(request.rig_file.string() + " was fitted to other model bytes (" + named->model_hash +
                             ", the model is " + request.model_hash +
                             "); refitted in memory and left the file as it is (--refit rewrites it)");
  } else if (!request.user_file && !request.force) {
    for (const std::filesystem::path& candidate : {request.rig_file, fallback}) {
      if (candidate.empty() || !std::filesystem::exists(candidate, missing)) continue;
      Result<ProxyRig> cached = read_rig(candidate, character);
      if (!cached) {
        out.warnings.push_back("cached rig " + cached.message() + "; refitted (fix or delete the file, or pass --force to replace it)");
        if (candidate == request.rig_file) keep_user_file = true;
        continue;
      }
      if (settings_match(*cached, request)) {
        out.rig = std::move(*cached);
        out.cache_hit = true;
        out.file = candidate;
        return out;
      }
    }
  }

  Result<ProxyRig> rig = fit_rig(character, request);
  if (!rig) return rig.error();
  out.rig = std::move(*rig);
  if (!request.write_cache) return out;
  if (!keep_user_file) {
    const Status written = write_rig(request.rig_file, out.rig, character);
    if (written) {
      out.file = request.rig_file;
      return out;
    }
    if (request.user_file || fallback.empty()) {
      out.write_error = written.message();
      return out;
    }
    std::error_code error;
    std::filesystem::create_directories(fallback.parent_path(), error);
    if (Status cached = write_rig(fallback, out.rig, character); !cached) {
      out.write_error = written.message() + "; and the user cache: " + cached.message();
      return out;
    }
    out.file = fallback;
    out.warnings.push_back("cannot write " + request.rig_file.string() + " (" + written.message() + "); cached the rig in " +
                           fallback.string());
    return out;
  }
  return out;
}

}  // namespace proxygi::proxies
