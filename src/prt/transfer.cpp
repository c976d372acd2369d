#include "prt/transfer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <string>
#include <thread>

#include "prt/sampling.h"
#include "settings/render_settings.h"
#include "sh/basis.h"
#include "sh/convolution.h"

namespace proxygi::prt {
namespace {

constexpr float kPiF = 3.14159265358979f;
constexpr std::size_t kChunk = 64;  // vertices per work item

// The receivers' surfaces in one Embree scene (geometry id = surface index); first hits with
// primitive id and barycentrics, which the path tracer's EmbreeScene does not report.
class RayScene {
 public:
  explicit RayScene(const StaticReceivers& receivers) : receivers_(receivers) {
    device_ = rtcNewDevice("threads=1");
    scene_ = rtcNewScene(device_);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    for (const StaticSurface& surface : receivers.surfaces) {
      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), surface.positions.size()));
      for (std::size_t i = 0; i < surface.positions.size(); ++i)
        for (int c = 0; c < 3; ++c) vertices[3 * i + std::size_t(c)] = surface.positions[i][c];
      auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), surface.indices.size() / 3));
      std::copy(surface.indices.begin(), surface.indices.end(), indices);
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(scene_, geometry);
      rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene_);
  }
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;
  ~RayScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }

  struct Hit {
    enum Kind { none, surface, outer_ground } kind = none;
    unsigned surface_index = 0, triangle = 0;
    float u = 0.0f, v = 0.0f;
    bool front = false;  // arrived against the surface's vertex normals
  };

  Hit intersect(const glm::vec3& origin, const glm::vec3& dir, float tnear) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit ray{};
    ray.ray.org_x = origin.x, ray.ray.org_y = origin.y, ray.ray.org_z = origin.z;
    ray.ray.dir_x = dir.x, ray.ray.dir_y = dir.y, ray.ray.dir_z = dir.z;
    ray.ray.tnear = tnear;
    ray.ray.tfar = INFINITY;
    ray.ray.mask = 0xFFFFFFFFu;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &ray);
    Hit hit;
    float t = INFINITY;
    if (ray.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
      hit.kind = Hit::surface;
      hit.surface_index = ray.hit.geomID;
      hit.triangle = ray.hit.primID;
      hit.u = ray.hit.u;
      hit.v = ray.hit.v;
      t = ray.ray.tfar;
      const StaticSurface& s = receivers_.surfaces[hit.surface_index];
      const std::uint32_t* tri = &s.indices[3 * std::size_t(hit.triangle)];
      const glm::vec3 n =
          (1.0f - hit.u - hit.v) * s.normals[tri[0]] + hit.u * s.normals[tri[1]] + hit.v * s.normals[tri[2]];
      hit.front = glm::dot(n, dir) < 0.0f;
    }
    const float t_ground = outer_ground_distance(origin, dir);
    if (t_ground < t) hit = Hit{Hit::outer_ground, 0, 0, 0.0f, 0.0f, true};
    return hit;
  }

  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tnear) const {
    if (outer_ground_distance(origin, dir) < INFINITY) return true;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
    ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
    ray.tnear = tnear;
    ray.tfar = INFINITY;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
  }

 private:
  // Distance to the outer ground (y = 0 inside the ground square, outside the patch), from above.
  float outer_ground_distance(const glm::vec3& origin, const glm::vec3& dir) const {
    const OuterGround& g = receivers_.outer_ground;
    if (!g.enabled || dir.y >= 0.0f || origin.y <= 0.0f) return INFINITY;
    const float t = -origin.y / dir.y;
    const glm::vec3 p = origin + t * dir;
    if (std::abs(p.x) > g.half_size || std::abs(p.z) > g.half_size) return INFINITY;
    if (p.x >= g.patch_min.x && p.x <= g.patch_max.x && p.z >= g.patch_min.y && p.z <= g.patch_max.y) return INFINITY;
    return t;
  }

  const StaticReceivers& receivers_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

using sampling::hash32;
using sampling::radical_inverse2;

