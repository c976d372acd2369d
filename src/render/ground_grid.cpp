#include "render/ground_grid.h"

#include <algorithm>
#include <cmath>

#include "scene/character_motion.h"

namespace proxygi::render {
namespace {

// Sorted grid-line coordinates along one axis: the edges ±half and the fine lines inside.
std::vector<float> axis_lines(float half, float low, float high, float density) {
  std::vector<float> lines{-half};
  low = std::max(low, -half);
  high = std::min(high, half);
  if (high > low) {
    const int cells = std::max(1, int(std::ceil((high - low) * density)));
    for (int i = 0; i <= cells; ++i) {
      const float x = low + (high - low) * float(i) / float(cells);
      if (x > lines.back()) lines.push_back(x);
    }
  }
  if (half > lines.back()) lines.push_back(half);
  return lines;
}

}  // namespace

GroundGrid make_ground_grid(float size, glm::vec2 fine_min, glm::vec2 fine_max, float vertices_per_metre) {
  const float half = 0.5f * size;
  const std::vector<float> xs = axis_lines(half, fine_min.x, fine_max.x, vertices_per_metre);
  const std::vector<float> zs = axis_lines(half, fine_min.y, fine_max.y, vertices_per_metre);
  GroundGrid grid;
  grid.lines_x = int(xs.size());
  grid.lines_z = int(zs.size());
  std::vector<std::uint32_t> index_of(xs.size() * zs.size());
  for (std::size_t block_z = 0; block_z < zs.size(); block_z += 8)
    for (std::size_t block_x = 0; block_x < xs.size(); block_x += 8)
      for (std::size_t z = block_z; z < std::min(block_z + 8, zs.size()); ++z)
        for (std::size_t x = block_x; x < std::min(block_x + 8, xs.size()); ++x) {
          index_of[z * xs.size() + x] = std::uint32_t(grid.positions.size());
          grid.positions.emplace_back(xs[x], 0.0f, zs[z]);
          grid.normals.emplace_back(0.0f, 1.0f, 0.0f);
        }
  for (std::size_t z = 0; z + 1 < zs.size(); ++z)
    for (std::size_t x = 0; x + 1 < xs.size(); ++x) {
      const std::uint32_t corner = index_of[z * xs.size() + x], next_x = index_of[z * xs.size() + x + 1];
      const std::uint32_t next_z = index_of[(z + 1) * xs.size() + x], far = index_of[(z + 1) * xs.size() + x + 1];
      grid.indices.insert(grid.indices.end(), {corner, next_z, next_x, next_x, next_z, far});
    }
  return grid;
}

GroundRegion ground_fine_region(const scene::Scene& scene) {
  GroundRegion region;
  if (scene.characters.empty()) return region;  // nothing casts: no fine region
  glm::vec2 low(1e30f), high(-1e30f);
  for (const auto& character : scene.characters)
    for (int frame = 0; frame < scene.output.frame_count; ++frame) {
      const glm::vec3 root = scene::character_root_position(
          character, scene::frame_time_s(scene.output, scene.output.first_frame + frame));
      low = glm::min(low, glm::vec2(root.x, root.z));
      high = glm::max(high, glm::vec2(root.x, root.z));
    }
  region.min = low - kGroundMargin;
  region.max = high + kGroundMargin;
  const glm::vec2 extent = region.max - region.min;
  const float longest = std::max(extent.x, extent.y);
  region.vertices_per_metre = std::min(kGroundVerticesPerMetre, float(kGroundMaxFineLines - 1) / longest);
  return region;
}

}  // namespace proxygi::render
