#include "prt/visibility_grid.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "prt/sampling.h"
#include "prt/transfer.h"
#include "settings/render_settings.h"
#include "sh/basis.h"

namespace proxygi::prt {
namespace {

constexpr float kPiF = 3.14159265358979f;
// A point is inside a mesh when more than this share of its rays hit back faces (a point in the
// open sees back faces only through cracks).
constexpr float kInsideBackFraction = 0.25f;

// The occluders in one Embree scene; first hits report whether they arrive on a back face.
class Occluders {
 public:
  explicit Occluders(std::vector<const StaticSurface*> surfaces) : surfaces_(std::move(surfaces)) {
    device_ = rtcNewDevice("threads=1");
    scene_ = rtcNewScene(device_);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    for (const StaticSurface* surface : surfaces_) {
      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), surface->positions.size()));
      for (std::size_t i = 0; i < surface->positions.size(); ++i)
        for (int c = 0; c < 3; ++c) vertices[3 * i + std::size_t(c)] = surface->positions[i][c];
      auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), surface->indices.size() / 3));
      std::copy(surface->indices.begin(), surface->indices.end(), indices);
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(scene_, geometry);
      rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene_);
  }
  Occluders(const Occluders&) = delete;
  Occluders& operator=(const Occluders&) = delete;
  ~Occluders() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }

  enum class Hit { none, front, back };
  Hit intersect(const glm::vec3& origin, const glm::vec3& dir) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit ray{};
    ray.ray.org_x = origin.x, ray.ray.org_y = origin.y, ray.ray.org_z = origin.z;
    ray.ray.dir_x = dir.x, ray.ray.dir_y = dir.y, ray.ray.dir_z = dir.z;
    ray.ray.tnear = 0.0f;
    ray.ray.tfar = INFINITY;
    ray.ray.mask = 0xFFFFFFFFu;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &ray);
    if (ray.hit.geomID == RTC_INVALID_GEOMETRY_ID) return Hit::none;
    const StaticSurface& s = *surfaces_[ray.hit.geomID];
    const std::uint32_t* tri = &s.indices[3 * std::size_t(ray.hit.primID)];
    const float u = ray.hit.u, v = ray.hit.v;
    const glm::vec3 n = (1.0f - u - v) * s.normals[tri[0]] + u * s.normals[tri[1]] + v * s.normals[tri[2]];
    return glm::dot(n, dir) < 0.0f ? Hit::front : Hit::back;
  }

 private:
  std::vector<const StaticSurface*> surfaces_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

// Direction k of K on the unit sphere (uniform) from a rotated Hammersley point.
glm::vec3 sphere_direction(std::uint32_t k, std::uint32_t count, glm::vec2 shift) {
  float u1 = (float(k) + 0.5f) / float(count) + shift.x;
  float u2 = sampling::radical_inverse2(k) + shift.y;
  u1 -= std::floor(u1);
  u2 -= std::floor(u2);
  const float z = 1.0f - 2.0f * u1, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPiF * u2;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

Status validate(const VisibilityGridSettings& settings, int order) {
  if (order < settings::kMinShOrder || order > settings::kMaxShOrder)
    return make_error("prt.order " + std::to_string(order) + ": must be in " + std::to_string(settings::kMinShOrder) +
                      ".." + std::to_string(settings::kMaxShOrder));
  if (!(settings.spacing_m > 0.0f) || !std::isfinite(settings.spacing_m))
    return make_error("prt.grid.spacing " + std::to_string(settings.spacing_m) + ": must be a positive length in m");
  if (!(settings.margin_m >= 0.0f) || !std::isfinite(settings.margin_m))
    return make_error("prt.grid.margin " + std::to_string(settings.margin_m) + ": must be >= 0 m");
  if (settings.directions < kMinDirections || settings.directions > kMaxDirections)
    return make_error("prt.grid.directions " + std::to_string(settings.directions) + ": must be in " +
                      std::to_string(kMinDirections) + ".." + std::to_string(kMaxDirections));
  return {};
}

}  // namespace

