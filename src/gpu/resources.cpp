#include "gpu/resources.h"

#include <string>
#include <utility>

#include "gpu/context.h"
#include "gpu/vulkan_check.h"

namespace proxygi::gpu {
namespace {

Result<VkDeviceMemory> allocate(const Context& context, const VkMemoryRequirements& requirements,
                                VkMemoryPropertyFlags flags) {
  auto type = context.find_memory_type(requirements.memoryTypeBits, flags);
  if (!type) return type.error();
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = *type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  PROXYGI_VK_TRY(vkAllocateMemory(context.device(), &info, nullptr, &memory));
  return memory;
}

}  // namespace

Result<Buffer> Buffer::create(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind memory) {
  if (size == 0) return make_error("gpu buffer: size must be > 0");
  Buffer buffer;
  buffer.device_ = context.device();
  buffer.size_ = size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  if (memory == MemoryKind::device_local) info.usage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  buffer.usage_ = info.usage;
  PROXYGI_VK_TRY(vkCreateBuffer(buffer.device_, &info, nullptr, &buffer.buffer_));

  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(buffer.device_, buffer.buffer_, &requirements);
  const VkMemoryPropertyFlags flags = memory == MemoryKind::device_local
                                          ? VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT
                                          : VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  auto allocated = allocate(context, requirements, flags);
  if (!allocated) return allocated.error();
  buffer.memory_ = *allocated;
  PROXYGI_VK_TRY(vkBindBufferMemory(buffer.device_, buffer.buffer_, buffer.memory_, 0));
  if (memory == MemoryKind::host_visible)
    PROXYGI_VK_TRY(vkMapMemory(buffer.device_, buffer.memory_, 0, VK_WHOLE_SIZE, 0, &buffer.mapped_));
  return buffer;
}

Status Buffer::add_texel_view(const Context& context, VkFormat format) {
  if (texel_view_ != VK_NULL_HANDLE) return make_error("gpu buffer: texel view added twice");
  if (!(usage_ & VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT))
    return make_error("gpu buffer: a texel view needs VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT usage");
  auto bytes = texel_size(format);
  if (!bytes) return bytes.error();
  const VkDeviceSize texels = size_ / *bytes;
  if (texels > context.limits().maxTexelBufferElements)
    return make_error("gpu buffer: " + std::to_string(texels) + " texels exceed the device's maxTexelBufferElements (" +
                      std::to_string(context.limits().maxTexelBufferElements) + ")");
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer_;
  info.format = format;
  info.offset = 0;
  info.range = texels * *bytes;
  PROXYGI_VK_TRY(vkCreateBufferView(device_, &info, nullptr, &texel_view_));
  return {};
}

void Buffer::release() {
  if (device_ == VK_NULL_HANDLE) return;
  if (texel_view_ != VK_NULL_HANDLE) vkDestroyBufferView(device_, texel_view_, nullptr);
  texel_view_ = VK_NULL_HANDLE;
  if (buffer_ != VK_NULL_HANDLE) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
  device_ = VK_NULL_HANDLE;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

Buffer::~Buffer() { release(); }
Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }
Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    texel_view_ = std::exchange(other.texel_view_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    usage_ = std::exchange(other.usage_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

VkImageAspectFlags Image::aspect() const {
  switch (format_) {
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D16_UNORM: return VK_IMAGE_ASPECT_DEPTH_BIT;
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT: return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    default: return VK_IMAGE_ASPECT_COLOR_BIT;
  }
}

Result<Image> Image::create(const Context& context, std::uint32_t width, std::uint32_t height, VkFormat format,
                            VkImageUsageFlags usage, std::uint32_t mip_levels) {
  if (width == 0 || height == 0) return make_error("gpu image: size must be > 0");
  if (mip_levels == 0) return make_error("gpu image: needs at least one mip level");
  Image image;
  image.device_ = context.device();
  image.format_ = format;
  image.width_ = width;
  image.height_ = height;
  image.mip_levels_ = mip_levels;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = mip_levels;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  PROXYGI_VK_TRY(vkCreateImage(image.device_, &info, nullptr, &image.image_));

  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(image.device_, image.image_, &requirements);
  auto allocated = allocate(context, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!allocated) return allocated.error();
  image.memory_ = *allocated;
  PROXYGI_VK_TRY(vkBindImageMemory(image.device_, image.image_, image.memory_, 0));

  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = image.image_;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {image.aspect(), 0, mip_levels, 0, 1};
  PROXYGI_VK_TRY(vkCreateImageView(image.device_, &view, nullptr, &image.view_));
  return image;
}

void Image::release() {
  if (device_ == VK_NULL_HANDLE) return;
  if (view_ != VK_NULL_HANDLE) vkDestroyImageView(device_, view_, nullptr);
  if (image_ != VK_NULL_HANDLE) vkDestroyImage(device_, image_, nullptr);
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(device_, memory_, nullptr);
  device_ = VK_NULL_HANDLE;
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

Image::~Image() { release(); }
Image::Image(Image&& other) noexcept { *this = std::move(other); }
Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    format_ = other.format_;
    width_ = other.width_;
    height_ = other.height_;
    mip_levels_ = other.mip_levels_;
  }
  return *this;
}

Result<std::uint32_t> texel_size(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_D32_SFLOAT: return 4u;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT: return 8u;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16u;
    default: return make_error("texel_size: unsupported VkFormat " + std::to_string(static_cast<int>(format)));
  }
}

}  // namespace proxygi::gpu
