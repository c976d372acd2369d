#pragma once
// Opens scenes on a worker thread so the window stays responsive: open_scene (scene_open.h),
// then world::World::load (model import, proxy rigs from their cache or a fresh fit). The GPU
// side (SceneRenderer, uploads) is made on the loop's thread once poll() hands the world over.
//
// A fit takes seconds, so an open loads in two steps: first the world without rigs (the scene
// unshadowed, no proxies), offered by poll() as a preview once it has waited preview_after_s for
// the second step; then the world with its rigs (fitted or cached), which replaces the preview
// keeping playback, camera and settings. A cached rig loads quickly enough that no preview shows.
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "base/result.h"
#include "scene/scene.h"
#include "world/world.h"

namespace proxygi::view {

struct LoadedScene {
  std::string name;  // what was opened (for the title)
  std::shared_ptr<const world::World> world;
  bool keep_state = false;  // an edit of the shown scene, or the rigs after a preview: keep playback, camera, settings
  bool preview = false;     // the world without rigs while they are fitted (no proxies)
};

struct LoaderOptions {
  double preview_after_s = 0.3;  // how long a ready preview waits for the rigs before poll() offers it
  // Tests: the second step (rigs) starts only once this is ready (a slow fit on demand).
  std::shared_future<void> rig_gate;
};

class SceneLoader {
 public:
  explicit SceneLoader(std::filesystem::path assets_dir, LoaderOptions options = {})
      : assets_dir_(std::move(assets_dir)), options_(std::move(options)) {}
  ~SceneLoader();

  // Starts opening `name`; `current` is the scene an environment file applies to. While a load
  // runs, a new request is queued (the latest replaces an older queued one) and starts when the
  // running one ends, so the caller never waits.
  void open(const std::string& name, const scene::Scene* current);
  // Starts loading an edited scene (clips, environment changed in the UI); keep_state is set.
  void load(scene::Scene scene, const std::string& name);

  bool busy() const { return future_.valid(); }
  // "loading walk.glb… 1.2 s" while busy, empty otherwise.
  std::string progress() const;
  // The finished load, once (nothing while it runs or when idle); or, while the rigs load, the
  // preview once (see above).
  std::optional<Result<LoadedScene>> poll();
  // Waits for the load in progress (its rigs included; no preview).
  std::optional<Result<LoadedScene>> wait();

  // Shared between a load's worker and poll(): the preview when the first step is done.
  struct Preview {
    std::mutex mutex;
    std::optional<LoadedScene> world;
    std::chrono::steady_clock::time_point ready;
    bool offered = false;
  };

 private:
  using Work = std::function<Result<LoadedScene>(Preview&)>;
  void start(Work work, const std::string& name);
  std::filesystem::path assets_dir_;
  LoaderOptions options_;
  std::future<Result<LoadedScene>> future_;
  std::shared_ptr<Preview> preview_;
  Work queued_;
  std::string queued_name_;
  std::string name_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace proxygi::view
