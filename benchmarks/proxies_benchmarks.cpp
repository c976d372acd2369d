// proxies/: fitting time per character, tracking throughput, and what culling and level of
// detail save in the default scene. Goals: fit CesiumMan in < 2 s; track >= 10 M spheres/s on
// one core.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/gltf_import.h"
#include "anim/mannequin.h"
#include "anim/posed_character.h"
#include "proxies/culling.h"
#include "proxies/fit.h"
#include "proxies/tracking.h"

#ifndef PROXYGI_SHARED_ASSETS_DIR
#define PROXYGI_SHARED_ASSETS_DIR "../shared/assets"
#endif

namespace {

using namespace proxygi;

const anim::Character& mannequin() {
  static const anim::Character character = anim::build_mannequin();
  return character;
}

const proxies::FitResult& mannequin_fit() {
  static const proxies::FitResult fit = [] {
    proxies::FitResult result;
    proxies::FitProxiesJob job;
    job.character = &mannequin();
    job.result = &result;
    (void)job.run();
    return result;
  }();
  return fit;
}

void fit_character(benchmark::State& state, const anim::Character& character) {
  int spheres = 0;
  for (auto _ : state) {
    proxies::FitResult fit;
    proxies::FitProxiesJob job;
    job.character = &character;
    job.result = &fit;
    if (Status s = job.run(); !s) {
      state.SkipWithError(s.message().c_str());
      return;
    }
    spheres = int(fit.rig.spheres.size());
  }
  state.counters["spheres"] = spheres;
}

void proxies_fit_shared(benchmark::State& state, const char* name) {
  const std::filesystem::path path = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf" / name;
  Result<anim::Character> character = anim::import_gltf(path);
  if (!character) {
    state.SkipWithError(character.message().c_str());
    return;
  }
  fit_character(state, *character);
}
BENCHMARK_CAPTURE(proxies_fit_shared, CesiumMan, "CesiumMan.glb")->Name("proxies/fit/CesiumMan")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(proxies_fit_shared, Fox, "Fox.glb")->Name("proxies/fit/Fox")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(proxies_fit_shared, RiggedSimple, "RiggedSimple.glb")->Name("proxies/fit/RiggedSimple")->Unit(benchmark::kMillisecond)->Iterations(3);

void proxies_fit_mannequin(benchmark::State& state) { fit_character(state, mannequin()); }
BENCHMARK(proxies_fit_mannequin)->Name("proxies/fit/mannequin")->Unit(benchmark::kMillisecond)->Iterations(3);

// Tracking: the mannequin rig repeated 256 times (a crowd of one rig), walk pose.
void proxies_track(benchmark::State& state) {
  const proxies::Binding binding = state.range(0) == 0 ? proxies::Binding::rigid : proxies::Binding::blended;
  Result<proxies::TrackingRig> one = proxies::compile_tracking(mannequin_fit().rig, mannequin(), binding);
  if (!one) {
    state.SkipWithError(one.message().c_str());
    return;
  }
  proxies::TrackingRig rig = *one;
  for (int copy = 1; copy < 256; ++copy) rig.spheres.insert(rig.spheres.end(), one->spheres.begin(), one->spheres.end());
  anim::PoseBuffers pose;
  if (Status s = anim::evaluate_pose(mannequin(), 0, 0.3f, anim::WrapMode::loop, pose); !s) {
    state.SkipWithError(s.message().c_str());
    return;
  }
  std::vector<proxies::WorldSphere> out(rig.spheres.size());
  const proxies::TrackProxiesJob job{&rig, pose.world, out};
  for (auto _ : state) {
    (void)job.run();
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(out.size()));
}
BENCHMARK(proxies_track)->Name("proxies/track/rigid")->Arg(0);
BENCHMARK(proxies_track)->Name("proxies/track/blended")->Arg(1);

// Default scene: the mannequin walks along +X from x = -5 m to +5 m (a 10 m ground plane) at
// its walk speed; the camera stands `distance` m in front of the path's middle (+Z), eye height
// 1.2 m, looking at (0, 0.9, 0); 60° vertical field of view, 1280 × 720, eta = 15, LOD merge
// below 2 px. Counters: mean fraction of proxies culled and merged away per frame.
void proxies_scene(benchmark::State& state) {
  const float distance = float(state.range(0));
  const anim::Character& character = mannequin();
  Result<proxies::TrackingRig> rig = proxies::compile_tracking(mannequin_fit().rig, character, mannequin_fit().rig.binding);
  if (!rig) {
    state.SkipWithError(rig.message().c_str());
    return;
  }
  const std::vector<int> groups = proxies::chain_groups(mannequin_fit().rig, character);
  const glm::vec3 eye(0.0f, 1.2f, distance);
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f, 0.9f, 0.0f), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1280.0f / 720.0f, 0.1f, 1000.0f);
  const proxies::Frustum frustum = proxies::Frustum::from_view_projection(projection * view);
  const float focal = 720.0f / (2.0f * std::tan(glm::radians(30.0f)));
  const int frames = int(std::ceil(10.0f / anim::kWalkSpeed * 30.0f));
  std::vector<std::vector<proxies::WorldSphere>> tracked(std::size_t(frames), std::vector<proxies::WorldSphere>(rig->spheres.size()));
  anim::PoseBuffers pose;
  for (int f = 0; f < frames; ++f) {
    const float t = float(f) / 30.0f;
    const glm::mat4 root = glm::translate(glm::mat4(1.0f), glm::vec3(-5.0f + anim::kWalkSpeed * t, 0, 0)) *
                           glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
    (void)anim::evaluate_pose(character, 0, t, anim::WrapMode::loop, pose, root);
    (void)proxies::TrackProxiesJob{&*rig, pose.world, tracked[std::size_t(f)]}.run();
  }
  std::vector<std::uint32_t> kept(rig->spheres.size());
  std::vector<proxies::WorldSphere> merged(rig->spheres.size());
  double culled = 0.0, saved_by_lod = 0.0;
  for (auto _ : state) {
    culled = saved_by_lod = 0.0;
    for (const auto& spheres : tracked) {
      int kept_count = 0, merged_count = 0;
      (void)proxies::CullProxiesJob{spheres, frustum, 15.0f, kept, &kept_count}.run();
      (void)proxies::MergeSmallProxiesJob{spheres, groups, eye, focal, 2.0f, merged, &merged_count}.run();
      culled += double(spheres.size() - std::size_t(kept_count));
      saved_by_lod += double(spheres.size() - std::size_t(merged_count));
    }
  }
  const double total = double(frames) * double(rig->spheres.size());
  state.counters["proxies"] = double(rig->spheres.size());
  state.counters["frames"] = frames;
  state.counters["culled_fraction"] = culled / total;
  state.counters["lod_saved_fraction"] = saved_by_lod / total;
}
BENCHMARK(proxies_scene)->Name("proxies/scene/walk_10m")->Arg(4)->Arg(40)->Arg(400)->Unit(benchmark::kMicrosecond);

}  // namespace
