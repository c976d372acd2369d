#pragma once
// Skin pass (frame step 1): linear blend skinning on the GPU, one dispatch per skinned primitive
// of a model for all its instances (SkinBatch).
//   inputs : SkinnedPrimitive (static bind-pose buffers, uploaded once), the skin's palette of
//            skin matrices (and optionally normal matrices) as column-major mat4 in a buffer,
//            read as a uniform buffer up to kSkinUniformPaletteJoints, else as a storage buffer
//   outputs: SkinnedPrimitive::world_positions / world_normals, vec4 per vertex, world space
// CPU twin: anim::SkinningJob (anim/skinning.h); tests compare them within 1e-5 × the model's
// bounding-box diagonal. Morph targets (anim::MorphJob) are applied before skinning, with one
// weight per target read from a buffer the caller writes each frame.
#include <memory>
#include <optional>

#include "anim/character.h"
#include "base/result.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;

// A skinned primitive's static bind-pose inputs, uploaded once per model primitive and shared
// by every instance of it (the crowd's 20 mannequins read one copy).
struct SkinBindPose {
  std::uint32_t vertex_count = 0;
  std::uint32_t influences = 0;
  bool has_normals = false;
  std::uint32_t morph_targets = 0;
  Buffer positions;        // float × 3 per vertex
  Buffer normals;          // float × 3 per vertex (one dummy float when absent)
  Buffer joints;           // uint16 × influences per vertex, packed in uints
  Buffer weights;          // float × influences per vertex
  Buffer position_deltas;  // float × 3, target-major (layouts.h SkinPush); absent without targets
  Buffer normal_deltas;    // same layout (zeros where a target has none); absent without normals
};

struct SkinnedPrimitive {
  std::uint32_t vertex_count = 0;  // these four as in bind_pose
  std::uint32_t influences = 0;
  bool has_normals = false;
  std::uint32_t morph_targets = 0;
  std::shared_ptr<const SkinBindPose> bind_pose;
  Buffer world_positions;  // out: vec4 per vertex (also usable as a vertex-pulling input)
  Buffer world_normals;    // out: vec4 per vertex
};

// A skin's palettes for one dispatch: column-major mat4 per joint, in buffers made with
// SkinPass::kPaletteUsage (either variant can read them).
struct SkinPalette {
  const Buffer* skin_matrices = nullptr;
  const Buffer* normal_matrices = nullptr;  // null: mat3(skin matrix) is used
  std::uint32_t joints = 0;                 // matrices in each
};

// Every instance of one skinned primitive, skinned in one dispatch: instance i reads joints
// i × palette.joints .. of the palettes and morph weights i × morph_targets .., and writes
// vertices i × instance_stride .. of the outputs (vec4 per vertex, world space).
struct SkinBatch {
  const SkinBindPose* bind_pose = nullptr;
  std::uint32_t instances = 1;
  std::uint32_t instance_stride = 0;        // vertices; ≥ bind_pose->vertex_count
  const Buffer* world_positions = nullptr;  // out: instances × instance_stride vec4
  const Buffer* world_normals = nullptr;    // out: same layout
  SkinPalette palette;                      // joints per instance; buffers hold instances × joints
  const Buffer* morph_weights = nullptr;    // instances × morph_targets floats; null: no morphing
};

// Which skin.comp variant reads a palette (shaders/shared/skin_palette.h).
enum class PaletteBinding { uniform, storage };

class SkinPass {
 public:
  static constexpr VkBufferUsageFlags kPaletteUsage =
      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

  static Result<SkinPass> create(const Context& context);

  // Uploads a skinned primitive's bind-pose data (influences_per_vertex must be ≥ 1).
  static Result<std::shared_ptr<const SkinBindPose>> upload_bind_pose(Context& context,
                                                                      const anim::Primitive& primitive);
  // upload_bind_pose and instantiate.
  static Result<SkinnedPrimitive> upload(Context& context, const anim::Primitive& primitive);
  // Another instance of an uploaded primitive: its bind pose shared, outputs of its own.
  static Result<SkinnedPrimitive> instantiate(const Context& context, std::shared_ptr<const SkinBindPose> bind_pose);

  // uniform for palettes of at most kSkinUniformPaletteJoints joints (when the device's
  // maxUniformBufferRange holds that many), storage beyond.
  PaletteBinding binding_for(std::uint32_t joints) const;

  // Vertices per instance in a SkinBatch's outputs: vertex_count rounded up so that each
  // instance's range starts at a multiple of the device's minStorageBufferOffsetAlignment (a
  // later pass binds one instance's range on its own).
  static std::uint32_t instance_stride(const Context& context, std::uint32_t vertex_count);

  // Records the dispatch, and no barrier: the dispatches of a frame write disjoint outputs, so
  // the caller records one record_outputs_barrier after all of them.
  // `morph_weights`: one float per morph target (the primitive's slice of PoseBuffers::
  // morph_weights); null = no morphing. `binding` overrides binding_for (tests compare the
  // variants); uniform needs palette.joints ≤ kSkinUniformPaletteJoints.
  void record(const Context& context, VkCommandBuffer commands, const SkinnedPrimitive& primitive,
              const SkinPalette& palette, const Buffer* morph_weights = nullptr,
              std::optional<PaletteBinding> binding = std::nullopt) const;
  // One dispatch for every instance of the batch (binding_for(instances × palette.joints)).
  void record(const Context& context, VkCommandBuffer commands, const SkinBatch& batch,
              std::optional<PaletteBinding> binding = std::nullopt) const;

  // Makes every earlier dispatch's outputs visible to later vertex/fragment/compute reads.
  static void record_outputs_barrier(VkCommandBuffer commands);

  static constexpr const char* kName = "skin";

 private:
  Pipeline uniform_pipeline_, storage_pipeline_;
  std::uint32_t uniform_joints_ = 0;  // most joints the uniform variant takes on this device
};

}  // namespace proxygi::gpu
