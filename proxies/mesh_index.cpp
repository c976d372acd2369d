#include "proxies/mesh_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxygi::proxies {
namespace {

glm::ivec3 clamp_cell(const glm::ivec3& c, const glm::ivec3& dims) {
  return glm::clamp(c, glm::ivec3(0), dims - 1);
}

float box_distance(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
  return glm::length(d);
}

// Twice the signed area of (a, b, p) in 2D, in doubles so near-degenerate cases stay consistent.
double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Where the line through q (in the u, v plane) along `axis` crosses triangle abc: false when it
// misses; else `crossing` is the axis coordinate and `sign` ±1 the winding contribution (the sign
// of the projected area, i.e. of normal[axis]).
bool line_crosses_triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int axis, const glm::dvec2& q,
                           double& crossing, int& sign) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const glm::dvec2 a2(a[u], a[v]), b2(b[u], b[v]), c2(c[u], c[v]);
  const double w0 = edge(b2, c2, q), w1 = edge(c2, a2, q), w2 = edge(a2, b2, q);
  const double area = w0 + w1 + w2;  // = twice the projected signed area, sign of normal[axis]
  if (area == 0.0) return false;
  const bool hit = area > 0.0 ? (w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0) : (w0 <= 0.0 && w1 <= 0.0 && w2 <= 0.0);
  if (!hit) return false;
  crossing = (w0 * double(a[axis]) + w1 * double(b[axis]) + w2 * double(c[axis])) / area;
  sign = area > 0.0 ? 1 : -1;
  return true;
}

}  // namespace

glm::vec3 closest_point_on_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                    const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = 1.0f / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

Box bounds_of(std::span<const glm::vec3> points) {
  Box box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
  for (const glm::vec3& p : points) {
    box.lo = glm::min(box.lo, p);
    box.hi = glm::max(box.hi, p);
  }
  if (points.empty()) box = Box{};
  return box;
}

void ClosestTriangleGrid::build(const TriangleSoup& soup, float cell) {
  soup_ = &soup;
  cell_ = cell;
  const Box box = bounds_of(soup.positions);
  origin_ = box.lo;
  dims_ = glm::max(glm::ivec3(glm::floor((box.hi - box.lo) / cell)) + 1, glm::ivec3(1));
  const std::size_t cells = std::size_t(dims_.x) * std::size_t(dims_.y) * std::size_t(dims_.z);
  cell_start_.assign(cells + 1, 0);
  auto for_cells = [&](const glm::uvec3& t, auto&& visit) {
    const glm::vec3& a = soup.positions[t.x];
    const glm::vec3& b = soup.positions[t.y];
    const glm::vec3& c = soup.positions[t.z];
    const glm::ivec3 lo = clamp_cell(glm::ivec3(glm::floor((glm::min(glm::min(a, b), c) - origin_) / cell)), dims_);
    const glm::ivec3 hi = clamp_cell(glm::ivec3(glm::floor((glm::max(glm::max(a, b), c) - origin_) / cell)), dims_);
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x)
          visit((std::size_t(z) * std::size_t(dims_.y) + std::size_t(y)) * std::size_t(dims_.x) + std::size_t(x));
  };
  for (const glm::uvec3& t : soup.triangles) for_cells(t, [&](std::size_t i) { ++cell_start_[i + 1]; });
  for (std::size_t i = 0; i < cells; ++i) cell_start_[i + 1] += cell_start_[i];
  cell_items_.assign(cell_start_[cells], 0);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t k = 0; k < soup.triangles.size(); ++k)
    for_cells(soup.triangles[k], [&](std::size_t i) { cell_items_[fill[i]++] = k; });
}

