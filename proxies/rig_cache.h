#pragma once
// The one way a rig is obtained for a model: reuse the cached *.proxies.json while it belongs to
// the same model bytes and fit settings (hand edits survive), else fit, measure its quality,
// choose the better binding over every clip (proxies/binding_eval.h) and cache it atomically.
// Used by `proxygi fit` and by the renderer, so both produce identical rigs.
#include <filesystem>
#include <string>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/fit.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

struct RigRequest {
  std::filesystem::path rig_file;  // where the rig is cached
  std::string model_name;          // written as the rig's "model"
  std::string model_hash;          // content hash of the model (rig_file.h content_hash)
  FitOptions options;              // tolerance and max_spheres decide whether a cache matches
  bool force = false;              // refit even when the cache matches
  bool write_cache = true;         // write a fresh fit to rig_file
};

struct ObtainedRig {
  ProxyRig rig;
  bool cache_hit = false;
};

// Errors: an unreadable or invalid cached rig (never overwritten: fix it or force), a failed
// fit, or a failed cache write.
Result<ObtainedRig> load_or_fit_rig(const anim::Character& character, const RigRequest& request);

}  // namespace proxygi::proxies
