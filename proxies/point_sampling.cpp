#include "proxies/point_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace proxygi::proxies {

std::uint64_t Random::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

float Random::uniform() { return float(next() >> 40) * (1.0f / float(1ull << 24)); }

std::vector<SurfaceSample> sample_surface(const anim::Character& character, const BindSurface& surface,
                                          int count, std::uint64_t seed) {
  std::vector<double> cdf(surface.triangle_area.size());
  double total = 0.0;
  for (std::size_t t = 0; t < cdf.size(); ++t) cdf[t] = (total += double(surface.triangle_area[t]));
  std::vector<SurfaceSample> samples;
  if (total <= 0.0 || count <= 0) return samples;
  samples.reserve(std::size_t(count));
  Random random(seed);
  for (int i = 0; i < count; ++i) {
    // Stratified in area: sample i lands in [i, i + 1) / count of the cumulative area.
    const double target = (double(i) + double(random.uniform())) / double(count) * total;
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), target);
    const std::size_t t = std::min(std::size_t(it - cdf.begin()), cdf.size() - 1);
    float u = random.uniform(), v = random.uniform();
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    SurfaceSample s;
    s.triangle = std::uint32_t(t);
    s.barycentric = glm::vec3(1.0f - u - v, u, v);
    const glm::uvec3& tri = surface.soup.triangles[t];
    s.position = s.barycentric.x * surface.soup.positions[tri.x] + s.barycentric.y * surface.soup.positions[tri.y] +
                 s.barycentric.z * surface.soup.positions[tri.z];
    const glm::vec2 uv = s.barycentric.x * surface.uvs[tri.x] + s.barycentric.y * surface.uvs[tri.y] +
                         s.barycentric.z * surface.uvs[tri.z];
    s.albedo = base_color(character, surface.triangle_material[t], uv);
    s.bone = sample_influences(surface, s).dominant();
    samples.push_back(s);
  }
  return samples;
}

Influences sample_influences(const BindSurface& surface, const SurfaceSample& sample) {
  std::vector<std::pair<int, float>> sum;
  const glm::uvec3& tri = surface.soup.triangles[sample.triangle];
  for (int corner = 0; corner < 3; ++corner) {
    const Influences& inf = surface.influences[tri[corner]];
    for (int k = 0; k < kMaxInfluences; ++k) accumulate(sum, inf.nodes[std::size_t(k)], sample.barycentric[corner] * inf.weights[std::size_t(k)]);
  }
  return to_influences(std::move(sum));
}

void NearestPointGrid::build(std::span<const glm::vec3> points, float cell) {
  points_ = points;
  cell_ = cell;
  const Box box = bounds_of(points);
  origin_ = box.lo;
  dims_ = glm::max(glm::ivec3(glm::floor((box.hi - box.lo) / cell)) + 1, glm::ivec3(1));
  const std::size_t cells = std::size_t(dims_.x) * std::size_t(dims_.y) * std::size_t(dims_.z);
  start_.assign(cells + 1, 0);
  std::vector<std::uint32_t> cell_of(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((points[i] - origin_) / cell)), glm::ivec3(0), dims_ - 1);
    cell_of[i] = std::uint32_t((std::size_t(c.z) * std::size_t(dims_.y) + std::size_t(c.y)) * std::size_t(dims_.x) + std::size_t(c.x));
    ++start_[cell_of[i] + 1];
  }
  for (std::size_t i = 0; i < cells; ++i) start_[i + 1] += start_[i];
  items_.assign(points.size(), 0);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < points.size(); ++i) items_[fill[cell_of[i]]++] = std::uint32_t(i);
}

int NearestPointGrid::nearest(const glm::vec3& p) const {
  if (points_.empty()) return -1;
  int best = -1;
  float best_d2 = std::numeric_limits<float>::max();
  const glm::ivec3 center = glm::clamp(glm::ivec3(glm::floor((p - origin_) / cell_)), glm::ivec3(0), dims_ - 1);
  const int max_ring = std::max({dims_.x, dims_.y, dims_.z});
  for (int r = 0; r <= max_ring; ++r) {
    // Same bound as ClosestTriangleGrid: ring r is at least (r - 1) cells away.
    const float bound = float(r - 1) * cell_;
    if (best >= 0 && bound > 0.0f && bound * bound >= best_d2) break;
    for_each_cell_in_ring(center, r, dims_, [&](std::size_t i) {
      for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
        const glm::vec3 d = points_[items_[k]] - p;
        const float d2 = glm::dot(d, d);
        if (d2 < best_d2) best_d2 = d2, best = int(items_[k]);
      }
    });
  }
  return best;
}

std::vector<glm::vec3> sample_interior(const DistanceGrid& grid, int max_count, std::uint64_t seed) {
  Random random(seed);
  std::vector<glm::vec3> points;
  std::size_t i = 0;
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x, ++i) {
        if (grid.values[i] >= 0.0f) continue;
        const glm::vec3 jitter(random.uniform() - 0.5f, random.uniform() - 0.5f, random.uniform() - 0.5f);
        const glm::vec3 p = grid.origin + (glm::vec3(x, y, z) + jitter) * grid.cell;
        if (grid.sample(p) < 0.0f) points.push_back(p);
      }
  if (max_count >= 0 && points.size() > std::size_t(max_count)) {
    // Deterministic thinning: a partial Fisher–Yates shuffle, then keep the first max_count.
    for (std::size_t k = 0; k < std::size_t(max_count); ++k) {
      const std::size_t j = k + std::size_t(random.next() % (points.size() - k));
      std::swap(points[k], points[j]);
    }
    points.resize(std::size_t(max_count));
  }
  return points;
}

std::vector<glm::vec3> fibonacci_directions(int n) {
  std::vector<glm::vec3> dirs(std::size_t(std::max(n, 0)));
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < n; ++i) {
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
    const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
    const float phi = golden * float(i);
    dirs[std::size_t(i)] = glm::vec3(r * std::cos(phi), y, r * std::sin(phi));
  }
  return dirs;
}

std::vector<glm::vec3> unit_ball_points(int n) {
  std::vector<glm::vec3> dirs = fibonacci_directions(n);
  std::vector<glm::vec3> points(dirs.size());
  for (int i = 0; i < n; ++i) {
    // Radii stratified so each shell holds equal volume; a second golden-ratio sequence
    // decorrelates radius from direction.
    const float u = std::fmod((float(i) + 0.5f) * 0.6180339887f, 1.0f);
    points[std::size_t(i)] = dirs[std::size_t(i)] * std::cbrt(u);
  }
  return points;
}

}  // namespace proxygi::proxies
