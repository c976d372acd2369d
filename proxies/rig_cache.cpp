#include "proxies/rig_cache.h"

#include <vector>

#include "proxies/binding_eval.h"
#include "proxies/quality.h"
#include "proxies/rig_file.h"

namespace proxygi::proxies {

Result<ObtainedRig> load_or_fit_rig(const anim::Character& character, const RigRequest& request) {
  std::error_code missing;
  if (!request.force && std::filesystem::exists(request.rig_file, missing)) {
    Result<ProxyRig> cached = read_rig(request.rig_file, character);
    if (!cached) return cached.error();
    if (cached->model_hash == request.model_hash && cached->tolerance == request.options.tolerance &&
        cached->max_spheres == request.options.max_spheres)
      return ObtainedRig{std::move(*cached), true};
  }

  FitResult fit;
  FitProxiesJob job;
  job.character = &character;
  job.options = request.options;
  job.result = &fit;
  if (Status fitted = job.run(); !fitted) return fitted.error();
  ProxyRig& rig = fit.rig;
  rig.model = request.model_name;
  rig.model_hash = request.model_hash;

  std::vector<glm::vec4> spheres;
  for (const FittedSphere& sphere : fit.fitted) spheres.emplace_back(sphere.center, sphere.radius);
  rig.quality = measure_quality(character, fit.surface, spheres, fit.tolerance_m);
  rig.has_quality = true;
  Result<BindingEvaluation> tracking = evaluate_bindings(character, fit);
  if (!tracking) return tracking.error();
  rig.frames_evaluated = tracking->frames;
  rig.rigid_error = tracking->rigid;
  rig.blended_error = tracking->blended;
  rig.binding = tracking->better;

  if (request.write_cache)
    if (Status written = write_rig(request.rig_file, rig, character); !written) return written.error();
  return ObtainedRig{std::move(rig), false};
}

}  // namespace proxygi::proxies
