#pragma once
// Base color textures of the G-buffer pass. Each image a character's materials use is uploaded
// once as a VK_FORMAT_R8G8B8A8_SRGB sampled image with a full mip chain, made on the CPU in
// linear space (srgb_mip_chain); each material's glTF sampler becomes a VkSampler (wrap and
// filters as glTF says, LOD bias kTextureLodBias when mipmapped, no anisotropy). Untextured draws
// use the G-buffer's untextured pipeline (frame_passes.h). Albedo = base color factor ×
// texture(uv_transform × TEXCOORD_0).
//
// Not supported: texCoord sets other than 0 (the material shows its texture's mean linear
// color, as the reference path tracer does), per-texture anisotropy.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "anim/character.h"
#include "base/result.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;

// Mip LOD bias of every mipmapped texture sampler. The reference path tracer's pixel value averages its
// jittered rays over the pixel: a box one footprint wide. Trilinear filtering at the standard
// LOD is a bilinear tent (two texels of a level whose texels are one footprint) over the mip
// chain's box: √3 times the box's standard deviation, so textures come out blurrier than the
// reference's; the bias log2(1/√3) ≈ −0.8 matches the spread, −1 makes the tent span one
// footprint. Measured on CesiumMan at 256² against 8×8 rays per pixel (tests/gpu/
// texture_shared_assets_test.cpp): mean |albedo difference| 0.043 at bias 0, 0.017 at −0.8,
// 0.016 at −1, 0.018 at −1.5; 0.034 for level-0 lookups at pixel centers.
inline constexpr float kTextureLodBias = -1.0f;

// The texture half of one draw: a null view or sampler means untextured (the factor alone).
struct BaseColorTexture {
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  glm::mat3 uv_transform{1.0f};  // KHR_texture_transform (anim::Material)
};

// What a G-buffer draw needs to shade its albedo.
struct MaterialBinding {
  glm::vec4 base_color{1.0f};  // linear RGBA factor
  BaseColorTexture texture;
};

// A VkSampler for a glTF sampler.
class Sampler {
 public:
  static Result<Sampler> create(const Context& context, const anim::TextureSampler& description);
  Sampler() = default;
  ~Sampler();
  Sampler(Sampler&& other) noexcept;
  Sampler& operator=(Sampler&& other) noexcept;
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;
  VkSampler handle() const { return sampler_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

// The mip chain of an RGBA8 sRGB image: level k is max(1, size >> k) on each axis, each texel
// the mean of the (up to) 2×2 texels below it, averaged in linear space and re-encoded to sRGB
// (alpha averaged as is). Level 0 is the image itself. Rows top first, RGBA8 per texel.
std::vector<std::vector<std::uint8_t>> srgb_mip_chain(const anim::Image& image);

// Uploads an RGBA8 sRGB image with its mip chain, left in SHADER_READ_ONLY_OPTIMAL.
Result<Image> upload_srgb_texture(Context& context, const anim::Image& image);

// Every base color texture of one character, and the binding of each of its materials.
class MaterialTextures {
 public:
  static Result<MaterialTextures> create(Context& context, const anim::Character& character);
  // The binding of material `material` (-1 or out of range: glTF's default white material).
  MaterialBinding binding(int material) const;

 private:
  std::vector<Image> images_;      // per character image; unused ones stay empty
  std::vector<Sampler> samplers_;  // per material
  std::vector<MaterialBinding> bindings_;
};

}  // namespace proxygi::gpu
