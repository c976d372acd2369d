#pragma once
// What the G-buffer and the vertex receivers draw: world-space meshes on the GPU (skinned
// characters from the skin pass, static meshes uploaded once).
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "base/result.h"
#include "gpu/material_textures.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;

// One mesh draw of the G-buffer pass: world-space vec4 positions and normals, 32-bit indices;
// albedo = base_color × texture (gpu/material_textures.h) at the vertices' uvs.
struct DrawItem {
  const Buffer* positions = nullptr;
  const Buffer* normals = nullptr;
  const Buffer* indices = nullptr;
  std::uint32_t index_count = 0;
  glm::vec4 base_color{1.0f};   // linear albedo factor
  const Buffer* uvs = nullptr;  // vec2 TEXCOORD_0 per vertex; null: uv (0, 0)
  BaseColorTexture texture;     // null view: white
  // The VSGL light (render.indirect_method vsgl) this draw sends bounce light through: its
  // character's index (< gpu_layout::kVsglMaxLights); −1: not a sender (static meshes).
  int vsgl_light = -1;
  // render.vsgl_grouping bone_groups: the draw's triangles in bone-group order (anim/bone_groups.h;
  // 32-bit indices, storage usage) and the first triangle of each of its K lights then the end
  // (K + 1 entries, K = render.vsgl_lights). Empty: the lights take K index ranges of `indices`.
  const Buffer* vsgl_indices = nullptr;
  std::span<const std::uint32_t> vsgl_group_first;
  // The sender exposure of each vertex (float, storage usage; ref/sender_exposure.h): each VPL's
  // flux is scaled by its triangle's mean. Null: exposure 1 (test meshes, static meshes).
  const Buffer* vsgl_exposure = nullptr;
  // The draw's vertices in `positions` and `normals` (its instance's range of its model's skin
  // outputs, gpu/skin_pass.h SkinBatch): first_vertex .., with first_vertex × 16 bytes a
  // multiple of minStorageBufferOffsetAlignment; vertices 0: the whole buffers. Passes bind that
  // range (vertex_bytes), so their shaders index the draw's vertices from 0.
  std::uint32_t first_vertex = 0;
  std::uint32_t vertices = 0;
  std::uint32_t vertex_count() const {
    return vertices > 0 ? vertices : positions ? std::uint32_t(positions->size() / sizeof(glm::vec4)) : 0;
  }
  BufferRange vertex_bytes() const {
    return {VkDeviceSize(first_vertex) * sizeof(glm::vec4), VkDeviceSize(vertex_count()) * sizeof(glm::vec4)};
  }
  bool textured() const { return texture.view != VK_NULL_HANDLE && texture.sampler != VK_NULL_HANDLE; }
};

// The vertex method's receiver capacity for these draws: each draw's vertices start a new group
// (FrameConfig::vertex_receivers must be at least this).
std::uint32_t vertex_receiver_count(std::span<const DrawItem> draws);

// A static world-space mesh uploaded once (ground, static meshes).
struct StaticMesh {
  Buffer positions;  // vec4
  Buffer normals;    // vec4
  Buffer indices;    // uint32
  Buffer uvs;        // vec2; no handle when the mesh has none
  std::uint32_t index_count = 0;
  glm::vec4 base_color{1.0f};
  BaseColorTexture texture;
  DrawItem draw() const {
    return {&positions, &normals, &indices, index_count, base_color, uvs.handle() != VK_NULL_HANDLE ? &uvs : nullptr,
            texture, -1};
  }
};
// uvs: empty or one per position. The texture's image and sampler must outlive the mesh's draws.
Result<StaticMesh> upload_static_mesh(Context& context, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, std::span<const std::uint32_t> indices,
                                      const glm::vec4& base_color, std::span<const glm::vec2> uvs = {},
                                      const BaseColorTexture& texture = {});

}  // namespace proxygi::gpu
