#include "proxies/binding_eval.h"

#include <algorithm>
#include <cmath>

#include "anim/posed_character.h"
#include "proxies/tracking.h"

namespace proxygi::proxies {
namespace {

struct Accumulator {
  double sum = 0.0;
  long count = 0;
  float worst = 0.0f;
  BindingError result() const { return {worst, count > 0 ? float(sum / double(count)) : 0.0f}; }
};

}  // namespace

Result<BindingEvaluation> evaluate_bindings(const anim::Character& character, const FitResult& fit, float fps) {
  Result<TrackingRig> rigid = compile_tracking(fit.rig, character, Binding::rigid);
  if (!rigid) return rigid.error();
  Result<TrackingRig> blended = compile_tracking(fit.rig, character, Binding::blended);
  if (!blended) return blended.error();

  // (clip, time) of every frame.
  std::vector<std::pair<int, float>> frames;
  for (std::size_t c = 0; c < character.clips.size(); ++c) {
    const float duration = std::max(character.clips[c].duration, 0.0f);
    const int last = int(std::ceil(duration * fps));
    for (int k = 0; k <= last; ++k) frames.emplace_back(int(c), std::min(float(k) / fps, duration));
  }
  if (frames.empty()) frames.emplace_back(-1, 0.0f);

  const BindSurface& surface = fit.surface;
  anim::PoseBuffers pose;
  std::vector<glm::mat4> skin(character.nodes.size());
  std::vector<glm::vec3> skinned(surface.soup.positions.size());
  std::vector<WorldSphere> spheres_rigid(fit.rig.spheres.size()), spheres_blended(fit.rig.spheres.size());
  Accumulator acc_rigid, acc_blended;
  for (const auto& [clip, time] : frames) {
    if (Status s = anim::evaluate_pose(character, clip, time, anim::WrapMode::clamp, pose); !s) return s.error();
    for (std::size_t n = 0; n < skin.size(); ++n) skin[n] = pose.world[n] * surface.bind_to_bone[n];
    for (std::size_t v = 0; v < skinned.size(); ++v) {
      const Influences& inf = surface.influences[v];
      glm::vec3 p(0.0f);
      for (int k = 0; k < kMaxInfluences && inf.nodes[std::size_t(k)] >= 0; ++k)
        p += inf.weights[std::size_t(k)] * glm::vec3(skin[std::size_t(inf.nodes[std::size_t(k)])] * glm::vec4(surface.soup.positions[v], 1.0f));
      skinned[v] = p;
    }
    if (Status s = TrackProxiesJob{&*rigid, pose.world, spheres_rigid}.run(); !s) return s.error();
    if (Status s = TrackProxiesJob{&*blended, pose.world, spheres_blended}.run(); !s) return s.error();
    for (std::size_t i = 0; i < fit.fitted.size(); ++i) {
      float poke_rigid = 0.0f, poke_blended = 0.0f;
      for (std::uint32_t si : fit.fitted[i].samples) {
        const SurfaceSample& s = fit.samples[si];
        const glm::uvec3& tri = surface.soup.triangles[s.triangle];
        const glm::vec3 p = s.barycentric.x * skinned[tri.x] + s.barycentric.y * skinned[tri.y] + s.barycentric.z * skinned[tri.z];
        poke_rigid = std::max(poke_rigid, glm::length(p - spheres_rigid[i].center) - spheres_rigid[i].radius);
        poke_blended = std::max(poke_blended, glm::length(p - spheres_blended[i].center) - spheres_blended[i].radius);
      }
      acc_rigid.sum += poke_rigid, ++acc_rigid.count, acc_rigid.worst = std::max(acc_rigid.worst, poke_rigid);
      acc_blended.sum += poke_blended, ++acc_blended.count, acc_blended.worst = std::max(acc_blended.worst, poke_blended);
    }
  }
  BindingEvaluation out;
  out.rigid = acc_rigid.result();
  out.blended = acc_blended.result();
  out.frames = int(frames.size());
  out.better = out.blended.worst_poke_out < out.rigid.worst_poke_out ? Binding::blended : Binding::rigid;
  return out;
}

}  // namespace proxygi::proxies
