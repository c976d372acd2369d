#include "proxies/sphere_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "base/atomic_file.h"

namespace proxygi::proxies {

void append_sphere_geometry(std::span<const WorldSphere> spheres, int segments, SphereGeometry& out) {
  const int around = std::max(segments, 3);
  const int rings = std::max(around / 2, 2);
  for (const WorldSphere& s : spheres) {
    const std::uint32_t base = std::uint32_t(out.positions.size());
    for (int r = 0; r <= rings; ++r) {
      const float theta = std::numbers::pi_v<float> * float(r) / float(rings);
      for (int a = 0; a <= around; ++a) {
        const float phi = 2.0f * std::numbers::pi_v<float> * float(a) / float(around);
        const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
        out.positions.push_back(s.center + s.radius * n);
        out.normals.push_back(n);
        out.colors.push_back(s.albedo);
      }
    }
    const std::uint32_t stride = std::uint32_t(around + 1);
    for (int r = 0; r < rings; ++r)
      for (int a = 0; a < around; ++a) {
        const std::uint32_t i0 = base + std::uint32_t(r) * stride + std::uint32_t(a), i1 = i0 + 1;
        const std::uint32_t j0 = i0 + stride, j1 = j0 + 1;
        if (r > 0) out.indices.insert(out.indices.end(), {i0, j0, i1});
        if (r + 1 < rings) out.indices.insert(out.indices.end(), {i1, j0, j1});
      }
  }
}

Status write_spheres_obj(const std::filesystem::path& path, std::span<const WorldSphere> spheres, int segments) {
  std::string text = "# proxygi sphere proxies\n";
  char line[160];
  std::uint32_t offset = 1;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    SphereGeometry g;
    append_sphere_geometry(spheres.subspan(i, 1), segments, g);
    text += "g sphere_" + std::to_string(i) + "\n";
    for (std::size_t v = 0; v < g.positions.size(); ++v) {
      std::snprintf(line, sizeof line, "v %.6g %.6g %.6g %.4g %.4g %.4g\n", double(g.positions[v].x), double(g.positions[v].y),
                    double(g.positions[v].z), double(g.colors[v].r), double(g.colors[v].g), double(g.colors[v].b));
      text += line;
    }
    for (const glm::vec3& n : g.normals) {
      std::snprintf(line, sizeof line, "vn %.5g %.5g %.5g\n", double(n.x), double(n.y), double(n.z));
      text += line;
    }
    for (std::size_t t = 0; t < g.indices.size(); t += 3) {
      const std::uint32_t a = g.indices[t] + offset, b = g.indices[t + 1] + offset, c = g.indices[t + 2] + offset;
      std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", a, a, b, b, c, c);
      text += line;
    }
    offset += std::uint32_t(g.positions.size());
  }
  return write_file_atomically(path, text);
}

}  // namespace proxygi::proxies
