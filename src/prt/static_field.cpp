#include "prt/static_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/product.h"

namespace proxygi::prt {

std::size_t StaticTransferField::bytes() const {
  return positions.size() * sizeof(glm::vec3) * 2 + triangles.size() * (sizeof(glm::uvec3) + sizeof(glm::vec3)) +
         (shadowed.size() + interreflected.size()) * sizeof(float) +
         (grid.cell_first.size() + grid.cell_triangles.size()) * sizeof(std::uint32_t);
}

namespace {

StaticGrid build_grid(const StaticTransferField& field, float spacing_m) {
  StaticGrid grid;
  if (field.triangles.empty()) return grid;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : field.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  lo -= glm::vec3(2.0f * kStaticHitDistance);
  hi += glm::vec3(2.0f * kStaticHitDistance);
  float cell = std::max(kStaticGridCellsPerSpacing * spacing_m, 1e-3f);
  glm::uvec3 size;
  for (;;) {
    size = glm::uvec3(glm::max(glm::ceil((hi - lo) / cell), glm::vec3(1.0f)));
    if (double(size.x) * double(size.y) * double(size.z) <= double(kStaticGridMaxCells)) break;
    cell *= 1.5f;
  }
  grid.origin = lo;
  grid.cell = cell;
  grid.size = size;
  const std::size_t cells = std::size_t(size.x) * size.y * size.z;
  auto cell_range = [&](std::size_t t, glm::ivec3& first, glm::ivec3& last) {
    const glm::uvec3 tri = field.triangles[t];
    const glm::vec3 a = field.positions[tri.x], b = field.positions[tri.y], c = field.positions[tri.z];
    const glm::vec3 tlo = glm::min(a, glm::min(b, c)) - glm::vec3(kStaticHitDistance);
    const glm::vec3 thi = glm::max(a, glm::max(b, c)) + glm::vec3(kStaticHitDistance);
    first = glm::clamp(glm::ivec3(glm::floor((tlo - lo) / cell)), glm::ivec3(0), glm::ivec3(size) - 1);
    last = glm::clamp(glm::ivec3(glm::floor((thi - lo) / cell)), glm::ivec3(0), glm::ivec3(size) - 1);
  };
  auto cell_index = [&](int x, int y, int z) { return (std::size_t(z) * size.y + std::size_t(y)) * size.x + std::size_t(x); };
  std::vector<std::uint32_t> counts(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> cursor;
    if (pass == 1) {
      grid.cell_first.assign(cells + 1, 0);
      for (std::size_t i = 0; i < cells; ++i) grid.cell_first[i + 1] = grid.cell_first[i] + counts[i];
      grid.cell_triangles.resize(grid.cell_first[cells]);
      cursor.assign(grid.cell_first.begin(), grid.cell_first.end() - 1);
    }
    for (std::size_t t = 0; t < field.triangles.size(); ++t) {
      if (field.triangle_normals[t] == glm::vec3(0.0f)) continue;  // degenerate
      glm::ivec3 first, last;
      cell_range(t, first, last);
      for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
          for (int x = first.x; x <= last.x; ++x) {
            const std::size_t i = cell_index(x, y, z);
            if (pass == 0) ++counts[i];
            else grid.cell_triangles[cursor[i]++] = std::uint32_t(t);
          }
    }
  }
  return grid;
}

}  // namespace

Result<std::shared_ptr<const StaticTransferField>> make_static_field(const StaticReceivers& receivers,
                                                                     const TransferSet& transfer, float spacing_m) {
  if (transfer.surfaces.size() != receivers.surfaces.size())
    return make_error("prt: transfer has " + std::to_string(transfer.surfaces.size()) + " surfaces, receivers " +
                      std::to_string(receivers.surfaces.size()));
  auto field = std::make_shared<StaticTransferField>();
  field->order = transfer.order;
  const std::size_t nn = std::size_t(transfer.order * transfer.order);
  for (std::size_t s = 0; s < receivers.surfaces.size(); ++s) {
    const StaticSurface& surface = receivers.surfaces[s];
    const SurfaceTransfer& t = transfer.surfaces[s];
    const std::size_t n = surface.positions.size();
    if (t.shadowed.size() != n * nn || t.interreflected.size() != 3 * n * nn)
      return make_error("prt: " + surface.name + ": transfer does not match its " + std::to_string(n) + " vertices");
    const std::uint32_t base = std::uint32_t(field->positions.size());
    field->positions.insert(field->positions.end(), surface.positions.begin(), surface.positions.end());
    field->normals.insert(field->normals.end(), surface.normals.begin(), surface.normals.end());
    field->shadowed.insert(field->shadowed.end(), t.shadowed.begin(), t.shadowed.end());
    field->interreflected.insert(field->interreflected.end(), t.interreflected.begin(), t.interreflected.end());
    for (std::size_t i = 0; i + 2 < surface.indices.size(); i += 3) {
      const glm::uvec3 tri(base + surface.indices[i], base + surface.indices[i + 1], base + surface.indices[i + 2]);
      const glm::vec3 a = field->positions[tri.x], b = field->positions[tri.y], c = field->positions[tri.z];
      glm::vec3 n_t = glm::cross(b - a, c - a);
      const float length = glm::length(n_t);
      n_t = length > 1e-12f ? n_t / length : glm::vec3(0.0f);
      if (glm::dot(n_t, field->normals[tri.x] + field->normals[tri.y] + field->normals[tri.z]) < 0.0f) n_t = -n_t;
      field->triangles.push_back(tri);
      field->triangle_normals.push_back(n_t);
    }
  }
  field->grid = build_grid(*field, spacing_m);
  return std::shared_ptr<const StaticTransferField>(std::move(field));
}

std::vector<float> bake_static_records(const StaticTransferField& field, const sh::RgbSh& lighting) {
  const int order = field.order;
  const std::size_t nn = std::size_t(order * order);
  const std::size_t stride = static_record_floats(order);
  std::vector<float> records(field.positions.size() * stride);
  std::array<std::vector<float>, 3> light;
  for (int c = 0; c < 3; ++c)
    light[std::size_t(c)].assign(lighting.channels[std::size_t(c)].begin(), lighting.channels[std::size_t(c)].begin() + long(nn));
  std::vector<float> product(nn);
  for (std::size_t v = 0; v < field.positions.size(); ++v) {
    float* out = records.data() + v * stride;
    const std::span<const float> t(field.shadowed.data() + v * nn, nn);
    for (int c = 0; c < 3; ++c) {
      sh::product(order, light[std::size_t(c)], t, product);
      std::copy(product.begin(), product.end(), out + std::size_t(c) * nn);
    }
    const std::vector<double> h = sh::clamped_cosine_about(order, glm::dvec3(field.normals[v]));
    for (std::size_t i = 0; i < nn; ++i) out[3 * nn + i] = float(h[i]) - t[i];
    for (int c = 0; c < 3; ++c) {
      const std::span<const float> t_di(field.interreflected.data() + (v * 3 + std::size_t(c)) * nn, nn);
      const std::span<const float> l = light[std::size_t(c)];
      const float t_di_l = dot_coefficients(t_di, l, nn);
      out[4 * nn + std::size_t(c)] = t_di_l - dot_coefficients(t, l, nn);
      out[4 * nn + 3 + std::size_t(c)] = t_di_l;
    }
  }
  return records;
}

std::optional<StaticHit> find_static_hit(const StaticTransferField& field, const glm::vec3& p, const glm::vec3& normal) {
  const StaticGrid& grid = field.grid;
  if (grid.size.x == 0) return std::nullopt;
  const glm::vec3 cell_f = glm::floor((p - grid.origin) / grid.cell);
  if (cell_f.x < 0.0f || cell_f.y < 0.0f || cell_f.z < 0.0f || cell_f.x >= float(grid.size.x) ||
      cell_f.y >= float(grid.size.y) || cell_f.z >= float(grid.size.z))
    return std::nullopt;
  const glm::uvec3 cell(cell_f);
  const std::size_t index = (std::size_t(cell.z) * grid.size.y + cell.y) * grid.size.x + cell.x;
  std::optional<StaticHit> best;
  float best_distance = kStaticHitDistance;
  for (std::uint32_t k = grid.cell_first[index]; k < grid.cell_first[index + 1]; ++k) {
    const std::uint32_t t = grid.cell_triangles[k];
    const glm::vec3 n_t = field.triangle_normals[t];
    if (!(glm::dot(normal, n_t) > kStaticHitCosine)) continue;
    const glm::uvec3 tri = field.triangles[t];
    const glm::vec3 a = field.positions[tri.x];
    const float d = glm::dot(p - a, n_t);
    if (!(std::abs(d) <= best_distance)) continue;
    if (best && !(std::abs(d) < best_distance)) continue;
    const glm::vec3 v0 = field.positions[tri.y] - a, v1 = field.positions[tri.z] - a, v2 = (p - d * n_t) - a;
    const float d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const float d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const float denominator = d00 * d11 - d01 * d01;
    if (!(denominator > 0.0f)) continue;
    const float wb = (d11 * d20 - d01 * d21) / denominator, wc = (d00 * d21 - d01 * d20) / denominator;
    const float wa = 1.0f - wb - wc;
    if (wa < -kStaticHitBarycentricSlack || wb < -kStaticHitBarycentricSlack || wc < -kStaticHitBarycentricSlack) continue;
    best = StaticHit{t, glm::vec3(wa, wb, wc)};
    best_distance = std::abs(d);
  }
  return best;
}

std::vector<float> interpolate_record(const StaticTransferField& field, std::span<const float> records,
                                      const StaticHit& hit) {
  const std::size_t stride = static_record_floats(field.order);
  const glm::uvec3 tri = field.triangles[hit.triangle];
  std::vector<float> out(stride);
  const float* a = records.data() + std::size_t(tri.x) * stride;
  const float* b = records.data() + std::size_t(tri.y) * stride;
  const float* c = records.data() + std::size_t(tri.z) * stride;
  for (std::size_t i = 0; i < stride; ++i) out[i] = hit.weights.x * a[i] + hit.weights.y * b[i] + hit.weights.z * c[i];
  return out;
}

glm::vec3 shade_static_direct(int order, StaticTransferLevel level, std::span<const float> record,
                              std::span<const float> occlusion, const std::array<std::vector<float>, 3>& lighting_lh) {
  const std::size_t nn = std::size_t(order * order);
  const float sqrt_four_pi = float(sh::kSqrtFourPi);
  glm::vec3 out(0.0f);
  if (level == StaticTransferLevel::ratio) {
    for (int c = 0; c < 3; ++c) {
      const std::span<const float> lh = lighting_lh[std::size_t(c)];
      const float unshadowed = std::max(sqrt_four_pi * lh[0], 0.0f);
      const float shadowed = std::clamp(dot_coefficients(occlusion, lh, nn), 0.0f, unshadowed);
      out[c] = unshadowed > 0.0f ? std::max(shadowed * record[4 * nn + 3 + std::size_t(c)] / unshadowed, 0.0f) : 0.0f;
    }
    return out;
  }
  const float kappa = unblocked_fraction_of_blocked(order, record.subspan(3 * nn, nn), occlusion);
  for (int c = 0; c < 3; ++c) {
    const float e = dot_coefficients(occlusion, record.subspan(std::size_t(c) * nn, nn), nn) + kappa * record[4 * nn + std::size_t(c)];
    out[c] = std::max(e, 0.0f);
  }
  return out;
}

}  // namespace proxygi::prt
