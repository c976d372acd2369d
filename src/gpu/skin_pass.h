#pragma once
// Skin pass (frame step 1): linear blend skinning on the GPU, one dispatch per skinned primitive.
//   inputs : SkinnedPrimitive (static bind-pose buffers, uploaded once), the skin's palette of
//            skin matrices (and optionally normal matrices) as column-major mat4 in a buffer
//   outputs: SkinnedPrimitive::world_positions / world_normals, vec4 per vertex, world space
// CPU twin: anim::SkinningJob (anim/skinning.h); tests compare them within 1e-5 × the model's
// bounding-box diagonal. Morph targets (anim::MorphJob) are applied before skinning, with one
// weight per target read from a buffer the caller writes each frame.
#include <memory>

#include "anim/character.h"
#include "base/result.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;

struct SkinnedPrimitive {
  std::uint32_t vertex_count = 0;
  std::uint32_t influences = 0;
  bool has_normals = false;
  Buffer bind_positions;   // float × 3 per vertex
  Buffer bind_normals;     // float × 3 per vertex (one dummy float when absent)
  Buffer joints;           // uint16 × influences per vertex, packed in uints
  Buffer weights;          // float × influences per vertex
  std::uint32_t morph_targets = 0;
  Buffer position_deltas;  // float × 3, target-major (layouts.h SkinPush); absent without targets
  Buffer normal_deltas;    // same layout (zeros where a target has none); absent without normals
  Buffer world_positions;  // out: vec4 per vertex (also usable as a vertex-pulling input)
  Buffer world_normals;    // out: vec4 per vertex
};

class SkinPass {
 public:
  static Result<SkinPass> create(const Context& context);

  // Uploads a skinned primitive's bind-pose data (influences_per_vertex must be ≥ 1).
  static Result<SkinnedPrimitive> upload(Context& context, const anim::Primitive& primitive);

  // Records the dispatch. `normal_matrices` may be null: then mat3(skin matrix) is used.
  // `morph_weights`: one float per morph target (the primitive's slice of PoseBuffers::
  // morph_weights); null = no morphing. A barrier making the outputs visible to later
  // vertex/fragment/compute reads is recorded too.
  void record(const Context& context, VkCommandBuffer commands, const SkinnedPrimitive& primitive,
              const Buffer& skin_matrices, const Buffer* normal_matrices,
              const Buffer* morph_weights = nullptr) const;

  static constexpr const char* kName = "skin";

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