struct Frame {
  glm::vec3 t, b, n;
};
Frame frame_about(const glm::vec3& n) {  // Duff et al. 2017
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  return {glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x), glm::vec3(b, sign + n.y * n.y * a, -n.y), n};
}

// Direction k of K for a vertex: cosine-weighted about n from a rotated Hammersley point.
glm::vec3 direction(const Frame& f, std::uint32_t k, std::uint32_t count, glm::vec2 shift) {
  float u1 = (float(k) + 0.5f) / float(count) + shift.x;
  float u2 = radical_inverse2(k) + shift.y;
  u1 -= std::floor(u1);
  u2 -= std::floor(u2);
  const float r = std::sqrt(u1), phi = 2.0f * kPiF * u2;
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  return glm::normalize(r * std::cos(phi) * f.t + r * std::sin(phi) * f.b + z * f.n);
}

float origin_offset(const glm::vec3& p) {
  return 1e-4f * std::max(1.0f, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
}

// Ray origins per vertex: p moved 1 mm (at most a tenth of the way) toward its one-ring's
// centroid in the tangent plane, then off the surface along N. A vertex on a seam (a floor vertex
// at a wall's foot, a corner) otherwise lies in the other surface's plane and its rays leak
// behind it; the shift keeps them in front of it.
std::vector<std::vector<glm::vec3>> ray_origins(const StaticReceivers& receivers) {
  std::vector<std::vector<glm::vec3>> out;
  for (const StaticSurface& s : receivers.surfaces) {
    std::vector<glm::vec3> sum(s.positions.size(), glm::vec3(0.0f));  // Σ adjacent triangle centroids
    std::vector<int> count(s.positions.size(), 0);
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
      const glm::vec3 c =
          (s.positions[s.indices[t]] + s.positions[s.indices[t + 1]] + s.positions[s.indices[t + 2]]) / 3.0f;
      for (int k = 0; k < 3; ++k) {
        sum[s.indices[t + std::size_t(k)]] += c;
        ++count[s.indices[t + std::size_t(k)]];
      }
    }
    std::vector<glm::vec3>& origins = out.emplace_back(s.positions.size());
    for (std::size_t v = 0; v < s.positions.size(); ++v) {
      const glm::vec3 p = s.positions[v], n = s.normals[v];
      origins[v] = p;
      if (count[v] > 0) {
        glm::vec3 d = sum[v] / float(count[v]) - p;
        d -= n * glm::dot(d, n);
        const float len = glm::length(d);
        if (len > 0.0f) origins[v] = p + std::min(1e-3f, 0.1f * len) * d / len;
      }
      origins[v] += origin_offset(p) * n;
    }
  }
  return out;
}

