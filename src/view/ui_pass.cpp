#include "view/ui_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <backends/imgui_impl_vulkan.h>

#include "gpu/vulkan_check.h"

namespace proxygi::view {
namespace {

void check_imgui_result(VkResult result) {
  if (result != VK_SUCCESS) std::fprintf(stderr, "proxygi: imgui vulkan backend: VkResult %d\n", int(result));
}

}  // namespace

std::vector<PixelRect> touched_rects(const ImDrawData& draw_data) {
  std::vector<PixelRect> rects;
  for (int l = 0; l < draw_data.CmdListsCount; ++l) {
    const ImDrawList& list = *draw_data.CmdLists[l];
    for (const ImDrawCmd& command : list.CmdBuffer) {
      if (command.UserCallback || command.ElemCount == 0) continue;
      ImVec2 low(1e30f, 1e30f), high(-1e30f, -1e30f);
      for (unsigned i = 0; i < command.ElemCount; ++i) {
        const ImVec2 p = list.VtxBuffer[int(command.VtxOffset + list.IdxBuffer[int(command.IdxOffset + i)])].pos;
        low = {std::min(low.x, p.x), std::min(low.y, p.y)}, high = {std::max(high.x, p.x), std::max(high.y, p.y)};
      }
      const ImVec2 origin = draw_data.DisplayPos;
      const float x0 = std::max(low.x, command.ClipRect.x) - origin.x, y0 = std::max(low.y, command.ClipRect.y) - origin.y;
      const float x1 = std::min(high.x, command.ClipRect.z) - origin.x, y1 = std::min(high.y, command.ClipRect.w) - origin.y;
      if (x1 < x0 || y1 < y0) continue;
      rects.push_back({int(std::floor(x0)) - 1, int(std::floor(y0)) - 1, int(std::ceil(x1)) + 1, int(std::ceil(y1)) + 1});
    }
  }
  return rects;
}

namespace {

// A framebuffer of one colour view for `render_pass` (the target's or the overlay's).
Result<VkFramebuffer> make_framebuffer(VkDevice device, VkRenderPass render_pass, VkImageView view, std::uint32_t width,
                                       std::uint32_t height) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = render_pass;
  info.attachmentCount = 1;
  info.pAttachments = &view;
  info.width = width;
  info.height = height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  PROXYGI_VK_TRY(vkCreateFramebuffer(device, &info, nullptr, &framebuffer));
  return framebuffer;
}

// ImGui's draw lists in one render pass over the whole framebuffer; `clear` for a pass that
// clears (the overlay), null for one that loads (the target).
void record_imgui(VkCommandBuffer commands, VkRenderPass render_pass, VkFramebuffer framebuffer, std::uint32_t width,
                  std::uint32_t height, ImDrawData* draw_data, const VkClearValue* clear) {
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = render_pass;
  pass.framebuffer = framebuffer;
  pass.renderArea.extent = {width, height};
  pass.clearValueCount = clear ? 1 : 0;
  pass.pClearValues = clear;
  vkCmdBeginRenderPass(commands, &pass, VK_SUBPASS_CONTENTS_INLINE);
  if (draw_data && draw_data->CmdListsCount > 0) ImGui_ImplVulkan_RenderDrawData(draw_data, commands);
  vkCmdEndRenderPass(commands);
}

template <typename T>
void append(std::vector<std::uint8_t>& out, const T& value) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

}  // namespace

