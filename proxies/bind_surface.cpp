#include "proxies/bind_surface.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

namespace proxygi::proxies {
namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

float srgb_to_linear(std::uint8_t encoded) {
  const float c = float(encoded) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Key for welding: the exact bit pattern of a position (glTF splits vertices at UV and normal
// seams without moving them, so equal bits is what "same point" means there).
struct PositionKey {
  std::uint32_t x, y, z;
  bool operator==(const PositionKey&) const = default;
};
struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    return (std::size_t(k.x) * 73856093u) ^ (std::size_t(k.y) * 19349663u) ^ (std::size_t(k.z) * 83492791u);
  }
};
PositionKey key_of(const glm::vec3& p) {
  PositionKey k{};
  const glm::vec3 q = p + glm::vec3(0.0f);  // folds -0 into +0
  std::memcpy(&k.x, &q.x, 4);
  std::memcpy(&k.y, &q.y, 4);
  std::memcpy(&k.z, &q.z, 4);
  return k;
}

// Welds the soup with OpenMesh, measures areas and open edges.
void analyse_with_openmesh(BindSurface& surface) {
  OmMesh mesh;
  std::unordered_map<PositionKey, OmMesh::VertexHandle, PositionKeyHash> welded;
  std::vector<OmMesh::VertexHandle> handle_of(surface.soup.positions.size());
  for (std::size_t i = 0; i < surface.soup.positions.size(); ++i) {
    const glm::vec3& p = surface.soup.positions[i];
    auto [it, added] = welded.try_emplace(key_of(p));
    if (added) it->second = mesh.add_vertex(OmMesh::Point(p.x, p.y, p.z));
    handle_of[i] = it->second;
  }
  surface.welded_vertices = int(mesh.n_vertices());
  surface.triangle_area.assign(surface.soup.triangles.size(), 0.0f);
  // Refused faces are counted below; OpenMesh's own per-face messages would only be noise.
  const bool was_enabled = omerr().is_enabled();
  omerr().disable();
  for (std::size_t t = 0; t < surface.soup.triangles.size(); ++t) {
    const glm::uvec3& tri = surface.soup.triangles[t];
    OmMesh::VertexHandle v[3] = {handle_of[tri.x], handle_of[tri.y], handle_of[tri.z]};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;  // zero area after welding
    OmMesh::FaceHandle face = mesh.add_face(v[0], v[1], v[2]);
    if (!face.is_valid()) {
      // Non-manifold edge or vertex: keep the triangle's area with detached corners.
      ++surface.non_manifold_faces;
      for (auto& h : v) h = mesh.add_vertex(mesh.point(h));
      face = mesh.add_face(v[0], v[1], v[2]);
    }
    if (face.is_valid()) surface.triangle_area[t] = float(mesh.calc_sector_area(mesh.halfedge_handle(face)));
  }
  if (was_enabled) omerr().enable();
  int boundary = 0;
  for (auto edge : mesh.edges()) boundary += mesh.is_boundary(edge) ? 1 : 0;
  surface.boundary_edges = boundary;
}

}  // namespace

void accumulate(std::vector<std::pair<int, float>>& sum, int node, float weight) {
  if (weight <= 0.0f || node < 0) return;
  for (auto& [n, w] : sum)
    if (n == node) {
      w += weight;
      return;
    }
  sum.emplace_back(node, weight);
}

Influences to_influences(std::vector<std::pair<int, float>> sum) {
  std::sort(sum.begin(), sum.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second > b.second : a.first < b.first;
  });
  if (sum.size() > std::size_t(kMaxInfluences)) sum.resize(kMaxInfluences);
  float total = 0.0f;
  for (const auto& entry : sum) total += entry.second;
  Influences out;
  for (std::size_t k = 0; k < sum.size(); ++k) {
    out.nodes[k] = sum[k].first;
    out.weights[k] = total > 0.0f ? sum[k].second / total : 0.0f;
  }
  return out;
}

std::vector<glm::mat4> rest_world_matrices(const anim::Character& character) {
  std::vector<glm::mat4> world(character.nodes.size(), glm::mat4(1.0f));
  for (int n : character.evaluation_order) {
    const anim::Node& node = character.nodes[std::size_t(n)];
    const glm::mat4 local = node.matrix ? *node.matrix : anim::to_matrix(node.rest);
    world[std::size_t(n)] = node.parent >= 0 ? world[std::size_t(node.parent)] * local : local;
  }
  return world;
}

std::vector<glm::mat4> bind_to_bone_matrices(const anim::Character& character,
                                             const std::vector<glm::mat4>& rest_world) {
  std::vector<glm::mat4> out(character.nodes.size());
  std::vector<bool> is_joint(character.nodes.size(), false);
  for (std::size_t n = 0; n < out.size(); ++n) out[n] = glm::inverse(rest_world[n]);
  for (const anim::Skin& skin : character.skins)
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
      const std::size_t node = std::size_t(skin.joints[j]);
      if (node >= out.size() || is_joint[node]) continue;  // the first skin listing a joint wins
      is_joint[node] = true;
      out[node] = j < skin.inverse_bind_matrices.size() ? skin.inverse_bind_matrices[j] : glm::mat4(1.0f);
    }
  return out;
}

