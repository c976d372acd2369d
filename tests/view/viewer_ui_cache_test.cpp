// The cached UI overlay on the GPU (label gpu, validation on, zero messages): the blend pass is
// its CPU twin; a frame whose UI comes from an overlay drawn frames earlier equals the frame
// with ImGui drawn straight onto it; the overlay is drawn again when the UI changes, not when
// it does not, and the panels' numbers at most every kOverlayPanelPeriodS.
#include <cstring>

#include "gpu/gpu_test_context.h"
#include "gpu/resources.h"
#include "gpu/transfer.h"
#include "view/overlay_blend_pass.h"
#include "viewer_test_util.h"

namespace proxygi::view {
namespace {

using ViewerUiCacheTest = gpu::testing::GpuTest;
using namespace view::testing;

// An image of `bytes` (RGBA8, tightly packed), left in `layout`.
gpu::Image upload(gpu::Context& context, const std::vector<std::uint8_t>& bytes, std::uint32_t width,
                  std::uint32_t height, VkImageUsageFlags usage, VkImageLayout layout) {
  auto image = gpu::Image::create(context, width, height, VK_FORMAT_R8G8B8A8_UNORM, usage | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  EXPECT_TRUE(image.ok()) << image.message();
  auto staging = gpu::Buffer::create(context, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryKind::host_visible);
  EXPECT_TRUE(staging.ok()) << staging.message();
  std::memcpy(staging->mapped(), bytes.data(), bytes.size());
  Status copied = context.submit_and_wait([&](VkCommandBuffer commands) {
    gpu::transition(commands, image->handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(commands, staging->handle(), image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::transition(commands, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layout);
  });
  EXPECT_TRUE(copied.ok()) << copied.message();
  return std::move(*image);
}

TEST_F(ViewerUiCacheTest, OverlayBlendPassIsItsCpuTwinInsideTheRectsAndLeavesTheRestAlone) {
  const std::uint32_t width = 70, height = 45;
  std::vector<std::uint8_t> frame(std::size_t(width) * height * 4), overlay(frame.size());
  std::uint32_t seed = 12345;
  auto next = [&seed] { return (seed = seed * 1664525u + 1013904223u) >> 24; };
  for (std::size_t i = 0; i < frame.size(); i += 4) {
    for (int c = 0; c < 4; ++c) frame[i + std::size_t(c)] = std::uint8_t(next());
    const std::uint32_t alpha = next();  // premultiplied: colour at most the coverage
    for (int c = 0; c < 3; ++c) overlay[i + std::size_t(c)] = std::uint8_t(alpha ? next() % (alpha + 1) : 0);
    overlay[i + 3] = std::uint8_t(alpha);
  }
  const auto rects = covering_rects(std::vector<PixelRect>{{5, 3, 40, 20}, {50, 30, 70, 45}}, int(width), int(height), 16);
  ASSERT_GE(rects.size(), 2u);
  gpu::Image target_image = upload(context(), frame, width, height,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  gpu::Image overlay_image = upload(context(), overlay, width, height, VK_IMAGE_USAGE_SAMPLED_BIT,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  auto pass = OverlayBlendPass::create(context(), VK_FORMAT_R8G8B8A8_UNORM);
  ASSERT_TRUE(pass.ok()) << pass.message();
  const TargetImage target{target_image.handle(), target_image.view(), target_image.format(), width, height};
  ASSERT_TRUE(context().submit_and_wait([&](VkCommandBuffer commands) {
    (*pass)->record(context(), commands, {overlay_image.view(), rects}, {&target});
  }).ok());
  auto blended = read_target(context(), target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  ASSERT_TRUE(blended.ok()) << blended.message();

  std::vector<bool> inside(std::size_t(width) * height, false);
  for (const PixelRect& rect : rects)
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) inside[std::size_t(y) * width + std::size_t(x)] = true;
  int worst = 0, outside_changed = 0;
  for (std::size_t p = 0; p < inside.size(); ++p) {
    std::vector<std::uint8_t> expected(frame.begin() + std::ptrdiff_t(4 * p), frame.begin() + std::ptrdiff_t(4 * p + 4));
    if (inside[p]) {
      blend_overlay(std::span(overlay).subspan(4 * p, 4), expected);
      for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int((*blended)[4 * p + std::size_t(c)]) - int(expected[std::size_t(c)])));
    } else {
      outside_changed += std::memcmp(&(*blended)[4 * p], expected.data(), 4) != 0;
    }
  }
  EXPECT_LE(worst, 1);  // an 8-bit blend unit's rounding against the twin's exact rounding
  EXPECT_EQ(outside_changed, 0);
}

// The default scene paused, the HUD hidden (H: its frame times are wall-clock, so two runs
// would differ): the playback bar, the settings header and the view legend stay.
std::string idle_script(const std::string& more_events) {
  return R"({"step_s": 0.05, "events": [{"t": 0, "key": "h"})" + more_events + "]}";
}

TEST_F(ViewerUiCacheTest, AFrameWithACachedOverlayEqualsTheFrameWithTheUiDrawnOnIt) {
  const std::string script = idle_script(R"(, {"t": 0.5, "screenshot": "ui.png", "ui": true})");
  const auto cached = run_viewer_script(script, "default", 160, 120, true, "ui_cache_cached");
  const auto direct = run_viewer_script(script, "default", 160, 120, true, "ui_cache_direct",
                                        [](ViewerOptions& options) { options.ui_cache = false; });
  ASSERT_TRUE(cached.status.ok()) << cached.status.message();
  ASSERT_TRUE(direct.status.ok()) << direct.status.message();
  // The screenshot blended an overlay drawn frames before it (nothing changed since).
  EXPECT_EQ(cached.state["ui_screenshots_reusing_overlay"], 1);
  EXPECT_GT(cached.state["ui_overlay_reuses"].get<int>(), 0);
  EXPECT_EQ(direct.state["ui_overlay_draws"], 0);
  EXPECT_GT(direct.state["ui_direct_draws"].get<int>(), 0);
  const Shot& with_cache = cached.shots.at("ui.png");
  const Shot& drawn = direct.shots.at("ui.png");
  expect_within_one_code(with_cache, drawn.rgba, "ui_cache_cached", "cached_vs_direct");
  // And the UI is there: the hidden-UI frame differs.
  const auto hidden = run_viewer_script(idle_script(R"(, {"t": 0.5, "screenshot": "ui.png", "ui": false})"), "default",
                                        160, 120, true, "ui_cache_hidden");
  ASSERT_TRUE(hidden.status.ok()) << hidden.status.message();
  EXPECT_GT(max_code_difference(hidden.shots.at("ui.png").rgba, drawn.rgba), 1);
}

TEST_F(ViewerUiCacheTest, TheOverlayIsDrawnAgainWhenTheUiChangesAndOnlyThen) {
  // Paused and idle for 1 s (21 frames): the overlay is drawn when ImGui's windows settle, then
  // reused. Each arrow key steps a frame, which the playback bar shows: drawn again at once.
  const auto idle = run_viewer_script(idle_script(R"(, {"t": 1.0, "key": "f1"}, {"t": 1.0, "key": "f1"})"), "default", 96, 96, true, "ui_cache_idle");
  std::string keys;
  for (int i = 1; i <= 8; ++i) keys += R"(, {"t": )" + std::to_string(0.1 * i) + R"(, "key": "right"})";
  const auto stepped = run_viewer_script(idle_script(keys + R"(, {"t": 1.0, "key": "f1"}, {"t": 1.0, "key": "f1"})"), "default", 96, 96, true, "ui_cache_stepped");
  ASSERT_TRUE(idle.status.ok()) << idle.status.message();
  ASSERT_TRUE(stepped.status.ok()) << stepped.status.message();
  const int idle_draws = idle.state["ui_overlay_draws"], stepped_draws = stepped.state["ui_overlay_draws"];
  EXPECT_LE(idle_draws, 4);  // first frame and ImGui's auto-sized windows settling
  EXPECT_GE(idle.state["ui_overlay_reuses"].get<int>(), 15);
  EXPECT_GE(stepped_draws, idle_draws + 8);  // every step shows at once
  EXPECT_EQ(stepped.state["frame"], 8);

  // Playing with the HUD shown: the panels change every frame, drawn about every 0.25 s of
  // the script's clock (2 s at 0.05 s a frame: 40 frames, about 8 draws).
  const auto playing = run_viewer_script(R"({"step_s": 0.05, "events": [{"t": 0, "key": "space"}, {"t": 2.0, "key": "space"}]})",
                                         "default", 96, 96, true, "ui_cache_playing");
  ASSERT_TRUE(playing.status.ok()) << playing.status.message();
  const int draws = playing.state["ui_overlay_draws"], reuses = playing.state["ui_overlay_reuses"];
  EXPECT_GE(draws, int(2.0 / kOverlayPanelPeriodS) - 1);
  EXPECT_LE(draws, int(2.0 / kOverlayPanelPeriodS) + 4);  // + the key frames and settling
  EXPECT_GE(reuses, 40 - draws - 2);
}

}  // namespace
}  // namespace proxygi::view
