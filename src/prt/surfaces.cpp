#include "prt/surfaces.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "base/log.h"
#include "render/texture_sampling.h"

namespace proxygi::prt {
namespace {

constexpr float kWeldM = 1e-5f;

// Welds vertices by position quantized to kWeldM and normal quantized to 1e-3.
class Welder {
 public:
  explicit Welder(StaticSurface& out) : out_(out) {}
  std::uint32_t add(const glm::vec3& p, const glm::vec3& n) {
    const glm::ivec3 qp(glm::round(p / kWeldM));
    const glm::ivec3 qn(glm::round(n * 1000.0f));
    std::uint64_t key = 1469598103934665603ull;
    for (int v : {qp.x, qp.y, qp.z, qn.x, qn.y, qn.z}) key = (key ^ std::uint64_t(std::uint32_t(v))) * 1099511628211ull;
    auto [it, inserted] = map_.try_emplace(key, std::uint32_t(out_.positions.size()));
    if (inserted) {
      out_.positions.push_back(p);
      out_.normals.push_back(n);
    }
    return it->second;
  }

 private:
  StaticSurface& out_;
  std::unordered_map<std::uint64_t, std::uint32_t> map_;
};

}  // namespace

StaticSurface subdivide(const StaticSurface& surface, float spacing_m) {
  StaticSurface out;
  out.name = surface.name;
  out.albedo = surface.albedo;
  Welder welder(out);
  for (std::size_t t = 0; t + 2 < surface.indices.size(); t += 3) {
    const std::uint32_t ia = surface.indices[t], ib = surface.indices[t + 1], ic = surface.indices[t + 2];
    const glm::vec3 a = surface.positions[ia], b = surface.positions[ib], c = surface.positions[ic];
    const glm::vec3 na = surface.normals[ia], nb = surface.normals[ib], nc = surface.normals[ic];
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const int m = std::max(1, int(std::ceil(longest / spacing_m)));
    // Vertex (i, j) of the m-grid: barycentric (1 - i/m - j/m, i/m, j/m).
    std::vector<std::uint32_t> grid;
    grid.reserve(std::size_t((m + 1) * (m + 2) / 2));
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i + j <= m; ++i) {
        const float u = float(i) / float(m), v = float(j) / float(m), w = 1.0f - u - v;
        const glm::vec3 n = w * na + u * nb + v * nc;
        const float len = glm::length(n);
        grid.push_back(welder.add(w * a + u * b + v * c, len > 0.0f ? n / len : na));
      }
    auto at = [&](int i, int j) {  // row j starts after rows 0..j-1 of m+1, m, ... entries
      const int row_start = j * (m + 1) - j * (j - 1) / 2;
      return grid[std::size_t(row_start + i)];
    };
    for (int j = 0; j < m; ++j)
      for (int i = 0; i + j < m; ++i) {
        out.indices.insert(out.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < m) out.indices.insert(out.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return out;
}

StaticSurface ground_patch(glm::vec2 patch_min, glm::vec2 patch_max, float spacing_m, const glm::vec3& albedo) {
  StaticSurface out;
  out.name = "ground";
  out.albedo = albedo;
  const glm::vec2 extent = patch_max - patch_min;
  const int nx = std::max(1, int(std::ceil(extent.x / spacing_m)));
  const int nz = std::max(1, int(std::ceil(extent.y / spacing_m)));
  for (int z = 0; z <= nz; ++z)
    for (int x = 0; x <= nx; ++x) {
      const glm::vec2 xz = patch_min + extent * glm::vec2(float(x) / float(nx), float(z) / float(nz));
      out.positions.emplace_back(xz.x, 0.0f, xz.y);
      out.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  const auto id = [&](int x, int z) { return std::uint32_t(z * (nx + 1) + x); };
  for (int z = 0; z < nz; ++z)
    for (int x = 0; x < nx; ++x)  // counter-clockwise seen from +Y
      out.indices.insert(out.indices.end(),
                         {id(x, z), id(x, z + 1), id(x + 1, z), id(x + 1, z), id(x, z + 1), id(x + 1, z + 1)});
  return out;
}

Result<StaticReceivers> static_receivers(const world::World& world, float spacing_m, float ground_margin_m) {
  if (!(spacing_m > 0.0f) || !std::isfinite(spacing_m))
    return make_error("prt spacing " + std::to_string(spacing_m) + " m: must be positive");
  StaticReceivers out;
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const world::StaticModel& model : world.static_models()) {
    for (const anim::PosedPrimitive& primitive : model.primitives) {
      const std::string name = "static_meshes[" + std::to_string(model.scene_static_mesh) + "]:" + primitive.name;
      if (primitive.normals.size() != primitive.positions.size()) {  // as the renderers do: skipped
        log_warning(name + ": no normals; not a PRT receiver");
        continue;
      }
      StaticSurface surface{name, primitive.positions, primitive.normals, primitive.indices, glm::vec3(1.0f)};
      const auto& materials = model.character.materials;
      if (model.albedo) {
        surface.albedo = *model.albedo;
      } else if (primitive.material >= 0 && std::size_t(primitive.material) < materials.size()) {
        const anim::Material& material = materials[std::size_t(primitive.material)];
        surface.albedo = glm::vec3(material.base_color_factor);
        if (material.base_color_image >= 0 && std::size_t(material.base_color_image) < model.character.images.size())
          surface.albedo *= render::mean_linear_color(model.character.images[std::size_t(material.base_color_image)]);
      }
      for (const glm::vec3& p : primitive.positions) {
        lo = glm::min(lo, glm::vec2(p.x, p.z));
        hi = glm::max(hi, glm::vec2(p.x, p.z));
      }
      out.surfaces.push_back(subdivide(surface, spacing_m));
    }
  }
  const scene::Ground& ground = world.scene().ground;
  if (ground.enabled) {
    const float half = 0.5f * ground.size;
    out.outer_ground = {true, half, glm::vec2(0.0f), glm::vec2(0.0f), ground.albedo};
    if (!out.surfaces.empty()) {
      const glm::vec2 patch_min = glm::max(lo - ground_margin_m, glm::vec2(-half));
      const glm::vec2 patch_max = glm::min(hi + ground_margin_m, glm::vec2(half));
      if (patch_min.x < patch_max.x && patch_min.y < patch_max.y) {
        out.surfaces.push_back(ground_patch(patch_min, patch_max, spacing_m, ground.albedo));
        out.outer_ground.patch_min = patch_min;
        out.outer_ground.patch_max = patch_max;
      }
    }
  }
  return out;
}

}  // namespace proxygi::prt
