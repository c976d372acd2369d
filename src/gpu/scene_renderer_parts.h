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

// One mesh node of one model, skinned for all the model's instances at once (one skin dispatch
// per primitive, SkinBatch): the instances' palettes, morph weights and skinned vertices
// concatenated, instance i (in world instance order) at i × palette_joints, i × morph_targets
// and i × instance_stride of each primitive.
struct SkinGroup {
  struct Primitive {
    std::shared_ptr<const SkinBindPose> bind_pose;
    std::uint32_t instance_stride = 0;  // SkinPass::instance_stride of its vertex count
    Buffer world_positions;             // out: instances × instance_stride vec4
    Buffer world_normals;
  };
  std::uint32_t instances = 0;
  std::uint32_t palette_joints = 1;     // matrices per instance
  std::uint32_t morph_targets = 0;      // weights per instance; 0: no morphs
  std::vector<Primitive> primitives;    // the node's primitives, in mesh order
  std::vector<Buffer> palettes;         // skin matrices, one buffer per ring slot, host-visible
  std::vector<Buffer> normal_palettes;  // their inverse-transposes (anim::normal_matrix layout)
  std::vector<Buffer> morph_weights;    // one buffer per ring slot; empty: no morphs
};

// One mesh node of one instance: its primitives skinned by the node's skin, or (no skin) by a
// one-joint palette holding the node's world matrix, in its model's SkinGroup.
struct MeshDraw {
  int node = -1;
  int skin = -1;
  std::size_t group = 0;           // SceneRenderer::skin_groups_ index
  std::uint32_t group_instance = 0;  // this instance's place in it
  // Static per-model data, one copy shared by every instance of the model (upload_instances).
  std::vector<std::shared_ptr<const Buffer>> indices;
  std::vector<std::uint32_t> index_counts;
  std::vector<std::shared_ptr<const Buffer>> uvs;  // static TEXCOORD_0 per primitive; null when absent
  std::vector<std::shared_ptr<const VsglTriangleOrders>> vsgl_orders;  // per primitive
  std::vector<std::shared_ptr<const Buffer>> vsgl_exposure;  // per primitive: float per vertex (ref/sender_exposure.h)
  std::vector<MaterialBinding> materials;
  std::size_t morph_offset = 0;  // the node's slice of PoseBuffers::morph_weights
};

struct SceneRenderer::Instance {
  std::vector<MeshDraw> meshes;
};

}  // namespace proxygi::gpu
