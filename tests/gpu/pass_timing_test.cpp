// Per-pass times for the viewer's HUD (SceneRenderer::time_passes): with timestamps asked for,
// either GPU timestamps (where the device's are valid and their sum is plausible) whose per-pass
// times are non-negative and sum to at most the frame's fenced time, or fenced CPU timings with
// the reason; the fenced CPU clock of `bench frame` times every pass it records. Times are
// checked for consistency only, never against a speed.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "gpu/pass_timestamps.h"
#include "gpu/scene_renderer.h"
#include "gpu_test_context.h"
#include "scene/scene_defaults.h"

namespace proxygi::gpu {
namespace {

using PassTimingTest = testing::GpuTest;

TEST_F(PassTimingTest, TimestampsWhereValidElseFencedCpuTimingsWithTheReason) {
  const std::string unusable = timestamps_unusable(context());
  std::printf("device %s: timestamps %s\n", context().report().name.c_str(), unusable.empty() ? "valid" : unusable.c_str());
  scene::Scene scene = scene::default_scene();
  scene.output.width = scene.output.height = 64;
  auto renderer = SceneRenderer::create(context(), scene, {PROXYGI_SOURCE_DIR "/assets", false});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  ASSERT_TRUE((*renderer)->render(10).ok());  // warm: the first dispatches compile
  const auto passes = frame_pass_order((*renderer)->frame().settings().method);

  auto fenced = (*renderer)->time_passes(10, PassClock::fenced_cpu);
  ASSERT_TRUE(fenced.ok()) << fenced.message();
  EXPECT_FALSE(fenced->timestamps);
  for (FramePass pass : passes) EXPECT_GT(fenced->milliseconds[std::size_t(pass)], 0.0) << frame_pass_name(pass);

  auto timed = (*renderer)->time_passes(10, PassClock::timestamps_if_valid);
  ASSERT_TRUE(timed.ok()) << timed.message();
  double sum = timed->milliseconds[std::size_t(FramePass::skin)];
  for (FramePass pass : passes) {
    EXPECT_GE(timed->milliseconds[std::size_t(pass)], 0.0) << frame_pass_name(pass);
    sum += timed->milliseconds[std::size_t(pass)];
  }
  for (FramePass pass : passes)
    std::printf("  %-20s %8.3f ms (%s)  %8.3f ms (fenced, one submit each)\n", frame_pass_name(pass),
                timed->milliseconds[std::size_t(pass)], timed->timestamps ? "timestamps" : "fenced", fenced->milliseconds[std::size_t(pass)]);
  std::printf("pass times from %s: sum %.3f ms, fenced frame %.3f ms %s\n", timed->timestamps ? "GPU timestamps" : "fenced CPU",
              sum, timed->frame_fenced_ms, timed->note.c_str());
  if (timed->timestamps) {
    EXPECT_TRUE(unusable.empty());
    EXPECT_GT(timed->frame_fenced_ms, 0.0);
    EXPECT_LE(sum, timed->frame_fenced_ms * (1.0 + 1e-9));
    EXPECT_TRUE(timed->note.empty());
  } else {
    EXPECT_FALSE(timed->note.empty()) << "fenced CPU timings say why timestamps were not used";
    if (!unusable.empty()) {
      EXPECT_NE(timed->note.find(unusable), std::string::npos) << timed->note;
    }
  }
  // Lavapipe reports valid timestamps (64 bits, 1 ns): the query path runs there.
  if (context().report().driver.find("llvmpipe") != std::string::npos || context().report().name.find("llvmpipe") != std::string::npos) {
    EXPECT_TRUE(unusable.empty());
  }
}

}  // namespace
}  // namespace proxygi::gpu

namespace proxygi::gpu {
namespace {

// FrameRequest::pass_timestamps: the frame itself carries the timestamps (no frame of its own, no
// fence), its pixels are those of the same frame untimed, and a ring slot reused without the
// flag reports nothing.
TEST_F(PassTimingTest, TimestampsInTheFrameShownLeaveItsPixelsAndTimeEveryPass) {
  const std::string unusable = timestamps_unusable(context());
  scene::Scene scene = scene::default_scene();
  scene.output.width = scene.output.height = 64;
  auto renderer = SceneRenderer::create(context(), scene, {PROXYGI_SOURCE_DIR "/assets", false});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const auto passes = frame_pass_order((*renderer)->frame().settings().method);
  auto request = [&](int frame, bool timed) {
    FrameRequest r;
    r.time_s = scene::frame_time_s(scene.output, frame);
    r.frame = frame;
    r.pass_timestamps = timed;
    return r;
  };
  auto plain = (*renderer)->render(request(10, false));
  ASSERT_TRUE(plain.ok()) << plain.message();
  EXPECT_FALSE(plain->passes.has_value());

  // Two frames in flight, the first timed: each slot reports only its own frame's timestamps.
  auto first = (*renderer)->begin(request(10, true));
  ASSERT_TRUE(first.ok()) << first.message();
  auto second = (*renderer)->begin(request(11, false));
  ASSERT_TRUE(second.ok()) << second.message();
  auto timed = (*renderer)->finish(*first);
  ASSERT_TRUE(timed.ok()) << timed.message();
  auto untimed = (*renderer)->finish(*second);
  ASSERT_TRUE(untimed.ok()) << untimed.message();
  EXPECT_FALSE(untimed->passes.has_value());
  EXPECT_EQ(timed->ldr, plain->ldr) << "timestamps changed the frame";
  ASSERT_TRUE(timed->passes.has_value());
  const PassTimings& t = *timed->passes;
  EXPECT_EQ(t.proxies, timed->statistics.proxies);
  if (!unusable.empty()) {
    EXPECT_FALSE(t.timestamps);
    EXPECT_NE(t.note.find(unusable), std::string::npos) << t.note;
    return;
  }
  ASSERT_TRUE(t.timestamps) << t.note;
  EXPECT_TRUE(t.note.empty()) << t.note;
  double sum = t.milliseconds[std::size_t(FramePass::skin)];
  for (FramePass pass : passes) {
    EXPECT_GE(t.milliseconds[std::size_t(pass)], 0.0) << frame_pass_name(pass);
    sum += t.milliseconds[std::size_t(pass)];
  }
  EXPECT_GT(sum, 0.0);
  for (std::size_t p = 0; p < std::size_t(FramePass::count); ++p) {  // passes the method does not record stay 0
    if (p != std::size_t(FramePass::skin) && std::find(passes.begin(), passes.end(), FramePass(p)) == passes.end()) {
      EXPECT_EQ(t.milliseconds[p], 0.0) << frame_pass_name(FramePass(p));
    }
  }
  std::printf("in-frame timestamps: sum %.3f ms\n", sum);

  // The slot of the timed frame, reused untimed, reports nothing.
  auto again = (*renderer)->render(request(12, false));
  ASSERT_TRUE(again.ok()) << again.message();
  auto reused = (*renderer)->render(request(13, false));
  ASSERT_TRUE(reused.ok()) << reused.message();
  EXPECT_FALSE(again->passes.has_value());
  EXPECT_FALSE(reused->passes.has_value());
}

}  // namespace
}  // namespace proxygi::gpu
