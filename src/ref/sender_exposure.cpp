#include "ref/sender_exposure.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "anim/sampling.h"
#include "ref/embree_scene.h"
#include "ref/sampling.h"

namespace proxygi::ref {

Status SenderExposureJob::validate() const {
  if (directions < kMinSenderExposureDirections || directions > kMaxSenderExposureDirections)
    return make_error("sender exposure: " + std::to_string(directions) + " directions, must be in " +
                      std::to_string(kMinSenderExposureDirections) + ".." + std::to_string(kMaxSenderExposureDirections));
  if (exposure == nullptr) return make_error("sender exposure: no output");
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const anim::PosedPrimitive& p = primitives[i];
    const std::string where = "sender exposure: primitive " + std::to_string(i) + " (" + p.name + ")";
    if (!p.normals.empty() && p.normals.size() != p.positions.size())
      return make_error(where + ": " + std::to_string(p.normals.size()) + " normals for " +
                        std::to_string(p.positions.size()) + " positions");
    if (p.indices.size() % 3 != 0) return make_error(where + ": index count is not a multiple of 3");
    for (std::size_t k = 0; k < p.indices.size(); ++k)
      if (p.indices[k] >= p.positions.size())
        return make_error(where + ": index " + std::to_string(k) + " out of range (" + std::to_string(p.positions.size()) +
                          " vertices)");
    for (std::size_t v = 0; v < p.positions.size(); ++v)
      if (!std::isfinite(p.positions[v].x + p.positions[v].y + p.positions[v].z))
        return make_error(where + ": position " + std::to_string(v) + " is not finite");
  }
  return {};
}

Status SenderExposureJob::run() const {
  if (Status s = validate(); !s) return s;
  std::vector<TriangleMesh> meshes;
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (const anim::PosedPrimitive& p : primitives) {
    TriangleMesh mesh;
    mesh.name = p.name;
    mesh.positions = p.positions;
    mesh.indices = p.indices;
    mesh.character = true;
    for (const glm::vec3& x : p.positions) low = glm::min(low, x), high = glm::max(high, x);
    meshes.push_back(std::move(mesh));
  }
  exposure->assign(primitives.size(), {});
  if (!(low.x <= high.x)) return {};  // no vertices
  const float epsilon = std::max(1e-4f * glm::length(high - low), 1e-6f);
  auto scene = EmbreeScene::build(std::move(meshes));
  if (!scene) return make_error("sender exposure: " + scene.message());

  // Vertices numbered across primitives; each thread takes every T-th (results do not depend on T).
  std::vector<std::pair<std::size_t, std::size_t>> vertices;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    (*exposure)[i].assign(primitives[i].positions.size(), 1.0f);
    if (!primitives[i].normals.empty())
      for (std::size_t v = 0; v < primitives[i].positions.size(); ++v) vertices.emplace_back(i, v);
  }
  const std::size_t threads = std::max<std::size_t>(1, std::min<std::size_t>(std::thread::hardware_concurrency(), 16));
  const auto work = [&](std::size_t first) {
    for (std::size_t j = first; j < vertices.size(); j += threads) {
      const auto [i, v] = vertices[j];
      const glm::vec3 n = primitives[i].normals[v];
      const float length = glm::length(n);
      if (!(length > 0.0f)) continue;  // no normal: left at 1
      const glm::vec3 normal = n / length, origin = primitives[i].positions[v] + epsilon * normal;
      const std::uint32_t key = std::uint32_t(j) * 0x9E3779B9u ^ seed;
      int open = 0;
      for (int k = 0; k < directions; ++k) {
        const glm::uvec2 bits = sobol_owen_2d(std::uint32_t(k), key);
        const glm::vec2 u(float(bits.x) * 0x1p-32f, float(bits.y) * 0x1p-32f);
        if (!scene->occluded(origin, sample_cosine_hemisphere(normal, u))) ++open;
      }
      (*exposure)[i][v] = float(open) / float(directions);
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& thread : pool) thread.join();
  return {};
}

Result<std::vector<std::vector<float>>> rest_pose_sender_exposure(const anim::Character& character, int directions) {
  anim::PoseBuffers pose;
  if (Status s = anim::evaluate_pose(character, -1, 0.0f, anim::WrapMode::loop, pose); !s) return s.error();
  auto primitives = anim::pose_meshes(character, pose);
  if (!primitives) return primitives.error();
  std::vector<std::vector<float>> exposure;
  SenderExposureJob job;
  job.primitives = *primitives;
  job.directions = directions;
  job.exposure = &exposure;
  if (Status s = job.run(); !s) return s.error();
  return exposure;
}

}  // namespace proxygi::ref
