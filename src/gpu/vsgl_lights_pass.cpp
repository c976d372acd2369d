#include "gpu/vsgl_lights_pass.h"

#include <algorithm>

#include "base/check.h"
#include "sh/spherical_gaussian.h"
#include "sh/vsgl.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

static_assert(double(kVsglDiffuseSharpness) == sh::kDiffuseLobeSharpness, "λ_d is defined in sh/spherical_gaussian.h");
static_assert(double(kVsglMinRelativeVariance) == double(float(sh::kVsglMinRelativeVariance)),
              "the variance floor is defined in sh/vsgl.h");

std::size_t VsglLightsPass::partials_bytes() { return sizeof(VsglPartial) * kVsglMaxPartials; }
std::size_t VsglLightsPass::lights_bytes() { return sizeof(glm::uvec4) + sizeof(VsglLight) * kVsglMaxLights; }

Result<VsglLightsPass> VsglLightsPass::create(const Context& context) {
  const ComputeBinding bindings[] = {
      {kVsglBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},    {kVsglBindPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {kVsglBindNormals, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},  {kVsglBindIndices, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {kVsglBindPartials, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {kVsglBindLights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {kVsglBindExposure, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, "vsgl_lights.comp", bindings, sizeof(VsglLightsPush));
  if (!pipeline) return pipeline.error();
  VsglLightsPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> VsglLightsPass::accesses(const Inputs& in, const Outputs& out) const {
  std::vector<ResourceAccess> list = {reads(in.constants), writes(out.partials), writes(out.lights)};
  for (const DrawItem& draw : in.draws) {
    if (draw.vsgl_light < 0) continue;
    list.push_back(reads(draw.positions));
    list.push_back(reads(draw.normals));
    list.push_back(reads(draw.vsgl_group_first.empty() ? draw.indices : draw.vsgl_indices));
    if (draw.vsgl_exposure) list.push_back(reads(draw.vsgl_exposure));
  }
  return list;
}

std::vector<VsglLightRange> vsgl_light_ranges(std::span<const DrawItem> draws, std::uint32_t lights_per_sender) {
  std::vector<VsglLightRange> ranges;
  const std::uint32_t per_sender = std::max(lights_per_sender, 1u);
  for (std::size_t d = 0; d < draws.size(); ++d) {
    const DrawItem& draw = draws[d];
    if (draw.vsgl_light < 0) continue;
    const bool grouped = !draw.vsgl_group_first.empty();
    PROXYGI_CHECK(!grouped || (draw.vsgl_indices && draw.vsgl_group_first.size() == per_sender + 1),
                  "bone groups: one start per light and the end");
    const std::uint32_t total = draw.index_count / 3;
    for (std::uint32_t range = 0; range < per_sender; ++range) {
      VsglLightRange out;
      out.draw = d;
      out.indices = grouped ? draw.vsgl_indices : draw.indices;
      out.light = std::uint32_t(draw.vsgl_light) * per_sender + range;
      out.first = grouped ? draw.vsgl_group_first[range] : std::uint32_t(std::uint64_t(range) * total / per_sender);
      out.last = grouped ? draw.vsgl_group_first[range + 1] : std::uint32_t(std::uint64_t(range + 1) * total / per_sender);
      if (out.light >= kVsglMaxLights) continue;  // documented capacity
      ranges.push_back(out);
    }
  }
  return ranges;
}

std::uint32_t vsgl_light_count(std::span<const DrawItem> draws, std::uint32_t lights_per_sender) {
  std::uint32_t count = 0;
  for (const VsglLightRange& range : vsgl_light_ranges(draws, lights_per_sender)) count = std::max(count, range.light + 1);
  return count;
}

void VsglLightsPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                            const Outputs& out) const {
  pipeline_.bind(commands);
  std::uint32_t partial = in.first_partial, light_count = 0;
  for (const VsglLightRange& range : vsgl_light_ranges(in.draws, in.lights_per_sender)) {
    const DrawItem& draw = in.draws[range.draw];
    const std::uint32_t triangles = range.last - range.first;
    const std::uint32_t groups = group_count(triangles, kVsglGroupSize * kVsglTrianglesPerInvocation);
    light_count = std::max(light_count, range.light + 1);
    if (groups == 0 || partial + groups > kVsglMaxPartials) continue;  // fitted as zero
    DescriptorPush()
        .uniform_buffer(kVsglBindFrame, *in.constants)
        .storage_buffer(kVsglBindPositions, *draw.positions, draw.vertex_bytes())
        .storage_buffer(kVsglBindNormals, *draw.normals, draw.vertex_bytes())
        .storage_buffer(kVsglBindIndices, *range.indices)
        .storage_buffer(kVsglBindPartials, *out.partials)
        .storage_buffer(kVsglBindLights, *out.lights)
        .storage_buffer(kVsglBindExposure, draw.vsgl_exposure ? *draw.vsgl_exposure : *draw.positions)  // unread without
        .push(context, commands, pipeline_);
    VsglLightsPush push{};
    push.base_color = draw.base_color;
    push.has_exposure = draw.vsgl_exposure ? 1u : 0u;
    push.stage = kVsglStageSums;
    push.triangle_count = triangles;
    push.partial_offset = partial;
    push.light = range.light;
    push.first_triangle = range.first;
    pipeline_.push_constants(commands, &push, sizeof(push));
    vkCmdDispatch(commands, groups, 1, 1);
    partial += groups;
  }
  PassBarriers fit;  // the sums, then the fit reading them
  const ResourceAccess summed[] = {writes(out.partials)};
  const ResourceAccess fitted[] = {reads(out.partials), writes(out.lights)};
  fit.before(commands, summed);
  fit.before(commands, fitted);
  DescriptorPush()
      .uniform_buffer(kVsglBindFrame, *in.constants)
      .storage_buffer(kVsglBindPositions, *out.partials)  // unread by the fit; any buffer
      .storage_buffer(kVsglBindNormals, *out.partials)
      .storage_buffer(kVsglBindIndices, *out.partials)
      .storage_buffer(kVsglBindPartials, *out.partials)
      .storage_buffer(kVsglBindLights, *out.lights)
      .storage_buffer(kVsglBindExposure, *out.partials)
      .push(context, commands, pipeline_);
  VsglLightsPush push{};
  push.stage = kVsglStageFit;
  push.partial_count = partial;
  push.light_count = light_count;
  pipeline_.push_constants(commands, &push, sizeof(push));
  vkCmdDispatch(commands, group_count(kVsglMaxLights, kVsglGroupSize), 1, 1);
}

}  // namespace proxygi::gpu