void draw_signature(const ImDrawData& draw_data, const ImDrawList* scene_list, DrawSignature& out) {
  out.scene.clear(), out.panels.clear();
  for (std::vector<std::uint8_t>* part : {&out.scene, &out.panels}) {
    append(*part, draw_data.DisplayPos), append(*part, draw_data.DisplaySize);
    append(*part, draw_data.FramebufferScale);
  }
  for (int l = 0; l < draw_data.CmdListsCount; ++l) {
    const ImDrawList& list = *draw_data.CmdLists[l];
    std::vector<std::uint8_t>& part = &list == scene_list ? out.scene : out.panels;
    append(part, l), append(part, list.VtxBuffer.Size), append(part, list.IdxBuffer.Size), append(part, list.CmdBuffer.Size);
    for (const ImDrawCmd& command : list.CmdBuffer) {  // field by field: no padding bytes
      append(part, command.ClipRect), append(part, command.TextureId), append(part, command.VtxOffset);
      append(part, command.IdxOffset), append(part, command.ElemCount), append(part, command.UserCallback);
    }
    static_assert(sizeof(ImDrawVert) == sizeof(ImVec2) * 2 + sizeof(ImU32), "ImDrawVert without padding");
    const auto* vertices = reinterpret_cast<const std::uint8_t*>(list.VtxBuffer.Data);
    part.insert(part.end(), vertices, vertices + std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
    const auto* indices = reinterpret_cast<const std::uint8_t*>(list.IdxBuffer.Data);
    part.insert(part.end(), indices, indices + std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
  }
}

Result<std::unique_ptr<UiPass>> UiPass::create(gpu::Context& context, VkFormat format, VkImageLayout final_layout,
                                               std::uint32_t image_count) {
  std::unique_ptr<UiPass> pass(new UiPass(context));
  const VkDevice device = context.device();

  VkAttachmentDescription color{};
  color.format = format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the frame is already there
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = final_layout;
  VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  // The frame's copy into the image (an earlier submission) happens before the UI loads it.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &dependency;
  PROXYGI_VK_TRY(vkCreateRenderPass(device, &info, nullptr, &pass->render_pass_));
  pass->final_layout_ = final_layout;

  // The overlay: cleared to transparent black, ImGui drawn (the same pipeline, so a compatible
  // pass: only load/store ops and layouts may differ, the dependency is the same), then a
  // barrier makes it readable by the blend's fragment shader in the same command buffer.
  VkAttachmentDescription overlay = color;
  overlay.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  overlay.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  overlay.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  info.pAttachments = &overlay;
  PROXYGI_VK_TRY(vkCreateRenderPass(device, &info, nullptr, &pass->overlay_render_pass_));
  auto blend = OverlayBlendPass::create(context, format);
  if (!blend) return blend.error();
  pass->blend_ = std::move(*blend);

  VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool_info.maxSets = 16;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &pool_size;
  PROXYGI_VK_TRY(vkCreateDescriptorPool(device, &pool_info, nullptr, &pass->descriptor_pool_));

  VkCommandPoolCreateInfo command_pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  command_pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  command_pool.queueFamilyIndex = context.queue_family();
  PROXYGI_VK_TRY(vkCreateCommandPool(device, &command_pool, nullptr, &pass->command_pool_));
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pass->command_pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  PROXYGI_VK_TRY(vkAllocateCommandBuffers(device, &allocate, &pass->commands_));
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  PROXYGI_VK_TRY(vkCreateFence(device, &fence, nullptr, &pass->fence_));

  ImGui_ImplVulkan_InitInfo init{};
  init.Instance = context.instance();
  init.PhysicalDevice = context.physical_device();
  init.Device = device;
  init.QueueFamily = context.queue_family();
  init.Queue = context.queue();
  init.DescriptorPool = pass->descriptor_pool_;
  init.MinImageCount = std::max(2u, image_count);
  init.ImageCount = std::max(2u, image_count);
  init.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  init.CheckVkResultFn = check_imgui_result;
  if (!ImGui_ImplVulkan_Init(&init, pass->render_pass_)) return make_error("ImGui_ImplVulkan_Init failed");
  pass->backend_ = true;
  Status fonts = context.submit_and_wait([](VkCommandBuffer commands) { ImGui_ImplVulkan_CreateFontsTexture(commands); });
  if (!fonts) return fonts.error();
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  return pass;
}

UiPass::~UiPass() {
  const VkDevice device = context_.device();
  if (pending_) vkWaitForFences(device, 1, &fence_, VK_TRUE, UINT64_MAX);
  if (backend_) ImGui_ImplVulkan_Shutdown();
  forget_framebuffers();
  if (fence_) vkDestroyFence(device, fence_, nullptr);
  if (command_pool_) vkDestroyCommandPool(device, command_pool_, nullptr);
  if (descriptor_pool_) vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);
  if (render_pass_) vkDestroyRenderPass(device, render_pass_, nullptr);
  if (overlay_render_pass_) vkDestroyRenderPass(device, overlay_render_pass_, nullptr);
}

void UiPass::forget_framebuffers() {
  if (pending_) (void)wait();  // a lost device shows on the next submit
  for (auto& [view, framebuffer] : framebuffers_) vkDestroyFramebuffer(context_.device(), framebuffer, nullptr);
  framebuffers_.clear();
  if (overlay_framebuffer_) vkDestroyFramebuffer(context_.device(), overlay_framebuffer_, nullptr);
  overlay_framebuffer_ = VK_NULL_HANDLE;
  overlay_.reset();
  overlay_drawn_ = false;
  overlay_rects_.clear();
}

bool UiPass::overlay_cached(std::uint32_t width, std::uint32_t height) const {
  return overlay_drawn_ && overlay_ && overlay_->width() == width && overlay_->height() == height;
}

Status UiPass::make_overlay(const TargetImage& target) {
  if (overlay_ && overlay_->width() == target.width && overlay_->height() == target.height) return {};
  if (Status s = wait(); !s) return s;
  if (overlay_framebuffer_) vkDestroyFramebuffer(context_.device(), overlay_framebuffer_, nullptr);
  overlay_framebuffer_ = VK_NULL_HANDLE;
  overlay_drawn_ = false;
  auto image = gpu::Image::create(context_, target.width, target.height, target.format,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  if (!image) return image.error();
  overlay_ = std::move(*image);
  auto framebuffer = make_framebuffer(context_.device(), overlay_render_pass_, overlay_->view(), target.width, target.height);
  if (!framebuffer) return framebuffer.error();
  overlay_framebuffer_ = *framebuffer;
  return {};
}

// Overlay (drawn again or as it is) blended over the frame, then the target to the final layout.
void UiPass::record_overlay(const TargetImage& target, ImDrawData* draw_data, UiDraw how, VkImageLayout final_layout) {
  if (how == UiDraw::redraw_overlay) {
    const VkClearValue clear{};  // transparent black
    record_imgui(commands_, overlay_render_pass_, overlay_framebuffer_, target.width, target.height, draw_data, &clear);
    VkImageMemoryBarrier readable{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    readable.srcQueueFamilyIndex = readable.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    readable.image = overlay_->handle();
    readable.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    readable.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    readable.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    readable.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    readable.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                         0, nullptr, 0, nullptr, 1, &readable);
    overlay_rects_ = covering_rects(touched_rects(*draw_data), int(target.width), int(target.height));
    overlay_drawn_ = true;
  }
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = target.image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  // The frame's copy into the image (an earlier submission) before the blend loads it.
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.oldLayout = barrier.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, 0, nullptr, 0, nullptr, 1, &barrier);
  blend_->record(context_, commands_, {overlay_->view(), overlay_rects_}, {&target});
  barrier.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT;
  barrier.newLayout = final_layout;
  vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0,
                       0, nullptr, 0, nullptr, 1, &barrier);
}

