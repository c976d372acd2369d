#include "gpu/pass_timestamps.h"

#include <string>
#include <utility>

#include "gpu/context.h"
#include "gpu/vulkan_check.h"

namespace proxygi::gpu {
namespace {

std::uint32_t valid_bits(const Context& context) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(context.physical_device(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(context.physical_device(), &count, families.data());
  return context.queue_family() < count ? families[context.queue_family()].timestampValidBits : 0u;
}

}  // namespace

std::string timestamps_unusable(const Context& context) {
  if (valid_bits(context) == 0) return "the queue family has no timestamp bits";
  if (!(context.limits().timestampPeriod > 0.0f)) return "timestampPeriod is 0";
  return {};
}

Result<TimestampQueries> TimestampQueries::create(const Context& context, std::uint32_t count) {
  if (std::string why = timestamps_unusable(context); !why.empty()) return make_error("timestamps: " + why);
  if (count < 2) return make_error("timestamps: need at least two");
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = count;
  TimestampQueries queries;
  PROXYGI_VK_TRY(vkCreateQueryPool(context.device(), &info, nullptr, &queries.pool_));
  queries.device_ = context.device();
  queries.count_ = count;
  const std::uint32_t bits = valid_bits(context);
  queries.mask_ = bits >= 64 ? ~0ull : (1ull << bits) - 1ull;
  queries.period_ns_ = double(context.limits().timestampPeriod);
  return queries;
}

TimestampQueries::~TimestampQueries() {
  if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
}

TimestampQueries::TimestampQueries(TimestampQueries&& other) noexcept { *this = std::move(other); }

TimestampQueries& TimestampQueries::operator=(TimestampQueries&& other) noexcept {
  if (this != &other) {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    count_ = std::exchange(other.count_, 0);
    mask_ = other.mask_;
    period_ns_ = other.period_ns_;
  }
  return *this;
}

void TimestampQueries::reset(VkCommandBuffer commands) const { vkCmdResetQueryPool(commands, pool_, 0, count_); }

void TimestampQueries::write(VkCommandBuffer commands, std::uint32_t index) const {
  vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, index);
}

Result<std::vector<double>> TimestampQueries::intervals_ms(std::uint32_t written) const {
  if (written == 0) written = count_;
  if (written < 2 || written > count_)
    return make_error("timestamps: " + std::to_string(written) + " read of a pool of " + std::to_string(count_));
  std::vector<std::uint64_t> ticks(written);
  PROXYGI_VK_TRY(vkGetQueryPoolResults(device_, pool_, 0, written, ticks.size() * sizeof(std::uint64_t), ticks.data(),
                                       sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  std::vector<double> ms;
  for (std::uint32_t i = 0; i + 1 < written; ++i) {
    const std::uint64_t delta = ((ticks[i + 1] & mask_) - (ticks[i] & mask_)) & mask_;  // wraps within the valid bits
    ms.push_back(double(delta) * period_ns_ * 1e-6);
  }
  return ms;
}

}  // namespace proxygi::gpu
