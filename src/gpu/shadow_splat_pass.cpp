#include "gpu/shadow_splat_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "gpu/context.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "settings/render_settings.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"
#include "shaders/shared/splat_layouts.h"

namespace proxygi::gpu {
namespace {

constexpr VkFormat kTargetFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkShaderStageFlags kVertex = VK_SHADER_STAGE_VERTEX_BIT;
constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

std::vector<glm::vec4> unit_sphere_bounding_mesh(int subdivisions) {
  // Icosahedron, counter-clockwise seen from outside.
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::vec3> vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                     {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& vertex : vertices) vertex = glm::normalize(vertex);
  const std::array<glm::uvec3, 20> faces = {{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}}};
  // Each subdivision splits every face into four, new vertices pushed onto the unit sphere.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    if (auto found = midpoints.find(key); found != midpoints.end()) return found->second;
    vertices.push_back(glm::normalize(vertices[a] + vertices[b]));
    return midpoints[key] = std::uint32_t(vertices.size() - 1);
  };
  std::vector<glm::uvec3> triangles(faces.begin(), faces.end());
  for (int level = 0; level < subdivisions; ++level) {
    std::vector<glm::uvec3> finer;
    for (const auto& face : triangles) {
      const std::uint32_t ab = midpoint(face.x, face.y), bc = midpoint(face.y, face.z), ca = midpoint(face.z, face.x);
      finer.insert(finer.end(), {{face.x, ab, ca}, {face.y, bc, ab}, {face.z, ca, bc}, {ab, bc, ca}});
    }
    triangles = std::move(finer);
  }
  // Scale so every face plane is at distance ≥ 1: the polyhedron then contains the unit sphere.
  float inradius = 1.0f;
  for (const auto& tri : triangles) {
    const glm::vec3 normal =
        glm::normalize(glm::cross(vertices[tri.y] - vertices[tri.x], vertices[tri.z] - vertices[tri.x]));
    inradius = std::min(inradius, glm::dot(normal, vertices[tri.x]));
  }
  const float scale = 1.0f / inradius * (1.0f + 1e-4f);  // margin for float rounding
  std::vector<glm::vec4> out;
  for (const auto& tri : triangles)
    for (std::uint32_t index : {tri.x, tri.y, tri.z}) out.emplace_back(vertices[index] * scale, 1.0f);
  return out;
}