float ClosestTriangleGrid::distance(const glm::vec3& p, float max_distance) const {
  float best = max_distance;
  // Rings around the cell of p's projection onto the grid box: every cell in ring r is at least
  // (r - 1) cells from that projection, and projecting onto a convex box never lengthens
  // distances to points inside it, so the bound holds for p too.
  const glm::ivec3 center = clamp_cell(glm::ivec3(glm::floor((p - origin_) / cell_)), dims_);
  const int max_ring = int(std::ceil(max_distance / cell_)) + 1;
  for (int r = 0; r <= max_ring; ++r) {
    if (float(r - 1) * cell_ >= best) break;
    for_each_cell_in_ring(center, r, dims_, [&](std::size_t i) {
      if (cell_start_[i] == cell_start_[i + 1]) return;
      const std::size_t x = i % std::size_t(dims_.x), y = (i / std::size_t(dims_.x)) % std::size_t(dims_.y),
                        z = i / (std::size_t(dims_.x) * std::size_t(dims_.y));
      const glm::vec3 cell_lo = origin_ + glm::vec3(float(x), float(y), float(z)) * cell_;
      if (box_distance(p, cell_lo, cell_lo + cell_) >= best) return;
      for (std::uint32_t k = cell_start_[i]; k < cell_start_[i + 1]; ++k) {
        const glm::uvec3& t = soup_->triangles[cell_items_[k]];
        const glm::vec3 q = closest_point_on_triangle(p, soup_->positions[t.x], soup_->positions[t.y],
                                                      soup_->positions[t.z]);
        best = std::min(best, glm::length(q - p));
      }
    });
  }
  return best;
}

void WindingIndex::build(const TriangleSoup& soup, int bins) {
  soup_ = &soup;
  bins_ = std::max(bins, 1);
  const Box box = bounds_of(soup.positions);
  nudge_ = 1e-5f * std::max(box.diagonal(), 1e-6f);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    Plane& plane = planes_[axis];
    plane.origin = glm::vec2(box.lo[u], box.lo[v]);
    plane.cell = glm::max(glm::vec2(box.hi[u] - box.lo[u], box.hi[v] - box.lo[v]) / float(bins_), glm::vec2(1e-9f));
    plane.start.assign(std::size_t(bins_) * std::size_t(bins_) + 1, 0);
    auto for_bins = [&](const glm::uvec3& t, auto&& visit) {
      glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
      for (int k = 0; k < 3; ++k) {
        const glm::vec3& q = soup.positions[t[k]];
        lo = glm::min(lo, glm::vec2(q[u], q[v]));
        hi = glm::max(hi, glm::vec2(q[u], q[v]));
      }
      // Widen by the nudge so a nudged query still finds triangles it may cross.
      const glm::ivec2 b0 = glm::clamp(glm::ivec2(glm::floor((lo - nudge_ - plane.origin) / plane.cell)), 0, bins_ - 1);
      const glm::ivec2 b1 = glm::clamp(glm::ivec2(glm::floor((hi + nudge_ - plane.origin) / plane.cell)), 0, bins_ - 1);
      for (int j = b0.y; j <= b1.y; ++j)
        for (int i = b0.x; i <= b1.x; ++i) visit(std::size_t(j) * std::size_t(bins_) + std::size_t(i));
    };
    for (const glm::uvec3& t : soup.triangles) for_bins(t, [&](std::size_t i) { ++plane.start[i + 1]; });
    for (std::size_t i = 0; i + 1 < plane.start.size(); ++i) plane.start[i + 1] += plane.start[i];
    plane.items.assign(plane.start.back(), 0);
    std::vector<std::uint32_t> fill(plane.start.begin(), plane.start.end() - 1);
    for (std::uint32_t k = 0; k < soup.triangles.size(); ++k)
      for_bins(soup.triangles[k], [&](std::size_t i) { plane.items[fill[i]++] = k; });
  }
}

bool WindingIndex::line_bin(const glm::vec3& point, int axis, glm::dvec2& q, std::size_t& cell) const {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Plane& plane = planes_[axis];
  // Irrational-looking offsets make exact hits on shared edges and vertices vanishingly rare.
  q = glm::dvec2(double(point[u]) + 0.7071067811 * double(nudge_), double(point[v]) + 0.5772156649 * double(nudge_));
  const glm::ivec2 bin = glm::ivec2(glm::floor((glm::vec2(q) - plane.origin) / plane.cell));
  if (bin.x < 0 || bin.y < 0 || bin.x >= bins_ || bin.y >= bins_) return false;
  cell = std::size_t(bin.y) * std::size_t(bins_) + std::size_t(bin.x);
  return true;
}