Result<VisibilityGrid> compute_visibility_grid(const StaticReceivers& receivers, int order,
                                               const VisibilityGridSettings& settings, int threads) {
  if (Status ok = validate(settings, order); !ok) return ok.error();
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const auto start = std::chrono::steady_clock::now();
  VisibilityGrid grid;
  grid.order = order;
  std::vector<const StaticSurface*> occluders;
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const StaticSurface& s : receivers.surfaces) {
    if (s.name == "ground" || s.indices.empty()) continue;
    occluders.push_back(&s);
    for (const glm::vec3& p : s.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (occluders.empty()) return grid;
  lo -= glm::vec3(settings.margin_m, 0.0f, settings.margin_m);
  lo.y = std::min(lo.y, 0.0f);
  hi += glm::vec3(settings.margin_m);
  const glm::vec3 cells = glm::ceil((hi - lo) / settings.spacing_m);
  const glm::uvec3 size = glm::uvec3(cells) + 1u;
  if (double(size.x) * size.y * size.z > double(kMaxVisibilityGridPoints))
    return make_error("prt.grid.spacing " + std::to_string(settings.spacing_m) + ": " + std::to_string(size.x) + "×" +
                      std::to_string(size.y) + "×" + std::to_string(size.z) + " points, more than " +
                      std::to_string(kMaxVisibilityGridPoints));
  grid.origin = lo;
  grid.spacing = settings.spacing_m;
  grid.size = size;
  const std::size_t nn = std::size_t(order * order), points = grid.points();
  grid.values.assign(points * nn, 0.0f);
  const Occluders scene(occluders);
  const auto count = std::uint32_t(settings.directions);
  const double weight = 4.0 * double(kPiF) / double(count);  // uniform sphere: ∫ f ≈ (4π/K) Σ f
  std::atomic<std::size_t> next{0};
  constexpr std::size_t kChunk = 64;
  auto worker = [&] {
    std::vector<double> blocked(nn);
    std::vector<float> basis(nn);
    for (std::size_t first; (first = next.fetch_add(kChunk)) < points;) {
      for (std::size_t i = first; i < std::min(first + kChunk, points); ++i) {
        const std::size_t x = i % size.x, y = (i / size.x) % size.y, z = i / (std::size_t(size.x) * size.y);
        const glm::vec3 p = lo + settings.spacing_m * glm::vec3(float(x), float(y), float(z));
        const std::uint32_t h = sampling::hash32(settings.seed ^ sampling::hash32(std::uint32_t(i) * 0x9e3779b9u));
        const glm::vec2 shift(float(h & 0xFFFFu) / 65536.0f, float(h >> 16) / 65536.0f);
        std::fill(blocked.begin(), blocked.end(), 0.0);
        std::uint32_t back = 0;
        for (std::uint32_t k = 0; k < count; ++k) {
          const glm::vec3 d = sphere_direction(k, count, shift);
          const Occluders::Hit hit = scene.intersect(p, d);
          if (hit == Occluders::Hit::none) continue;
          if (hit == Occluders::Hit::back) ++back;
          sh::evaluate_basis(order, d, basis);
          for (std::size_t c = 0; c < nn; ++c) blocked[c] += basis[c];
        }
        float* v = &grid.values[i * nn];
        for (std::size_t c = 0; c < nn; ++c) v[c] = float((c == 0 ? sh::kSqrtFourPi : 0.0) - weight * blocked[c]);
        if (float(back) > kInsideBackFraction * float(count)) {
          std::fill(v, v + nn, 0.0f);
          v[0] = kInsidePoint;
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  grid.rays = std::uint64_t(points) * count;
  grid.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return grid;
}

bool sample_visibility(const VisibilityGrid& grid, const glm::vec3& p, std::span<float> out) {
  if (grid.size.x == 0) return false;
  const glm::vec3 u = (p - grid.origin) / grid.spacing;
  const glm::vec3 last = glm::vec3(grid.size - 1u);
  if (glm::any(glm::lessThan(u, glm::vec3(0.0f))) || glm::any(glm::greaterThan(u, last))) return false;
  const glm::uvec3 base = glm::min(glm::uvec3(glm::floor(u)), glm::max(grid.size, 2u) - 2u);
  const glm::vec3 f = u - glm::vec3(base);
  const std::size_t nn = std::size_t(grid.order * grid.order);
  std::vector<float> sum(nn, 0.0f);
  float total = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::uvec3 o((corner & 1) ? 1u : 0u, (corner & 2) ? 1u : 0u, (corner & 4) ? 1u : 0u);
    const glm::uvec3 q = glm::min(base + o, grid.size - 1u);
    const float w = (o.x ? f.x : 1.0f - f.x) * (o.y ? f.y : 1.0f - f.y) * (o.z ? f.z : 1.0f - f.z);
    const float* v = &grid.values[((std::size_t(q.z) * grid.size.y + q.y) * grid.size.x + q.x) * nn];
    if (v[0] < 0.0f) continue;  // inside a mesh
    total += w;
    for (std::size_t c = 0; c < nn; ++c) sum[c] += w * v[c];
  }
  if (!(total > kMinVisibilityWeight)) return false;
  for (std::size_t c = 0; c < nn; ++c) out[c] = sum[c] / total;
  return true;
}

}  // namespace proxygi::prt