Result<std::unique_ptr<ShadowSplatPass>> ShadowSplatPass::create(Context& context, int order,
                                                                 std::uint32_t display_width,
                                                                 std::uint32_t display_height,
                                                                 std::uint32_t receiver_scale) {
  if (order < settings::kMinShOrder || order > settings::kMaxShOrder)
    return make_error("shadow splat: SH order " + std::to_string(order) + " is out of range");
  std::unique_ptr<ShadowSplatPass> pass(new ShadowSplatPass(context));
  pass->order_ = order;
  pass->passes_ = std::uint32_t(PROXYGI_SPLAT_PASSES(order));
  pass->targets_per_pass_ = std::uint32_t(PROXYGI_SPLAT_TARGETS_PER_PASS(order));
  const VkPhysicalDeviceLimits& limits = context.limits();
  if (limits.maxColorAttachments < pass->targets_per_pass_ || limits.maxFragmentOutputAttachments < pass->targets_per_pass_)
    return make_error("shadow splat: order " + std::to_string(order) + " needs " +
                      std::to_string(pass->targets_per_pass_) + " colour attachments, the device allows " +
                      std::to_string(std::min(limits.maxColorAttachments, limits.maxFragmentOutputAttachments)));
  const std::uint32_t k = receiver_scale;
  pass->receiver_width_ = (display_width + k - 1) / k;
  pass->receiver_height_ = (display_height + k - 1) / k;
  // Receiver pixel x's center must project from display texel x·k + ⌊k/2⌋ (receivers.comp), i.e.
  // display coordinate x·k + ⌊k/2⌋ + 0.5: a viewport of the display's size / k, shifted.
  const float shift = 0.5f - (float(k / 2) + 0.5f) / float(k);
  pass->viewport_x_ = pass->viewport_y_ = shift;
  pass->viewport_width_ = float(display_width) / float(k);
  pass->viewport_height_ = float(display_height) / float(k);

  const std::string suffix = ":order" + std::to_string(order);
  GraphicsPipelineDescription depth;
  depth.vertex_shader = "fullscreen.vert";
  depth.fragment_shader = "receiver_depth.frag";
  depth.depth_format = kDepthFormat;
  depth.depth_test = depth.depth_write = true;
  depth.depth_compare = VK_COMPARE_OP_ALWAYS;
  const Binding depth_bindings[] = {{gpu_layout::kSplatBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kFragment},
                                    {gpu_layout::kSplatBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFragment}};
  auto depth_pipeline = Pipeline::graphics(context, depth, depth_bindings, 0);
  if (!depth_pipeline) return make_error("receiver_depth.frag: " + depth_pipeline.message());
  pass->depth_pipeline_ = std::move(*depth_pipeline);

  GraphicsPipelineDescription splat;
  splat.vertex_shader = "shadow_splat.vert";
  splat.fragment_shader = "shadow_splat.frag" + suffix;
  splat.color_formats.assign(pass->targets_per_pass_, kTargetFormat);
  splat.depth_format = kDepthFormat;
  splat.depth_test = true;
  splat.depth_compare = VK_COMPARE_OP_GREATER;
  splat.blend = BlendMode::additive;
  splat.cull = VK_CULL_MODE_FRONT_BIT;  // keep the back faces (y-down projection: outside CCW is front)
  const Binding splat_bindings[] = {{gpu_layout::kSplatBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kVertex | kFragment},
                                    {gpu_layout::kSplatBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFragment},
                                    {gpu_layout::kSplatBindProxies, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kVertex},
                                    {gpu_layout::kSplatBindLogTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFragment},
                                    {gpu_layout::kSplatBindBoundingMesh, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kVertex}};
  auto splat_pipeline = Pipeline::graphics(context, splat, splat_bindings, sizeof(gpu_layout::SplatPush));
  if (!splat_pipeline) return make_error("shadow_splat.frag: " + splat_pipeline.message());
  pass->splat_pipeline_ = std::move(*splat_pipeline);

  const std::uint32_t read_targets = std::uint32_t(PROXYGI_SPLAT_TARGETS(order));
  std::vector<Binding> resolve_bindings = {
      {gpu_layout::kResolveBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
      {gpu_layout::kResolveBindLogOcclusion, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT}};
  for (std::uint32_t i = 0; i < read_targets; ++i)
    resolve_bindings.push_back(
        {gpu_layout::kResolveBindFirstTarget + i, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT});
  auto resolve_pipeline = Pipeline::compute(context, "splat_resolve.comp" + suffix, resolve_bindings, 0);
  if (!resolve_pipeline) return make_error("splat_resolve.comp: " + resolve_pipeline.message());
  pass->resolve_pipeline_ = std::move(*resolve_pipeline);

  for (std::uint32_t i = 0; i < pass->passes_ * pass->targets_per_pass_; ++i) {
    auto target = Image::create(context, pass->receiver_width_, pass->receiver_height_, kTargetFormat,
                                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT);
    if (!target) return target.error();
    pass->targets_.push_back(std::move(*target));
  }
  auto depth_image = Image::create(context, pass->receiver_width_, pass->receiver_height_, kDepthFormat,
                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  if (!depth_image) return depth_image.error();
  pass->depth_ = std::move(*depth_image);

  const auto mesh = unit_sphere_bounding_mesh();
  auto mesh_buffer = create_buffer_with_data(context, as_bytes(std::span<const glm::vec4>(mesh)),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  if (!mesh_buffer) return mesh_buffer.error();
  pass->bounding_mesh_ = std::move(*mesh_buffer);
  pass->mesh_vertices_ = std::uint32_t(mesh.size());
  return pass;
}

void ShadowSplatPass::set_viewport(VkCommandBuffer commands) const {
  const VkViewport viewport{viewport_x_, viewport_y_, viewport_width_, viewport_height_, 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {receiver_width_, receiver_height_}};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);
}

std::vector<ResourceAccess> ShadowSplatPass::accesses(const ShadowSplatInputs& inputs) const {
  constexpr VkPipelineStageFlags2 kGraphics = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
  return {reads(inputs.constants, kGraphics | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT),
          reads(inputs.receivers, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT),
          reads(inputs.proxies, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT),
          reads(inputs.log_table, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT), writes(inputs.log_occlusion)};
}

void ShadowSplatPass::record(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const {
  record_depth(commands, inputs);
  record_splat(commands, inputs);
  record_resolve(commands, inputs);
}

void ShadowSplatPass::record_depth(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const {
  transition(commands, depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  VkRenderingAttachmentInfo depth =
      attachment_info(depth_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR);
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {receiver_width_, receiver_height_}};
  rendering.layerCount = 1;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(commands, &rendering);
  set_viewport(commands);
  depth_pipeline_.bind(commands);
  DescriptorPush()
      .uniform_buffer(gpu_layout::kSplatBindFrame, *inputs.constants)
      .storage_buffer(gpu_layout::kSplatBindReceivers, *inputs.receivers)
      .push(context_, commands, depth_pipeline_);
  vkCmdDraw(commands, 3, 1, 0, 0);
  vkCmdEndRendering(commands);
  memory_barrier(commands);
}

void ShadowSplatPass::record_splat(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const {
  for (const Image& target : targets_)
    transition(commands, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  const VkRenderingAttachmentInfo depth =
      attachment_info(depth_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_LOAD);
  for (std::uint32_t pass = 0; pass < passes_; ++pass) {
    std::vector<VkRenderingAttachmentInfo> colors;
    for (std::uint32_t i = 0; i < targets_per_pass_; ++i) {
      colors.push_back(attachment_info(targets_[pass * targets_per_pass_ + i], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                  VK_ATTACHMENT_LOAD_OP_CLEAR));
      colors.back().clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
    }
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {receiver_width_, receiver_height_}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = std::uint32_t(colors.size());
    rendering.pColorAttachments = colors.data();
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(commands, &rendering);
    set_viewport(commands);
    splat_pipeline_.bind(commands);
    DescriptorPush()
        .uniform_buffer(gpu_layout::kSplatBindFrame, *inputs.constants)
        .storage_buffer(gpu_layout::kSplatBindReceivers, *inputs.receivers)
        .uniform_buffer(gpu_layout::kSplatBindProxies, *inputs.proxies)
        .storage_buffer(gpu_layout::kSplatBindLogTable, *inputs.log_table)
        .storage_buffer(gpu_layout::kSplatBindBoundingMesh, bounding_mesh_)
        .push(context_, commands, splat_pipeline_);
    const gpu_layout::SplatPush push{4 * pass * targets_per_pass_, 0, 0, 0};
    splat_pipeline_.push_constants(commands, &push, sizeof(push));
    if (inputs.proxy_count > 0) vkCmdDraw(commands, mesh_vertices_, inputs.proxy_count, 0, 0);
    vkCmdEndRendering(commands);
  }
  for (const Image& target : targets_)
    transition(commands, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
}

void ShadowSplatPass::record_resolve(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const {
  resolve_pipeline_.bind(commands);
  DescriptorPush push;
  push.uniform_buffer(gpu_layout::kResolveBindFrame, *inputs.constants)
      .storage_buffer(gpu_layout::kResolveBindLogOcclusion, *inputs.log_occlusion);
  const std::uint32_t read_targets = std::uint32_t(PROXYGI_SPLAT_TARGETS(order_));
  for (std::uint32_t i = 0; i < read_targets; ++i)
    push.storage_image(gpu_layout::kResolveBindFirstTarget + i, targets_[i].view());
  push.push(context_, commands, resolve_pipeline_);
  vkCmdDispatch(commands, group_count(receiver_width_, gpu_layout::kFrameLocalSize),
                group_count(receiver_height_, gpu_layout::kFrameLocalSize), 1);
  memory_barrier(commands);
}

}  // namespace proxygi::gpu
