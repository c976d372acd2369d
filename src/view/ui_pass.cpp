#include "view/ui_pass.h"

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
}

void UiPass::forget_framebuffers() {
  if (pending_) (void)wait();  // a lost device shows on the next submit
  for (auto& [view, framebuffer] : framebuffers_) vkDestroyFramebuffer(context_.device(), framebuffer, nullptr);
  framebuffers_.clear();
}

Result<VkFramebuffer> UiPass::framebuffer(const TargetImage& target) {
  if (auto found = framebuffers_.find(target.view); found != framebuffers_.end()) return found->second;
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = render_pass_;
  info.attachmentCount = 1;
  info.pAttachments = &target.view;
  info.width = target.width;
  info.height = target.height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  PROXYGI_VK_TRY(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer));
  framebuffers_[target.view] = framebuffer;
  return framebuffer;
}

Status UiPass::wait() {
  if (!pending_) return {};
  PROXYGI_VK_TRY(vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
  pending_ = false;
  return {};
}

Status UiPass::submit(const TargetImage& target, ImDrawData* draw_data, VkSemaphore signal) {
  if (Status s = wait(); !s) return s;
  auto framebuffer_handle = framebuffer(target);
  if (!framebuffer_handle) return framebuffer_handle.error();
  PROXYGI_VK_TRY(vkResetFences(context_.device(), 1, &fence_));
  PROXYGI_VK_TRY(vkResetCommandBuffer(commands_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PROXYGI_VK_TRY(vkBeginCommandBuffer(commands_, &begin));
  context_.begin_label(commands_, "ui");
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = render_pass_;
  pass.framebuffer = *framebuffer_handle;
  pass.renderArea.extent = {target.width, target.height};
  vkCmdBeginRenderPass(commands_, &pass, VK_SUBPASS_CONTENTS_INLINE);
  if (draw_data && draw_data->CmdListsCount > 0) ImGui_ImplVulkan_RenderDrawData(draw_data, commands_);
  vkCmdEndRenderPass(commands_);
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
