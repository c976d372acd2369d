#pragma once
// Internal to SceneRenderer (scene_renderer.cpp, scene_meshes.cpp): its per-model and
// per-instance GPU data.
#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include "settings/render_settings.h"

#include "gpu/scene_renderer.h"

namespace proxygi::gpu {

// The base color textures of one world model, shared by its instances.
struct SceneRenderer::ModelTextures {
  const world::Model* model = nullptr;
  MaterialTextures textures;
};

// One primitive's triangles in bone-group order (render.vsgl_grouping bone_groups), one order for
// each K of settings::kVsglLightsPerCharacter, concatenated in that order into one index buffer;
// first[i]: the K + 1 group starts of the i-th order, in triangles of that buffer.
struct VsglTriangleOrders {
  Buffer indices;
  std::array<std::vector<std::uint32_t>, settings::kVsglLightsPerCharacter.size()> first;
};

// One mesh node of one instance: its primitives skinned by the node's skin, or (no skin) by a
// one-joint palette holding the node's world matrix.
struct MeshDraw {
  int node = -1;
  int skin = -1;
  std::vector<SkinnedPrimitive> primitives;
  // Static per-model data, one copy shared by every instance of the model (upload_instances).
  std::vector<std::shared_ptr<const Buffer>> indices;
  std::vector<std::uint32_t> index_counts;
  std::vector<std::shared_ptr<const Buffer>> uvs;  // static TEXCOORD_0 per primitive; null when absent
  std::vector<std::shared_ptr<const VsglTriangleOrders>> vsgl_orders;  // per primitive
  std::vector<std::shared_ptr<const Buffer>> vsgl_exposure;  // per primitive: float per vertex (ref/sender_exposure.h)
  std::vector<MaterialBinding> materials;
  std::vector<Buffer> palettes;         // skin matrices, one buffer per ring slot, host-visible
  std::vector<Buffer> normal_palettes;  // their inverse-transposes (anim::normal_matrix layout)
  std::uint32_t palette_joints = 1;     // matrices in each palette
  std::size_t morph_offset = 0;         // the node's slice of PoseBuffers::morph_weights
  std::vector<Buffer> morph_weights;    // that slice, one buffer per ring slot; empty: no morphs
};

struct SceneRenderer::Instance {
  std::vector<MeshDraw> meshes;
};

}  // namespace proxygi::gpu
