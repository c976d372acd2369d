// Vertex normals for primitives without NORMAL: OpenMesh computes each triangle's normal, and a
// vertex takes the normalized sum over its triangles (OpenMesh's own vertex-normal rule).
// Triangles go into OpenMesh on their own three vertices: glTF triangle soups are often not
// manifold, and OpenMesh's add_face asserts (aborts, in Debian's build) on some such
// connectivity instead of returning an invalid handle; normals need no connectivity.
#include <array>
#include <cmath>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "anim/import_context.h"

namespace proxygi::anim::detail {
namespace {

struct NormalTraits : OpenMesh::DefaultTraits {
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<NormalTraits>;

}  // namespace

std::vector<glm::vec3> compute_vertex_normals(const std::vector<glm::vec3>& positions,
                                              const std::vector<std::uint32_t>& indices) {
  TriMesh mesh;
  std::vector<std::array<std::uint32_t, 3>> corners;  // OpenMesh face -> primitive vertices
  corners.reserve(indices.size() / 3);
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::array<std::uint32_t, 3> triangle = {indices[t], indices[t + 1], indices[t + 2]};
    if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2]) continue;
    std::array<TriMesh::VertexHandle, 3> handles;
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::vec3& p = positions[triangle[k]];
      handles[k] = mesh.add_vertex(TriMesh::Point(p.x, p.y, p.z));
    }
    mesh.add_face(handles[0], handles[1], handles[2]);
    corners.push_back(triangle);
  }
  mesh.update_face_normals();

  std::vector<glm::dvec3> sums(positions.size(), glm::dvec3(0.0));
  for (const auto face : mesh.faces()) {
    const auto& n = mesh.normal(face);
    if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) continue;
    for (std::uint32_t v : corners[static_cast<std::size_t>(face.idx())]) sums[v] += glm::dvec3(n[0], n[1], n[2]);
  }
  std::vector<glm::vec3> normals(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const double length = glm::length(sums[v]);
    normals[v] = length > 1e-12 && std::isfinite(length) ? glm::vec3(sums[v] / length) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return normals;
}

}  // namespace proxygi::anim::detail