Result<VkFramebuffer> UiPass::framebuffer(const TargetImage& target) {
  if (auto found = framebuffers_.find(target.view); found != framebuffers_.end()) return found->second;
  auto framebuffer = make_framebuffer(context_.device(), render_pass_, target.view, target.width, target.height);
  if (!framebuffer) return framebuffer.error();
  framebuffers_[target.view] = *framebuffer;
  return *framebuffer;
}

Status UiPass::wait() {
  if (!pending_) return {};
  PROXYGI_VK_TRY(vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
  pending_ = false;
  return {};
}

Status UiPass::submit(const TargetImage& target, ImDrawData* draw_data, UiDraw how, VkSemaphore signal) {
  if (Status s = wait(); !s) return s;
  const bool cached = draw_data && how != UiDraw::direct;
  if (cached && how == UiDraw::reuse_overlay && !overlay_cached(target.width, target.height))
    return make_error("ui pass: no overlay of " + std::to_string(target.width) + "x" + std::to_string(target.height) +
                      " to reuse");
  if (cached)
    if (Status s = make_overlay(target); !s) return s;
  auto framebuffer_handle = framebuffer(target);
  if (!framebuffer_handle) return framebuffer_handle.error();
  PROXYGI_VK_TRY(vkResetFences(context_.device(), 1, &fence_));
  PROXYGI_VK_TRY(vkResetCommandBuffer(commands_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PROXYGI_VK_TRY(vkBeginCommandBuffer(commands_, &begin));
  context_.begin_label(commands_, "ui");
  if (cached) {
    record_overlay(target, draw_data, how, final_layout_);
  } else {
    record_imgui(commands_, render_pass_, *framebuffer_handle, target.width, target.height, draw_data, nullptr);
  }
  context_.end_label(commands_);
  PROXYGI_VK_TRY(vkEndCommandBuffer(commands_));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  if (signal) {
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &signal;
  }
  PROXYGI_VK_TRY(vkQueueSubmit(context_.queue(), 1, &submit, fence_));
  pending_ = true;
  return {};
}

}  // namespace proxygi::view
