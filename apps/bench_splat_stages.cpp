#include "apps/bench_splat_stages.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

#include "gpu/shadow_splat_pass.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::app {
namespace {

Result<double> median_ms(gpu::Context& context, int repeats, const std::function<void(VkCommandBuffer)>& record) {
  std::vector<double> times;
  for (int i = 0; i < repeats + 1; ++i) {  // the first submit warms up (JIT) and is dropped
    const auto begin = std::chrono::steady_clock::now();
    if (Status done = context.submit_and_wait(record); !done) return done.error();
    if (i > 0) times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

Result<SplatStageTimes> time_splat_stages(gpu::Context& context, int order, std::uint32_t size,
                                          std::uint32_t receiver_scale, int repeats) {
  auto pass = gpu::ShadowSplatPass::create(context, order, size, size, receiver_scale);
  if (!pass) return pass.error();
  const std::uint32_t receivers_side = (size + receiver_scale - 1) / receiver_scale;
  const VkDeviceSize receivers = VkDeviceSize(receivers_side) * receivers_side;
  gpu_layout::FrameConstants constants{};
  constants.display_width = constants.display_height = size;
  constants.receiver_width = constants.receiver_height = receivers_side;
  constants.view_projection = glm::mat4(1.0f);
  constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  auto constant_buffer = gpu::create_buffer_with_data(
      context, gpu::as_bytes(std::span<const gpu_layout::FrameConstants>(&constants, 1)),
      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  const std::vector<gpu_layout::Receiver> empty(receivers, gpu_layout::Receiver{});  // no receivers: depth 1
  auto receiver_buffer =
      gpu::create_buffer_with_data(context, gpu::as_bytes(std::span<const gpu_layout::Receiver>(empty)), kStorage);
  const std::vector<gpu_layout::ProxySphere> proxies(gpu_layout::kMaxProxies, gpu_layout::ProxySphere{});
  auto proxy_buffer = gpu::create_buffer_with_data(
      context, gpu::as_bytes(std::span<const gpu_layout::ProxySphere>(proxies)), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  const std::vector<float> table(std::size_t(2 * order), 0.0f);
  auto table_buffer = gpu::create_buffer_with_data(context, gpu::as_bytes(std::span<const float>(table)), kStorage);
  auto log_occlusion = gpu::Buffer::create(context, receivers * VkDeviceSize(order * order) * sizeof(float), kStorage,
                                           gpu::MemoryKind::device_local);
  if (!constant_buffer) return constant_buffer.error();
  if (!receiver_buffer) return receiver_buffer.error();
  if (!proxy_buffer) return proxy_buffer.error();
  if (!table_buffer) return table_buffer.error();
  if (!log_occlusion) return log_occlusion.error();
  const gpu::ShadowSplatInputs inputs{&*constant_buffer, &*receiver_buffer, &*proxy_buffer, 0, &*table_buffer,
                                      &*log_occlusion};
  // The resolve reads the targets in the layout the splat leaves them in: run the pass once.
  if (Status done = context.submit_and_wait([&](VkCommandBuffer commands) { (*pass)->record(commands, inputs); });
      !done)
    return done.error();
  SplatStageTimes times;
  auto depth = median_ms(context, repeats, [&](VkCommandBuffer commands) { (*pass)->record_depth(commands, inputs); });
  if (!depth) return depth.error();
  times.depth_ms = *depth;
  auto resolve =
      median_ms(context, repeats, [&](VkCommandBuffer commands) { (*pass)->record_resolve(commands, inputs); });
  if (!resolve) return resolve.error();
  times.resolve_ms = *resolve;
  return times;
}

}  // namespace proxygi::app
