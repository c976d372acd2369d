#include "view/scene_loader.h"

#include <cstdio>

#include "view/scene_open.h"

namespace proxygi::view {
namespace {

Result<LoadedScene> load_world(const scene::Scene& scene, const std::string& name, const std::filesystem::path& assets,
                               bool rigs) {
  auto world = world::World::load(scene, {.assets_dir = assets, .load_rigs = rigs, .write_rig_cache = true});
  if (!world) return make_error(name + ": " + world.message());
  return LoadedScene{name, std::shared_ptr<const world::World>(std::move(*world)), false, !rigs};
}

}  // namespace

SceneLoader::~SceneLoader() {
  if (future_.valid()) future_.wait();  // a queued load is dropped
}

void SceneLoader::start(Work work, const std::string& name) {
  if (future_.valid()) {  // one load at a time: this one goes next
    queued_ = std::move(work);
    queued_name_ = name;
    return;
  }
  name_ = name;
  started_ = std::chrono::steady_clock::now();
  preview_ = std::make_shared<Preview>();
  future_ = std::async(std::launch::async, [work = std::move(work), preview = preview_] { return work(*preview); });
}

void SceneLoader::open(const std::string& name, const scene::Scene* current) {
  std::optional<scene::Scene> base;
  if (current) base = *current;
  start([name, base, assets = assets_dir_, gate = options_.rig_gate](Preview& preview) -> Result<LoadedScene> {
    auto scene = open_scene(name, base ? &*base : nullptr, assets);
    if (!scene) return make_error(name + ": " + scene.message());
    if (!scene->characters.empty()) {
      // The scene without rigs first (no fit, no cache read); a failure here fails the load.
      auto bare = load_world(*scene, name, assets, false);
      if (!bare) return bare;
      std::lock_guard lock(preview.mutex);
      preview.world = std::move(*bare);
      preview.ready = std::chrono::steady_clock::now();
    }
    if (gate.valid()) gate.wait();
    return load_world(*scene, name, assets, true);
  }, name);
}

void SceneLoader::load(scene::Scene scene, const std::string& name) {
  start([scene = std::move(scene), name, assets = assets_dir_](Preview&) -> Result<LoadedScene> {
    auto loaded = load_world(scene, name, assets, true);
    if (loaded) loaded->keep_state = true;
    return loaded;
  }, name);
}

std::string SceneLoader::progress() const {
  if (!future_.valid()) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  bool previewing = false;
  if (preview_) {
    std::lock_guard lock(preview_->mutex);
    previewing = preview_->offered;
  }
  char line[512];
  std::snprintf(line, sizeof line, previewing ? "loading %s ... %.1f s: fitting proxies (shown without them until ready)"
                                              : "loading %s ... %.1f s (proxies are fitted when no cached rig matches)",
                name_.c_str(), seconds);
  return line;
}

std::optional<Result<LoadedScene>> SceneLoader::poll() {
  if (!future_.valid()) return std::nullopt;
  if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    std::lock_guard lock(preview_->mutex);
    const double waited = preview_->world ? std::chrono::duration<double>(std::chrono::steady_clock::now() - preview_->ready).count() : 0.0;
    if (!preview_->world || preview_->offered || waited < options_.preview_after_s) return std::nullopt;
    preview_->offered = true;
    return Result<LoadedScene>(std::move(*preview_->world));
  }
  Result<LoadedScene> done = future_.get();
  {
    std::lock_guard lock(preview_->mutex);
    if (done && preview_->offered) done->keep_state = true;  // it replaces the preview shown
  }
  if (queued_) {
    start(std::move(queued_), queued_name_);
    queued_ = nullptr;
  }
  return done;
}

std::optional<Result<LoadedScene>> SceneLoader::wait() {
  if (!future_.valid()) return std::nullopt;
  future_.wait();
  return poll();
}

}  // namespace proxygi::view
