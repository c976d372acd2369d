#pragma once
// Barriers between the passes of one frame, derived from what each pass declares it reads and
// writes: before a pass, one VkMemoryBarrier2 makes every earlier conflicting access (read after
// write, write after write, write after read) available to exactly the stages that need it, and
// nothing is emitted when the pass touches nothing an earlier pass wrote or read. Layout
// transitions of images stay with the pass that owns the image (the G-buffer, the raster splat).
//
//   PassBarriers barriers;                     // one per command buffer
//   barriers.before(commands, exponentiate.accesses(inputs, outputs));
//   exponentiate.record(commands, inputs, outputs);
#include <map>
#include <span>

#include <vulkan/vulkan.h>

namespace proxygi::gpu {

enum class Use { read, write };

// One resource (a gpu::Buffer or gpu::Image; compared by address) touched by a pass in `stages`.
struct ResourceAccess {
  const void* resource = nullptr;
  Use use = Use::read;
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
};

inline ResourceAccess reads(const void* resource, VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT) {
  return {resource, Use::read, stages};
}
inline ResourceAccess writes(const void* resource, VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT) {
  return {resource, Use::write, stages};
}

// The access bits a use in `stages` implies (shader, attachment or transfer access).
VkAccessFlags2 access_mask(VkPipelineStageFlags2 stages, Use use);

class PassBarriers {
 public:
  // Records the barrier the next pass needs, then remembers its accesses.
  void before(VkCommandBuffer commands, std::span<const ResourceAccess> accesses);
  // Earlier work outside this tracker (another submission, a full barrier) ordered everything.
  void reset() { states_.clear(); }
  std::size_t barriers_recorded() const { return barriers_; }

 private:
  struct State {
    VkPipelineStageFlags2 write_stages = 0;  // the last write
    VkPipelineStageFlags2 read_stages = 0;   // reads since the last write
  };
  std::map<const void*, State> states_;
  std::size_t barriers_ = 0;
};

}  // namespace proxygi::gpu