glm::vec3 base_color(const anim::Character& character, int material, const glm::vec2& uv) {
  if (material < 0 || material >= int(character.materials.size())) return glm::vec3(1.0f);
  const anim::Material& m = character.materials[std::size_t(material)];
  glm::vec3 color(m.base_color_factor);
  if (m.base_color_image < 0 || m.base_color_image >= int(character.images.size())) return color;
  const anim::Image& image = character.images[std::size_t(m.base_color_image)];
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() < std::size_t(image.width) * std::size_t(image.height) * 4)
    return color;
  // Bilinear with repeat wrapping, texel centers at half-integers; blend in linear space.
  const float x = uv.x * float(image.width) - 0.5f, y = uv.y * float(image.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  auto texel = [&](int ix, int iy) {
    ix = ((ix % image.width) + image.width) % image.width;
    iy = ((iy % image.height) + image.height) % image.height;
    const std::uint8_t* p = &image.rgba[(std::size_t(iy) * std::size_t(image.width) + std::size_t(ix)) * 4];
    return glm::vec3(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]));
  };
  const int ix = int(fx), iy = int(fy);
  const glm::vec3 t = glm::mix(glm::mix(texel(ix, iy), texel(ix + 1, iy), tx),
                               glm::mix(texel(ix, iy + 1), texel(ix + 1, iy + 1), tx), ty);
  return color * t;
}

Result<BindSurface> extract_bind_surface(const anim::Character& character) {
  BindSurface surface;
  const std::vector<glm::mat4> rest_world = rest_world_matrices(character);
  const std::size_t node_count = character.nodes.size();
  surface.bind_to_bone = bind_to_bone_matrices(character, rest_world);
  surface.vertex_count_per_bone.assign(node_count, 0);

  for (std::size_t n = 0; n < node_count; ++n) {
    const anim::Node& node = character.nodes[n];
    if (node.mesh < 0) continue;
    if (node.mesh >= int(character.meshes.size()))
      return make_error(character.source + ": node " + std::to_string(n) + ": mesh " + std::to_string(node.mesh) + " out of range");
    const anim::Mesh& mesh = character.meshes[std::size_t(node.mesh)];
    const anim::Skin* skin = nullptr;
    if (node.skin >= 0) {
      if (node.skin >= int(character.skins.size()))
        return make_error(character.source + ": node " + std::to_string(n) + ": skin " + std::to_string(node.skin) + " out of range");
      skin = &character.skins[std::size_t(node.skin)];
    }
    for (std::size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const anim::Primitive& prim = mesh.primitives[pi];
      const std::string where = character.source + ": mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(pi);
      const bool skinned = skin != nullptr && prim.influences_per_vertex > 0;
      const std::size_t base = surface.soup.positions.size();
      const std::size_t per = std::size_t(std::max(prim.influences_per_vertex, 0));
      if (skinned && (prim.joints.size() < prim.positions.size() * per || prim.weights.size() < prim.positions.size() * per))
        return make_error(where + ": joints/weights shorter than vertex count × influences");
      for (std::size_t v = 0; v < prim.positions.size(); ++v) {
        const glm::vec3 p = prim.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          return make_error(where + ": vertex " + std::to_string(v) + ": position is not finite");
        std::vector<std::pair<int, float>> sum;
        if (skinned) {
          for (std::size_t k = 0; k < per; ++k) {
            const int joint = prim.joints[v * per + k];
            const float w = prim.weights[v * per + k];
            if (w <= 0.0f) continue;
            if (joint >= int(skin->joints.size()))
              return make_error(where + ": vertex " + std::to_string(v) + ": joint " + std::to_string(joint) +
                                " out of range (" + std::to_string(skin->joints.size()) + " joints)");
            const int bone = skin->joints[std::size_t(joint)];
            accumulate(sum, bone, w);
          }
          surface.soup.positions.push_back(p);
        } else {
          surface.soup.positions.push_back(glm::vec3(rest_world[n] * glm::vec4(p, 1.0f)));
        }
        if (sum.empty()) {
          // Unskinned: rigid to the mesh's own node, whose bone space is its local frame.
          accumulate(sum, int(n), 1.0f);
        }
        surface.influences.push_back(to_influences(std::move(sum)));
        ++surface.vertex_count_per_bone[std::size_t(surface.influences.back().dominant())];
        surface.uvs.push_back(v < prim.uvs.size() ? prim.uvs[v] : glm::vec2(0.0f));
      }
      for (std::size_t t = 0; t + 2 < prim.indices.size(); t += 3) {
        const glm::uvec3 tri(prim.indices[t], prim.indices[t + 1], prim.indices[t + 2]);
        if (tri.x >= prim.positions.size() || tri.y >= prim.positions.size() || tri.z >= prim.positions.size())
          return make_error(where + ": triangle " + std::to_string(t / 3) + ": index out of range");
        surface.soup.triangles.push_back(tri + glm::uvec3(std::uint32_t(base)));
        surface.triangle_material.push_back(prim.material);
      }
    }
  }
  if (surface.soup.triangles.empty()) return make_error(character.source + ": no triangles to fit proxies to");
  analyse_with_openmesh(surface);
  if (surface.boundary_edges > 0)
    surface.warnings.push_back(character.source + ": surface is open (" + std::to_string(surface.boundary_edges) +
                               " boundary edges after welding): inside tests use a 3-ray majority vote");
  return surface;
}

}  // namespace proxygi::proxies
