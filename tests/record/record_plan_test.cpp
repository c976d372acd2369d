// The frame planner of `proxygi record`: --frames and --shard parsing, range checks, and the
// shard rule (shards are disjoint, cover the range, balanced to one frame).
#include <gtest/gtest.h>

#include <algorithm>

#include "run/frame_plan.h"

namespace proxygi::run {
namespace {

scene::Output output_range(int first, int count) {
  scene::Output output;
  output.first_frame = first;
  output.frame_count = count;
  return output;
}

TEST(RecordPlan, ParsesFrameRanges) {
  ASSERT_TRUE(parse_frame_range("0:23"));
  EXPECT_EQ(*parse_frame_range("0:23"), (FrameRange{0, 23}));
  EXPECT_EQ(*parse_frame_range("7:7"), (FrameRange{7, 7}));
  for (const char* bad : {"", "5", ":", "3:", ":4", "-1:3", "4:2", "a:b", "1:2:3", " 1:2", "1:2x", "+1:2",
                          "99999999999:1"})
    EXPECT_FALSE(parse_frame_range(bad)) << bad;
  EXPECT_NE(parse_frame_range("4:2").message().find("--frames '4:2'"), std::string::npos);
}

TEST(RecordPlan, ParsesShards) {
  ASSERT_TRUE(parse_shard("1/4"));
  EXPECT_EQ(*parse_shard("1/4"), (Shard{1, 4}));
  EXPECT_EQ(*parse_shard("0/1"), (Shard{0, 1}));
  for (const char* bad : {"", "1", "/", "2/2", "3/2", "0/0", "-1/2", "1/-2", "a/2", "1/2/3", "1 /2"})
    EXPECT_FALSE(parse_shard(bad)) << bad;
  EXPECT_NE(parse_shard("2/2").message().find("below N"), std::string::npos);
}

TEST(RecordPlan, DefaultsToTheScenesRange) {
  auto frames = plan_frames(output_range(10, 4), std::nullopt, {});
  ASSERT_TRUE(frames) << frames.message();
  EXPECT_EQ(*frames, (std::vector<int>{10, 11, 12, 13}));
  EXPECT_EQ(scene_frame_range(output_range(10, 4)), (FrameRange{10, 13}));
}

TEST(RecordPlan, RefusesRangesOutsideTheScene) {
  const scene::Output output = output_range(10, 4);  // frames 10..13
  EXPECT_TRUE(plan_frames(output, FrameRange{11, 13}, {}));
  auto before = plan_frames(output, FrameRange{9, 12}, {});
  ASSERT_FALSE(before);
  EXPECT_NE(before.message().find("10:13"), std::string::npos) << before.message();
  EXPECT_FALSE(plan_frames(output, FrameRange{12, 14}, {}));
}

TEST(RecordPlan, ShardsPartitionTheRangeByOffsetFromItsFirstFrame) {
  const scene::Output output = output_range(0, 96);
  const FrameRange range{5, 17};
  for (int count : {1, 2, 3, 5, 13, 20}) {
    std::vector<int> all;
    std::size_t smallest = 1000, largest = 0;
    for (int index = 0; index < count; ++index) {
      auto share = plan_frames(output, range, {index, count});
      ASSERT_TRUE(share) << share.message();
      for (int frame : *share) EXPECT_EQ((frame - range.first) % count, index) << frame << " in " << index << "/" << count;
      EXPECT_TRUE(std::is_sorted(share->begin(), share->end()));
      smallest = std::min(smallest, share->size());
      largest = std::max(largest, share->size());
      all.insert(all.end(), share->begin(), share->end());
    }
    std::sort(all.begin(), all.end());
    std::vector<int> expected;
    for (int f = range.first; f <= range.last; ++f) expected.push_back(f);
    EXPECT_EQ(all, expected) << count << " shards";
    EXPECT_LE(largest - smallest, 1u) << count << " shards";
  }
  EXPECT_EQ(*plan_frames(output, range, {1, 2}), (std::vector<int>{6, 8, 10, 12, 14, 16}));
}

TEST(RecordPlan, MoreShardsThanFramesLeavesSomeEmpty) {
  auto share = plan_frames(output_range(0, 2), std::nullopt, {3, 4});
  ASSERT_TRUE(share);
  EXPECT_TRUE(share->empty());
}

}  // namespace
}  // namespace proxygi::app

namespace proxygi::run {
namespace {

// The contiguous shard slices (regress checks, bench chart units) tile the list in order.
TEST(ShardSlice, ContiguousRunsCoverTheListInOrderBalanced) {
  for (std::size_t items : {0u, 1u, 4u, 7u, 25u})
    for (int count : {1, 2, 3, 8}) {
      std::size_t next = 0, smallest = items, largest = 0;
      for (int index = 0; index < count; ++index) {
        const IndexRange slice = shard_slice(items, {index, count});
        EXPECT_EQ(slice.begin, next) << index << "/" << count << " of " << items;
        EXPECT_LE(slice.begin, slice.end);
        next = slice.end;
        smallest = std::min(smallest, slice.end - slice.begin);
        largest = std::max(largest, slice.end - slice.begin);
      }
      EXPECT_EQ(next, items) << count << " shards of " << items;
      EXPECT_LE(largest - smallest, 1u) << count << " shards of " << items;
    }
  EXPECT_EQ(shard_slice(4, {1, 2}).begin, 2u);
  EXPECT_TRUE(shard_slice(4, {1, 2}).contains(3));
  EXPECT_FALSE(shard_slice(4, {1, 2}).contains(1));
}

}  // namespace
}  // namespace proxygi::run
