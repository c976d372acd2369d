#include "view/scene_loader.h"

#include <cstdio>

#include "view/scene_open.h"

namespace proxygi::view {
namespace {

Result<LoadedScene> load_world(const scene::Scene& scene, const std::string& name, const std::filesystem::path& assets) {
  auto world = world::World::load(scene, {.assets_dir = assets, .load_rigs = true, .write_rig_cache = true});
  if (!world) return make_error(name + ": " + world.message());
  return LoadedScene{name, std::shared_ptr<const world::World>(std::move(*world))};
}

}  // namespace

SceneLoader::~SceneLoader() {
  if (future_.valid()) future_.wait();  // a queued load is dropped
}

void SceneLoader::start(std::function<Result<LoadedScene>()> work, const std::string& name) {
  if (future_.valid()) {  // one load at a time: this one goes next
    queued_ = std::move(work);
    queued_name_ = name;
    return;
  }
  name_ = name;
  started_ = std::chrono::steady_clock::now();
  future_ = std::async(std::launch::async, std::move(work));
}

void SceneLoader::open(const std::string& name, const scene::Scene* current) {
  std::optional<scene::Scene> base;
  if (current) base = *current;
  start([name, base, assets = assets_dir_]() -> Result<LoadedScene> {
    auto scene = open_scene(name, base ? &*base : nullptr);
    if (!scene) return make_error(name + ": " + scene.message());
    return load_world(*scene, name, assets);
  }, name);
}

void SceneLoader::load(scene::Scene scene, const std::string& name) {
  start([scene = std::move(scene), name, assets = assets_dir_]() -> Result<LoadedScene> {
    auto loaded = load_world(scene, name, assets);
    if (loaded) loaded->keep_state = true;
    return loaded;
  }, name);
}

std::string SceneLoader::progress() const {
  if (!future_.valid()) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  char line[512];
  std::snprintf(line, sizeof line, "loading %s ... %.1f s (proxies are fitted when no cached rig matches)",
                name_.c_str(), seconds);
  return line;
}

std::optional<Result<LoadedScene>> SceneLoader::poll() {
  if (!future_.valid() || future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
  Result<LoadedScene> done = future_.get();
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