// Runs body(surface, vertex) over every vertex on `threads` threads, in chunks.
template <class Body>
void for_each_vertex(const StaticReceivers& receivers, int threads, std::string_view stage, const Progress& progress,
                     Body body) {
  std::vector<std::pair<std::size_t, std::size_t>> chunks;  // (surface, first vertex)
  std::size_t total = 0;
  for (std::size_t s = 0; s < receivers.surfaces.size(); ++s) {
    const std::size_t n = receivers.surfaces[s].positions.size();
    for (std::size_t v = 0; v < n; v += kChunk) chunks.emplace_back(s, v);
    total += n;
  }
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex mutex;
  auto worker = [&] {
    for (std::size_t c; (c = next.fetch_add(1)) < chunks.size();) {
      const auto [s, first] = chunks[c];
      const std::size_t last = std::min(first + kChunk, receivers.surfaces[s].positions.size());
      for (std::size_t v = first; v < last; ++v) body(s, v);
      if (progress) {
        std::lock_guard lock(mutex);
        done += last - first;
        progress(stage, done, total);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

Status validate(const StaticReceivers& receivers, const TransferSettings& settings) {
  if (settings.order < settings::kMinShOrder || settings.order > settings::kMaxShOrder)
    return make_error("prt.order " + std::to_string(settings.order) + ": must be in " +
                      std::to_string(settings::kMinShOrder) + ".." + std::to_string(settings::kMaxShOrder));
  if (settings.directions < kMinDirections || settings.directions > kMaxDirections)
    return make_error("prt.directions " + std::to_string(settings.directions) + ": must be in " +
                      std::to_string(kMinDirections) + ".." + std::to_string(kMaxDirections));
  if (settings.bounces < 0 || settings.bounces > kMaxBounces)
    return make_error("prt.bounces " + std::to_string(settings.bounces) + ": must be in 0.." +
                      std::to_string(kMaxBounces));
  for (const StaticSurface& s : receivers.surfaces) {
    if (s.normals.size() != s.positions.size())
      return make_error(s.name + ": " + std::to_string(s.normals.size()) + " normals for " +
                        std::to_string(s.positions.size()) + " positions");
    if (s.indices.size() % 3 != 0)
      return make_error(s.name + ": index count " + std::to_string(s.indices.size()) + " not a multiple of 3");
    for (std::size_t i = 0; i < s.indices.size(); ++i)
      if (s.indices[i] >= s.positions.size())
        return make_error(s.name + ": index " + std::to_string(i) + " = " + std::to_string(s.indices[i]) +
                          " out of range (" + std::to_string(s.positions.size()) + " vertices)");
    for (std::size_t i = 0; i < s.positions.size(); ++i)
      if (!(std::isfinite(s.positions[i].x) && std::isfinite(s.positions[i].y) && std::isfinite(s.positions[i].z)) ||
          !(std::abs(glm::length(s.normals[i]) - 1.0f) < 1e-3f))
        return make_error(s.name + ": vertex " + std::to_string(i) + ": non-finite position or non-unit normal");
  }
  return {};
}

}  // namespace

std::size_t TransferSet::bytes() const {
  std::size_t total = 0;
  for (const SurfaceTransfer& s : surfaces) total += (s.shadowed.size() + s.interreflected.size()) * sizeof(float);
  return total;
}

Result<TransferSet> compute_transfer(const StaticReceivers& receivers, const TransferSettings& settings,
                                     const Progress& progress, int threads) {
  if (Status ok = validate(receivers, settings); !ok) return ok.error();
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const auto start = std::chrono::steady_clock::now();
  const int order = settings.order;
  const std::size_t nn = std::size_t(order * order);
  const auto count = std::uint32_t(settings.directions);
  const float weight = kPiF / float(count);  // cosine-weighted: ∫ f cos ≈ (π/K) Σ f
  RayScene scene(receivers);
  const std::vector<std::vector<glm::vec3>> origins = ray_origins(receivers);
  std::atomic<std::uint64_t> rays{0};

  TransferSet out;
  out.order = order;
  out.surfaces.resize(receivers.surfaces.size());
  for (std::size_t s = 0; s < receivers.surfaces.size(); ++s) {
    out.surfaces[s].shadowed.assign(receivers.surfaces[s].positions.size() * nn, 0.0f);
    out.surfaces[s].interreflected.assign(receivers.surfaces[s].positions.size() * 3 * nn, 0.0f);
  }
  // One vertex's ray set: its hemisphere frame, its seeded shift of the direction set, and where
  // its rays start (the same in every pass, so each pass sees the same directions).
  struct VertexRays {
    Frame frame;
    glm::vec2 shift;
    glm::vec3 origin;
    float offset;
  };
  const auto rays_of = [&](std::size_t s, std::size_t v) {
    const StaticSurface& surface = receivers.surfaces[s];
    const std::uint32_t h = hash32(settings.seed ^ hash32(std::uint32_t(s) * 0x9e3779b9u ^ hash32(std::uint32_t(v))));
    return VertexRays{frame_about(surface.normals[v]), glm::vec2(float(h & 0xFFFFu) / 65536.0f, float(h >> 16) / 65536.0f),
                      origins[s][v], origin_offset(surface.positions[v])};
  };

  // Pass 0: T_DS = H(N) − (π/K) Σ_blocked y(s_k).
  for_each_vertex(receivers, threads, "shadow", progress, [&](std::size_t s, std::size_t v) {
    const VertexRays r = rays_of(s, v);
    std::vector<double> blocked(nn, 0.0);
    std::vector<float> basis(nn);
    for (std::uint32_t k = 0; k < count; ++k) {
      const glm::vec3 d = direction(r.frame, k, count, r.shift);
      if (!scene.occluded(r.origin, d, r.offset)) continue;
      sh::evaluate_basis(order, d, basis);
      for (std::size_t i = 0; i < nn; ++i) blocked[i] += basis[i];
    }
    rays += count;
    const std::vector<double> h = sh::clamped_cosine_about(order, glm::dvec3(receivers.surfaces[s].normals[v]));
    float* t = &out.surfaces[s].shadowed[v * nn];
    for (std::size_t i = 0; i < nn; ++i) t[i] = float(h[i] - double(weight) * blocked[i]);
  });

  // Bounce passes: previous[s] holds T^{b−1} per vertex and channel (vertex × 3 × n²).
  std::vector<std::vector<float>> previous(receivers.surfaces.size()), current(receivers.surfaces.size());
  for (std::size_t s = 0; s < receivers.surfaces.size(); ++s) {
    const std::vector<float>& t = out.surfaces[s].shadowed;
    std::vector<float>& rgb = out.surfaces[s].interreflected;
    previous[s].resize(rgb.size());
    for (std::size_t v = 0; v < receivers.surfaces[s].positions.size(); ++v)
      for (int c = 0; c < 3; ++c) std::copy_n(&t[v * nn], nn, &previous[s][(3 * v + std::size_t(c)) * nn]);
    rgb = previous[s];
    current[s].assign(rgb.size(), 0.0f);
  }
  const std::vector<double> h_up = sh::clamped_cosine_about(order, glm::dvec3(0.0, 1.0, 0.0));
  for (int b = 1; b <= settings.bounces; ++b) {
    for_each_vertex(receivers, threads, "bounce " + std::to_string(b), progress, [&](std::size_t s, std::size_t v) {
      const VertexRays r = rays_of(s, v);
      std::vector<double> sum(3 * nn, 0.0);
      for (std::uint32_t k = 0; k < count; ++k) {
        const glm::vec3 d = direction(r.frame, k, count, r.shift);
        const RayScene::Hit hit = scene.intersect(r.origin, d, r.offset);
        if (hit.kind == RayScene::Hit::none || !hit.front) continue;
        if (hit.kind == RayScene::Hit::outer_ground) {
          if (b != 1) continue;  // the outer ground has no bounce light of its own
          const glm::vec3& albedo = receivers.outer_ground.albedo;
          for (int c = 0; c < 3; ++c)
            for (std::size_t i = 0; i < nn; ++i) sum[std::size_t(c) * nn + i] += double(albedo[c]) * h_up[i];
          continue;
        }
        const StaticSurface& q = receivers.surfaces[hit.surface_index];
        const std::uint32_t* tri = &q.indices[3 * std::size_t(hit.triangle)];
        const float w[3] = {1.0f - hit.u - hit.v, hit.u, hit.v};
        const std::vector<float>& prev = previous[hit.surface_index];
        for (int corner = 0; corner < 3; ++corner) {
          const float* tq = &prev[3 * std::size_t(tri[corner]) * nn];
          for (int c = 0; c < 3; ++c) {
            const double scale = double(w[corner]) * double(q.albedo[c]);
            for (std::size_t i = 0; i < nn; ++i) sum[std::size_t(c) * nn + i] += scale * tq[std::size_t(c) * nn + i];
          }
        }
      }
      rays += count;
      float* dst = &current[s][3 * v * nn];
      for (std::size_t i = 0; i < 3 * nn; ++i) dst[i] = float(sum[i] / double(count));
    });
    for (std::size_t s = 0; s < receivers.surfaces.size(); ++s) {
      std::vector<float>& rgb = out.surfaces[s].interreflected;
      for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] += current[s][i];
      std::swap(previous[s], current[s]);
    }
  }
  out.rays = rays.load();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace proxygi::prt