int WindingIndex::winding(const glm::vec3& p, int axis) const {
  const Plane& plane = planes_[axis];
  glm::dvec2 q;
  std::size_t cell = 0;
  if (!line_bin(p, axis, q, cell)) return 0;
  int winding = 0;
  for (std::uint32_t k = plane.start[cell]; k < plane.start[cell + 1]; ++k) {
    const glm::uvec3& t = soup_->triangles[plane.items[k]];
    double crossing = 0.0;
    int sign = 0;
    if (!line_crosses_triangle(soup_->positions[t.x], soup_->positions[t.y], soup_->positions[t.z], axis, q, crossing,
                               sign))
      continue;
    if (crossing > double(p[axis])) winding += sign;
  }
  return winding;
}

bool WindingIndex::inside(const glm::vec3& p) const {
  int votes = 0;
  for (int axis = 0; axis < 3; ++axis) votes += winding(p, axis) != 0 ? 1 : 0;
  return votes >= 2;
}

float DistanceGrid::sample(const glm::vec3& p) const {
  const glm::vec3 g = (p - origin) / cell;
  const glm::ivec3 i = glm::ivec3(glm::floor(g));
  if (i.x < 0 || i.y < 0 || i.z < 0 || i.x + 1 >= dims.x || i.y + 1 >= dims.y || i.z + 1 >= dims.z) return band;
  const glm::vec3 f = g - glm::vec3(i);
  auto at = [&](int x, int y, int z) {
    return values[(std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x) + std::size_t(x)];
  };
  const float c00 = glm::mix(at(i.x, i.y, i.z), at(i.x + 1, i.y, i.z), f.x);
  const float c10 = glm::mix(at(i.x, i.y + 1, i.z), at(i.x + 1, i.y + 1, i.z), f.x);
  const float c01 = glm::mix(at(i.x, i.y, i.z + 1), at(i.x + 1, i.y, i.z + 1), f.x);
  const float c11 = glm::mix(at(i.x, i.y + 1, i.z + 1), at(i.x + 1, i.y + 1, i.z + 1), f.x);
  return glm::mix(glm::mix(c00, c10, f.y), glm::mix(c01, c11, f.y), f.z);
}

void WindingIndex::winding_along_line(const glm::vec3& origin, int axis, float step, std::span<int> out) const {
  const Plane& plane = planes_[axis];
  std::fill(out.begin(), out.end(), 0);
  glm::dvec2 q;
  std::size_t cell = 0;
  if (!line_bin(origin, axis, q, cell)) return;
  for (std::uint32_t k = plane.start[cell]; k < plane.start[cell + 1]; ++k) {
    const glm::uvec3& t = soup_->triangles[plane.items[k]];
    double crossing = 0.0;
    int sign = 0;
    if (!line_crosses_triangle(soup_->positions[t.x], soup_->positions[t.y], soup_->positions[t.z], axis, q, crossing,
                               sign))
      continue;
    // Nodes strictly before the crossing count it: i * step < crossing - origin.
    const double first_after = std::ceil((crossing - double(origin[axis])) / double(step));  // first i not counting it
    const long last = std::min(long(out.size()), long(first_after));
    for (long i = 0; i < last; ++i) out[std::size_t(i)] += sign;
  }
}

