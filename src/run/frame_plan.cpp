#include "run/frame_plan.h"

#include <algorithm>
#include <charconv>

namespace proxygi::run {
namespace {

// A whole non-negative decimal integer (no sign, no spaces, no trailing characters).
std::optional<int> parse_count(std::string_view text) {
  if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

Result<FrameRange> parse_frame_range(std::string_view text) {
  const std::string quoted = "--frames '" + std::string(text) + "'";
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) return make_error(quoted + ": expected A:B (first and last frame, inclusive)");
  const auto first = parse_count(text.substr(0, colon));
  const auto last = parse_count(text.substr(colon + 1));
  if (!first || !last) return make_error(quoted + ": expected A:B with non-negative integers A <= B");
  if (*first > *last) return make_error(quoted + ": first frame is after the last frame");
  return FrameRange{*first, *last};
}

Result<Shard> parse_shard(std::string_view text) {
  const std::string quoted = "--shard '" + std::string(text) + "'";
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return make_error(quoted + ": expected I/N (shard index I of N, 0-based)");
  const auto index = parse_count(text.substr(0, slash));
  const auto count = parse_count(text.substr(slash + 1));
  if (!index || !count) return make_error(quoted + ": expected I/N with non-negative integers");
  if (*count < 1) return make_error(quoted + ": the shard count N must be at least 1");
  if (*index >= *count) return make_error(quoted + ": the shard index must be below N (0-based)");
  return Shard{*index, *count};
}

FrameRange scene_frame_range(const scene::Output& output) {
  return {output.first_frame, scene::last_frame(output)};
}

Result<std::vector<int>> plan_frames(const scene::Output& output, const std::optional<FrameRange>& requested,
                                     const Shard& shard) {
  const FrameRange scene_range = scene_frame_range(output);
  const FrameRange range = requested.value_or(scene_range);
  if (range.first < scene_range.first || range.last > scene_range.last)
    return make_error("--frames " + std::to_string(range.first) + ":" + std::to_string(range.last) +
                      " is outside the scene's frames " + std::to_string(scene_range.first) + ":" +
                      std::to_string(scene_range.last));
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count)
    return make_error("shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) + " is invalid");
  std::vector<int> frames;
  for (long long f = range.first + shard.index; f <= range.last; f += shard.count) frames.push_back(int(f));
  return frames;
}

IndexRange shard_slice(std::size_t count, const Shard& shard) {
  const std::size_t n = std::size_t(std::max(1, shard.count)), i = std::size_t(std::clamp(shard.index, 0, shard.count - 1));
  return {count * i / n, count * (i + 1) / n};
}

}  // namespace proxygi::run
