// anim/ micro benchmarks: clip sampling, local-to-model, skin matrices and CPU skinning of a
// 35k-vertex, 4-influence mesh (a densely tessellated mannequin). Items are joint samples,
// nodes or vertices per second (state.SetItemsProcessed). One core; run with
//   proxygi bench micro --filter '^anim/'
#include <benchmark/benchmark.h>

#include <vector>

#include "anim/local_to_model.h"
#include "anim/mannequin.h"
#include "anim/posed_character.h"
#include "anim/sampling.h"
#include "anim/skinning.h"

namespace proxygi::anim {
namespace {

// The dense mannequin with every primitive merged into one vertex stream (about 35k vertices).
struct DenseRig {
  Character character = build_mannequin(MannequinOptions{32, 180});
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  PoseBuffers pose;

  DenseRig() {
    for (const Primitive& p : character.meshes[0].primitives) {
      positions.insert(positions.end(), p.positions.begin(), p.positions.end());
      normals.insert(normals.end(), p.normals.begin(), p.normals.end());
      joints.insert(joints.end(), p.joints.begin(), p.joints.end());
      weights.insert(weights.end(), p.weights.begin(), p.weights.end());
    }
    // A mid-stride walk pose: every joint away from its bind pose.
    (void)evaluate_pose(character, 0, 0.3f, WrapMode::loop, pose);
  }
};

const DenseRig& dense_rig() {
  static const DenseRig rig;
  return rig;
}

void anim_sample_clip(benchmark::State& state) {
  const Character& character = dense_rig().character;
  const Clip& clip = character.clips[static_cast<std::size_t>(state.range(0))];
  std::vector<Transform> locals(character.nodes.size());
  SampleClipJob job;
  job.character = &character;
  job.clip = &clip;
  job.wrap = WrapMode::loop;
  job.locals = locals;
  float time = 0.0f;
  for (auto _ : state) {
    job.time = time;
    time += 1.0f / 60.0f;
    if (!job.run()) state.SkipWithError("sampling failed");
    benchmark::DoNotOptimize(locals.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(clip.channels.size()));
  state.SetLabel(clip.name + ", " + std::to_string(clip.channels.size()) + " channels");
}
BENCHMARK(anim_sample_clip)->Name("anim/sample_clip")->Arg(0)->Arg(2);

void anim_local_to_model(benchmark::State& state) {
  const DenseRig& rig = dense_rig();
  std::vector<glm::mat4> world(rig.character.nodes.size());
  LocalToModelJob job;
  job.character = &rig.character;
  job.locals = rig.pose.locals;
  job.world = world;
  for (auto _ : state) {
    if (!job.run()) state.SkipWithError("local_to_model failed");
    benchmark::DoNotOptimize(world.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.size()));
}
BENCHMARK(anim_local_to_model)->Name("anim/local_to_model");

// Arg: 0 = positions only, 1 = positions + normals with mat3(M) (fast path), 2 = positions +
// normals with blended inverse-transpose normal matrices.
void anim_skinning(benchmark::State& state) {
  const DenseRig& rig = dense_rig();
  const int mode = static_cast<int>(state.range(0));
  const auto kernel = static_cast<SkinningKernel>(state.range(1));
  if (!skinning_kernel_available(kernel)) return state.SkipWithError("kernel not available on this CPU");
  std::vector<glm::vec3> out_positions(rig.positions.size()), out_normals(rig.normals.size());
  SkinningJob job;
  job.kernel = kernel;
  job.influences_per_vertex = 4;
  job.skin_matrices = rig.pose.skin_matrices[0];
  if (mode == 2) job.normal_matrices = rig.pose.normal_matrices[0];
  job.joints = rig.joints;
  job.weights = rig.weights;
  job.positions = rig.positions;
  job.out_positions = out_positions;
  if (mode > 0) {
    job.normals = rig.normals;
    job.out_normals = out_normals;
  }
  for (auto _ : state) {
    if (!job.run()) state.SkipWithError("skinning failed");
    benchmark::DoNotOptimize(out_positions.data());
    benchmark::DoNotOptimize(out_normals.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rig.positions.size()));
  static const char* const kLabels[] = {"positions", "positions+normals (mat3 of M)",
                                        "positions+normals (inverse-transpose)"};
  static const char* const kKernels[] = {"automatic", "portable", "avx2+fma"};
  state.SetLabel(std::to_string(rig.positions.size()) + " vertices, 4 influences, " + kLabels[mode] + ", " +
                 kKernels[state.range(1)] + " kernel");
}
// Arguments: mode (0 positions, 1 + normals, 2 + normal matrices), kernel (SkinningKernel:
// 0 automatic, 1 portable, 2 AVX2 + FMA).
BENCHMARK(anim_skinning)->Name("anim/skinning")->ArgsProduct({{0, 1, 2}, {0, 1, 2}});

// One whole frame on the CPU: sample, local-to-model, skin matrices, skin every primitive.
void anim_pose_frame(benchmark::State& state) {
  const DenseRig& rig = dense_rig();
  PoseBuffers pose;
  std::vector<glm::vec3> out_positions(rig.positions.size()), out_normals(rig.normals.size());
  float time = 0.0f;
  for (auto _ : state) {
    if (!evaluate_pose(rig.character, 0, time, WrapMode::loop, pose)) state.SkipWithError("pose failed");
    time += 1.0f / 60.0f;
    SkinningJob job;
    job.influences_per_vertex = 4;
    job.skin_matrices = pose.skin_matrices[0];
    job.joints = rig.joints;
    job.weights = rig.weights;
    job.positions = rig.positions;
    job.normals = rig.normals;
    job.out_positions = out_positions;
    job.out_normals = out_normals;
    if (!job.run()) state.SkipWithError("skinning failed");
    benchmark::DoNotOptimize(out_positions.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rig.positions.size()));
}
BENCHMARK(anim_pose_frame)->Name("anim/pose_frame");

}  // namespace
}  // namespace proxygi::anim