DistanceGrid build_distance_grid(const TriangleSoup& soup, const WindingIndex& winding, const Box& box,
                                 float cell, float band) {
  DistanceGrid grid;
  grid.cell = cell;
  grid.band = band;
  grid.origin = box.lo - glm::vec3(band);
  grid.dims = glm::ivec3(glm::ceil((box.hi - box.lo + 2.0f * band) / cell)) + 1;
  const glm::ivec3 dims = grid.dims;
  const std::size_t count = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
  auto index = [&](int x, int y, int z) {
    return (std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x) + std::size_t(x);
  };
  auto node = [&](int x, int y, int z) { return grid.origin + glm::vec3(x, y, z) * cell; };
  std::vector<float> distance(count, std::numeric_limits<float>::max());
  std::vector<std::int32_t> nearest(count, -1);
  auto distance_to = [&](const glm::vec3& p, std::int32_t t) {
    const glm::uvec3& tri = soup.triangles[std::size_t(t)];
    return glm::length(p - closest_point_on_triangle(p, soup.positions[tri.x], soup.positions[tri.y], soup.positions[tri.z]));
  };
  // Exact near the surface.
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const glm::uvec3& tri = soup.triangles[t];
    const glm::vec3 lo = glm::min(glm::min(soup.positions[tri.x], soup.positions[tri.y]), soup.positions[tri.z]);
    const glm::vec3 hi = glm::max(glm::max(soup.positions[tri.x], soup.positions[tri.y]), soup.positions[tri.z]);
    const glm::ivec3 a = glm::clamp(glm::ivec3(glm::floor((lo - grid.origin) / cell)) - 1, glm::ivec3(0), dims - 1);
    const glm::ivec3 b = glm::clamp(glm::ivec3(glm::ceil((hi - grid.origin) / cell)) + 1, glm::ivec3(0), dims - 1);
    for (int z = a.z; z <= b.z; ++z)
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) {
          const std::size_t i = index(x, y, z);
          const float d = distance_to(node(x, y, z), std::int32_t(t));
          if (d < distance[i]) distance[i] = d, nearest[i] = std::int32_t(t);
        }
  }
  // Sweeps: the 13 neighbours already visited in raster order (then in reverse order).
  std::vector<glm::ivec3> causal;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (dz < 0 || (dz == 0 && (dy < 0 || (dy == 0 && dx < 0)))) causal.emplace_back(dx, dy, dz);
  constexpr float kDiagonalStep = 1.7320508f;
  auto relax = [&](int x, int y, int z, int sign) {
    const std::size_t i = index(x, y, z);
    const glm::vec3 p = node(x, y, z);
    for (const glm::ivec3& o : causal) {
      const glm::ivec3 n = glm::ivec3(x, y, z) + sign * o;
      if (n.x < 0 || n.y < 0 || n.z < 0 || n.x >= dims.x || n.y >= dims.y || n.z >= dims.z) continue;
      const std::size_t j = index(n.x, n.y, n.z);
      const std::int32_t t = nearest[j];
      if (t < 0 || t == nearest[i]) continue;
      // The neighbour's triangle is at least its distance minus the step away: skip when that
      // cannot beat what this node has (or the band, beyond which values are clamped).
      if (distance[j] - kDiagonalStep * cell >= std::min(distance[i], band)) continue;
      const float d = distance_to(p, t);
      if (d < distance[i]) distance[i] = d, nearest[i] = t;
    }
  };
  for (int pass = 0; pass < 2; ++pass) {
    for (int z = 0; z < dims.z; ++z)
      for (int y = 0; y < dims.y; ++y)
        for (int x = 0; x < dims.x; ++x) relax(x, y, z, 1);
    for (int z = dims.z - 1; z >= 0; --z)
      for (int y = dims.y - 1; y >= 0; --y)
        for (int x = dims.x - 1; x >= 0; --x) relax(x, y, z, -1);
  }
  // Signs: majority of the three axis winding numbers, one grid line at a time.
  std::vector<std::uint8_t> votes(count, 0);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::vector<int> line(static_cast<std::size_t>(dims[axis]));
    for (int j = 0; j < dims[v]; ++j)
      for (int i = 0; i < dims[u]; ++i) {
        glm::ivec3 c(0);
        c[u] = i, c[v] = j;
        winding.winding_along_line(node(c.x, c.y, c.z), axis, cell, line);
        for (int k = 0; k < dims[axis]; ++k) {
          c[axis] = k;
          votes[index(c.x, c.y, c.z)] += line[std::size_t(k)] != 0 ? 1 : 0;
        }
      }
  }
  grid.values.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const float d = std::min(distance[i], band);
    grid.values[i] = votes[i] >= 2 ? -d : d;
  }
  return grid;
}

}  // namespace proxygi::proxies
