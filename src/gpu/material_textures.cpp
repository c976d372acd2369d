#include "gpu/material_textures.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "base/log.h"
#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu/vulkan_check.h"
#include "image/image.h"
#include "render/texture_sampling.h"

namespace proxygi::gpu {
namespace {

VkFilter vulkan_filter(anim::TextureFilter filter) {
  return filter == anim::TextureFilter::nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

VkSamplerAddressMode vulkan_wrap(anim::TextureWrap wrap) {
  switch (wrap) {
    case anim::TextureWrap::repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case anim::TextureWrap::clamp_to_edge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case anim::TextureWrap::mirrored_repeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

std::uint32_t mip_level_count(int width, int height) {
  std::uint32_t levels = 1;
  for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
  return levels;
}

bool valid_image(const anim::Image& image) {
  return image.width > 0 && image.height > 0 &&
         image.rgba.size() >= std::size_t(image.width) * std::size_t(image.height) * 4;
}

}  // namespace

Result<Sampler> Sampler::create(const Context& context, const anim::TextureSampler& description) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = vulkan_filter(description.magnification);
  info.minFilter = vulkan_filter(description.minification);
  info.addressModeU = vulkan_wrap(description.wrap_s);
  info.addressModeV = vulkan_wrap(description.wrap_t);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.minLod = 0.0f;
  if (description.mipmaps) {
    info.mipmapMode = description.mipmap == anim::TextureFilter::nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                                         : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.mipLodBias = kTextureLodBias;  // not without mipmaps: it would move the mag/min switch
    info.maxLod = VK_LOD_CLAMP_NONE;
  } else {
    // Level 0 only, but λ may still exceed 0 so minification keeps its own filter (maxLod 0
    // would select the magnification filter everywhere; the Vulkan spec's suggested 0.25).
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.maxLod = 0.25f;
  }
  Sampler sampler;
  sampler.device_ = context.device();
  PROXYGI_VK_TRY(vkCreateSampler(sampler.device_, &info, nullptr, &sampler.sampler_));
  return sampler;
}

Sampler::~Sampler() {
  if (device_ != VK_NULL_HANDLE && sampler_ != VK_NULL_HANDLE) vkDestroySampler(device_, sampler_, nullptr);
}
Sampler::Sampler(Sampler&& other) noexcept { *this = std::move(other); }
Sampler& Sampler::operator=(Sampler&& other) noexcept {
  if (this != &other) {
    if (device_ != VK_NULL_HANDLE && sampler_ != VK_NULL_HANDLE) vkDestroySampler(device_, sampler_, nullptr);
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
  }
  return *this;
}

std::vector<std::vector<std::uint8_t>> srgb_mip_chain(const anim::Image& image) {
  std::vector<std::vector<std::uint8_t>> levels;
  if (!valid_image(image)) return levels;
  levels.push_back(std::vector<std::uint8_t>(image.rgba.begin(),
                                             image.rgba.begin() + std::ptrdiff_t(image.width) * image.height * 4));
  std::vector<glm::vec4> linear(std::size_t(image.width) * std::size_t(image.height));
  for (std::size_t i = 0; i < linear.size(); ++i)
    linear[i] = glm::vec4(image::srgb8_to_linear(image.rgba[4 * i]), image::srgb8_to_linear(image.rgba[4 * i + 1]),
                          image::srgb8_to_linear(image.rgba[4 * i + 2]), float(image.rgba[4 * i + 3]) / 255.0f);
  int width = image.width, height = image.height;
  auto encode = [](float value) { return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); };
  while (width > 1 || height > 1) {
    const int next_width = std::max(1, width / 2), next_height = std::max(1, height / 2);
    std::vector<glm::vec4> next(std::size_t(next_width) * std::size_t(next_height));
    std::vector<std::uint8_t> bytes(next.size() * 4);
    for (int y = 0; y < next_height; ++y)
      for (int x = 0; x < next_width; ++x) {
        glm::vec4 sum(0.0f);
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)  // an odd last row or column is dropped, a size-1 axis repeated
            sum += linear[std::size_t(std::min(2 * y + dy, height - 1)) * std::size_t(width) +
                          std::size_t(std::min(2 * x + dx, width - 1))];
        const std::size_t i = std::size_t(y) * std::size_t(next_width) + std::size_t(x);
        next[i] = 0.25f * sum;
        for (int c = 0; c < 3; ++c) bytes[4 * i + std::size_t(c)] = encode(image::linear_to_srgb(next[i][c]));
        bytes[4 * i + 3] = encode(next[i].a);
      }
    levels.push_back(std::move(bytes));
    linear = std::move(next);
    width = next_width;
    height = next_height;
  }
  return levels;
}

Result<Image> upload_srgb_texture(Context& context, const anim::Image& source) {
  if (!valid_image(source)) return make_error("texture '" + source.name + "': empty or truncated image");
  const auto levels = srgb_mip_chain(source);
  auto image = Image::create(context, std::uint32_t(source.width), std::uint32_t(source.height),
                             VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                             mip_level_count(source.width, source.height));
  if (!image) return image.error();
  if (levels.size() != image->mip_levels()) return make_error("texture: mip chain and image disagree");
  std::size_t total = 0;
  for (const auto& level : levels) total += level.size();
  auto staging = Buffer::create(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::host_visible);
  if (!staging) return staging.error();
  std::vector<VkBufferImageCopy> regions;
  std::size_t offset = 0;
  for (std::uint32_t level = 0; level < levels.size(); ++level) {
    std::memcpy(static_cast<std::uint8_t*>(staging->mapped()) + offset, levels[level].data(), levels[level].size());
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    region.imageExtent = {std::max(1u, image->width() >> level), std::max(1u, image->height() >> level), 1};
    regions.push_back(region);
    offset += levels[level].size();
  }
  Status copied = context.submit_and_wait([&](VkCommandBuffer commands) {
    transition(commands, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(commands, staging->handle(), image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           std::uint32_t(regions.size()), regions.data());
    transition(commands, *image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
  if (!copied) return copied.error();
  return std::move(*image);
}

Result<MaterialTextures> MaterialTextures::create(Context& context, const anim::Character& character) {
  MaterialTextures out;
  out.images_.resize(character.images.size());
  for (std::size_t index = 0; index < character.materials.size(); ++index) {
    const anim::Material& material = character.materials[index];
    MaterialBinding binding;
    binding.base_color = material.base_color_factor;
    auto sampler = Sampler::create(context, material.base_color_sampler);
    if (!sampler) return sampler.error();
    const int image = material.base_color_image;
    if (image >= 0 && std::size_t(image) < character.images.size()) {
      const anim::Image& source = character.images[std::size_t(image)];
      if (material.base_color_texcoord != 0) {
        log_warning(character.source + ": material " + std::to_string(index) + " reads TEXCOORD_" +
                    std::to_string(material.base_color_texcoord) + ", only TEXCOORD_0 is supported: using the " +
                    "texture's mean color");
        binding.base_color *= glm::vec4(render::mean_linear_color(source), 1.0f);
      } else {
        Image& uploaded = out.images_[std::size_t(image)];
        if (uploaded.handle() == VK_NULL_HANDLE) {
          auto made = upload_srgb_texture(context, source);
          if (!made) return make_error(character.source + ": image " + std::to_string(image) + ": " + made.message());
          uploaded = std::move(*made);
        }
        binding.texture = {uploaded.view(), sampler->handle(), material.base_color_uv_transform};
      }
    }
    out.samplers_.push_back(std::move(*sampler));
    out.bindings_.push_back(binding);
  }
  return out;
}

MaterialBinding MaterialTextures::binding(int material) const {
  if (material < 0 || std::size_t(material) >= bindings_.size()) return {};
  return bindings_[std::size_t(material)];
}

}  // namespace proxygi::gpu
