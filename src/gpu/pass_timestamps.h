#pragma once
// GPU timestamps of a frame's passes: a query pool with one timestamp before the first pass and
// one after each, written with vkCmdWriteTimestamp (after every earlier command completed:
// BOTTOM_OF_PIPE), read back once the submission's fence signalled.
//
// Timestamps are used only where the device says they are valid: timestampValidBits > 0 on the
// queue family and timestampPeriod > 0. Lavapipe reports them valid (64 bits, 1 ns), but they are
// known to go wrong after graphics draws (rendering-notes §4.2), so callers cross-check their sum
// against the fenced wall-clock time of the same submission (SceneRenderer::time_passes).
//
//   auto queries = TimestampQueries::create(context, passes + 1);
//   queries->reset(commands); queries->write(commands, 0); ...record pass i...; queries->write(commands, i + 1);
//   submit and wait; auto ms = queries->intervals_ms();   // ms[i]: pass i
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace proxygi::gpu {

class Context;

// Why the device's timestamps cannot be used, or empty when they can.
std::string timestamps_unusable(const Context& context);

class TimestampQueries {
 public:
  // Errors when timestamps_unusable(context) is not empty, or the pool cannot be made.
  static Result<TimestampQueries> create(const Context& context, std::uint32_t count);
  TimestampQueries() = default;
  ~TimestampQueries();
  TimestampQueries(TimestampQueries&& other) noexcept;
  TimestampQueries& operator=(TimestampQueries&& other) noexcept;
  TimestampQueries(const TimestampQueries&) = delete;
  TimestampQueries& operator=(const TimestampQueries&) = delete;

  void reset(VkCommandBuffer commands) const;  // outside a render pass, before the first write
  void write(VkCommandBuffer commands, std::uint32_t index) const;
  // Milliseconds between consecutive timestamps of the first `written` (count − 1 values when
  // 0: all), after the submission completed; the valid-bit mask and period applied. Only
  // timestamps written since the last reset may be read (an unwritten one never becomes ready).
  Result<std::vector<double>> intervals_ms(std::uint32_t written = 0) const;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  std::uint32_t count_ = 0;
  std::uint64_t mask_ = ~0ull;
  double period_ns_ = 1.0;
};

}  // namespace proxygi::gpu
