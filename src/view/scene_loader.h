#pragma once
// Opens scenes on a worker thread so the window stays responsive: open_scene (scene_open.h),
// then world::World::load (model import, proxy rigs from their cache or a fresh fit). The GPU
// side (SceneRenderer, uploads) is made on the loop's thread once poll() hands the world over.
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "base/result.h"
#include "scene/scene.h"
#include "world/world.h"

namespace proxygi::view {

struct LoadedScene {
  std::string name;  // what was opened (for the title)
  std::shared_ptr<const world::World> world;
  bool keep_state = false;  // an edit of the shown scene: keep playback, camera and settings
};

class SceneLoader {
 public:
  explicit SceneLoader(std::filesystem::path assets_dir) : assets_dir_(std::move(assets_dir)) {}
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
  // The finished load, once (nothing while it runs or when idle).
  std::optional<Result<LoadedScene>> poll();
  // Waits for the load in progress.
  std::optional<Result<LoadedScene>> wait();

 private:
  void start(std::function<Result<LoadedScene>()> work, const std::string& name);
  std::filesystem::path assets_dir_;
  std::future<Result<LoadedScene>> future_;
  std::function<Result<LoadedScene>()> queued_;
  std::string queued_name_;
  std::string name_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace proxygi::view
