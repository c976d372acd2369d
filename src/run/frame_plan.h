#pragma once
// Which frames one `proxygi record` process renders: the scene's output range, optionally
// narrowed by --frames A:B (inclusive) and split by --shard I/N; and which contiguous run of a
// work list (regress checks, bench chart units) one shard takes.
//
// Shard rule: shard I of N takes every frame f of the range with (f - A) mod N == I, where A is
// the first frame of the range. Shards are disjoint, cover the range, and are balanced to within
// one frame, so N independent processes (Slurm arrays, GNU parallel) writing into one folder
// produce exactly the files of a single run.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::run {

struct FrameRange {
  int first = 0;  // inclusive
  int last = 0;   // inclusive, >= first
  bool operator==(const FrameRange&) const = default;
};

struct Shard {
  int index = 0;  // 0-based, < count
  int count = 1;  // >= 1
  bool operator==(const Shard&) const = default;
};

// "A:B" with integers 0 <= A <= B. Errors quote the text.
Result<FrameRange> parse_frame_range(std::string_view text);
// "I/N" with integers 0 <= I < N. Errors quote the text.
Result<Shard> parse_shard(std::string_view text);

// The scene's own range: first_frame .. last_frame(output).
FrameRange scene_frame_range(const scene::Output& output);

// The frames this process renders, ascending. `requested` must lie inside the scene's range
// (an error names both ranges otherwise). May be empty when the shard count exceeds the range.
Result<std::vector<int>> plan_frames(const scene::Output& output, const std::optional<FrameRange>& requested,
                                     const Shard& shard);

// Shard I of N of a list of `count` work items, for work where neighbours share set-up (regress:
// a scenario's world; bench chart: a scene's references): the I-th of N contiguous runs,
// [count·I/N, count·(I+1)/N). Disjoint, covering, balanced to within one item; may be empty.
struct IndexRange {
  std::size_t begin = 0, end = 0;  // [begin, end)
  bool contains(std::size_t i) const { return i >= begin && i < end; }
};
IndexRange shard_slice(std::size_t count, const Shard& shard);

}  // namespace proxygi::run
