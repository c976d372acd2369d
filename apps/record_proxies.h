#pragma once
// The proxy spheres of a scene at a frame, for the --aov proxies overlay. SceneRenderer keeps
// its per-frame spheres private, so this recomputes them the same way: the same model files,
// the rig the renderer cached next to each model (create it after the renderer), clip pose at
// the character's clip time with its world matrix, then proxies::TrackProxiesJob.
#include <filesystem>
#include <memory>
#include <vector>

#include "base/result.h"
#include "render/shading.h"
#include "scene/scene.h"

namespace proxygi::app {

class SceneProxies {
 public:
  static Result<std::unique_ptr<SceneProxies>> create(const scene::Scene& scene,
                                                      const std::filesystem::path& assets_dir);
  ~SceneProxies();

  // Every character's spheres at frame `frame` (scene time frame / fps), world space.
  Result<std::vector<render::Sphere>> spheres(int frame);

 private:
  struct Character;
  SceneProxies() = default;
  scene::Scene scene_;
  std::vector<std::unique_ptr<Character>> characters_;
};

}  // namespace proxygi::app
