#pragma once
// The one way a rig is obtained for a model. Two kinds of rig file:
//  - a rig the user named (a scene's "proxies", `fit -o`): used as it is while it belongs to the
//    model's bytes (hash), whatever tolerance or sphere cap it was made with. When the model's
//    bytes changed it is refitted in memory with a warning and the file is left alone, unless
//    `force` (--refit / --force) allows rewriting it.
//  - the cache: MODEL.proxies.json next to the model, or, when that folder is not writable, the
//    user cache folder ($XDG_CACHE_HOME/proxygi, else ~/.cache/proxygi) keyed by the model hash
//    and the fit settings. Reused while it belongs to the same model bytes and fit settings (hand
//    edits survive); a cache that cannot be read is reported and refitted (the broken file is
//    kept for the user to fix or delete; `force` replaces it).
// A fresh fit measures its quality, chooses the better binding over every clip
// (proxies/binding_eval.h) and is written atomically. Used by `proxygi fit` and by the renderer,
// so both produce identical rigs.
#include <filesystem>
#include <string>
#include <vector>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/fit.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

struct RigRequest {
  std::filesystem::path rig_file;  // the user's rig, or where the rig is cached next to the model
  bool user_file = false;          // rig_file was named by the user (see above)
  std::string model_name;          // written as the rig's "model"
  std::string model_hash;          // content hash of the model (rig_file.h content_hash)
  FitOptions options;              // tolerance and max_spheres decide whether a cache matches
  bool force = false;              // refit even when the rig matches, and write it
  bool write_cache = true;         // write a fresh fit (never a user's existing file without force)
  // Where the cache goes when rig_file's folder is not writable; empty: user_cache_dir().
  std::filesystem::path fallback_dir;
  bool fallback = true;            // false: rig_file or nothing (`fit -o`)
};

struct ObtainedRig {
  ProxyRig rig;
  bool cache_hit = false;
  std::filesystem::path file;           // the file it came from or was written to (empty: in memory only)
  std::vector<std::string> warnings;    // for the user: refits kept in memory, broken caches, fallbacks
  std::string write_error;              // set when a fresh fit could be written nowhere (rig still valid)
};

// $XDG_CACHE_HOME/proxygi, else $HOME/.cache/proxygi; empty when neither variable is set.
std::filesystem::path user_cache_dir();
// The user-cache file of a model hash and fit settings: DIR/<hash hex>-t<tolerance>-s<max>.proxies.json.
std::filesystem::path user_cache_file(const std::filesystem::path& dir, const std::string& model_hash,
                                      const FitOptions& options);

// Errors: an unreadable or invalid user rig, or a failed fit. A rig that could be written nowhere
// (next to the model nor in the user cache folder) is returned with write_error set.
Result<ObtainedRig> load_or_fit_rig(const anim::Character& character, const RigRequest& request);

}  // namespace proxygi::proxies
