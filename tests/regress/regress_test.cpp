// The regression runner's CPU parts: scenario parsing (errors name the field), image comparison
// (threshold, failing fraction, shift radius), track comparison (proxies appearing), patterns,
// device families, results.json round trip and shard merging, the report's contents.
#include <gtest/gtest.h>

#include "regress/golden_store.h"
#include "regress/image_compare.h"
#include "regress/json_edit.h"
#include "regress/report.h"
#include "regress/runner.h"
#include "regress/scenario.h"
#include "regress/tracks.h"

namespace proxygi::regress {
namespace {

Result<Scenario> parse(const std::string& checks, const std::string& extra = "") {
  return parse_scenario(R"({"scenario_version": 1, "scene": "builtin:default", )" + extra + R"("checks": [)" + checks + "]}",
                        "dir/s.json", "");
}

TEST(Scenario, ParsesChecksAndOverrides) {
  auto s = parse(R"({"name": "a", "type": "image", "region": "ground", "shift_radius": 1},
                    {"name": "b", "type": "tracks", "joint_mm": 0.5},
                    {"name": "c", "type": "differential", "kind": "settings", "a": {"render.splat": "compute"}, "b": {"render.splat": "raster"}})",
                 R"("overrides": {"render.sh_order": 5, "output.width": 64}, "checkpoints": [0, 10], )");
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->name, "s");
  EXPECT_EQ(s->scene.render.sh_order, 5);
  EXPECT_EQ(s->scene.output.width, 64);
  ASSERT_EQ(s->checks.size(), 3u);
  EXPECT_EQ(s->checks[0].region, Region::ground);
  EXPECT_EQ(s->checks[0].frames, (std::vector<int>{0, 10}));
  EXPECT_DOUBLE_EQ(s->checks[1].tracks.joint_mm, 0.5);
  EXPECT_EQ(s->checks[2].image.pixel_threshold, 0);  // differential default: bit-identical
}

TEST(Scenario, ErrorsNameTheField) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"name": "a", "type": "image", "pixel_threshold": -1})", "checks[0].pixel_threshold: must be >= 0"},
      {R"({"name": "a", "type": "imag"})", "checks[0].type: unknown value \"imag\""},
      {R"({"name": "a", "type": "image", "regoin": "all"})", "checks[0]"},
      {R"({"name": "a", "type": "image"}, {"name": "a", "type": "tracks"})", "checks[1].name: duplicate check name"},
      {R"({"name": "a", "type": "image", "frames": [500]})", "checks[0].frames: frame 500 outside"},
      {R"({"name": "a", "type": "temporal", "frames": [3]})", "checks[0].frames: a temporal check needs"},
      {R"({"name": "a b", "type": "image"})", "checks[0].name: use letters"},
      {R"({"name": "a", "type": "budget"})", "checks[0].devices: required"},
  };
  for (const auto& [checks, needle] : cases) {
    auto s = parse(checks);
    ASSERT_FALSE(s.ok()) << checks;
    EXPECT_NE(s.message().find("dir/s.json: " + needle), std::string::npos) << s.message();
  }
  auto bad = parse(R"({"name": "a", "type": "image"})", R"("overrides": {"render.sh_ordr": 3}, )");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("overrides.render.sh_ordr: unknown render setting"), std::string::npos) << bad.message();
}

// "auto" η in overrides (and differential a/b blocks), as in scene files; the stored 0 as a number is refused.
TEST(Scenario, OverridesTakeAutoEta) {
  auto s = parse(R"({"name": "d", "type": "differential", "kind": "settings", "a": {"render.shadow_eta": "auto"}, "b": {"render.shadow_eta": 15}})",
                 R"("overrides": {"render.shadow_eta": "auto"}, )");
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->scene.render.shadow_eta, settings::kEtaFromLighting);
  EXPECT_EQ(s->checks[0].a.at("render.shadow_eta"), double(settings::kEtaFromLighting));
  EXPECT_EQ(s->checks[0].b.at("render.shadow_eta"), 15.0);
  const std::pair<std::string, std::string> cases[] = {
      {R"("overrides": {"render.shadow_eta": 0}, )", "overrides.render.shadow_eta: must be > 1 or \"auto\" (got 0)"},
      {R"("overrides": {"render.shadow_eta": "big"}, )",
       "overrides.render.shadow_eta: unknown value \"big\" (expected a number or \"auto\")"},
      {R"("overrides": {"render.indirect_eta": "auto"}, )", "overrides.render.indirect_eta: expected a number"},
      {R"("overrides": {"render.tonemap": "filmic"}, )", "overrides.render.tonemap: unknown value \"filmic\""},
  };
  for (const auto& [extra, needle] : cases) {
    auto bad = parse(R"({"name": "a", "type": "image"})", extra);
    ASSERT_FALSE(bad.ok()) << extra;
    EXPECT_NE(bad.message().find(needle), std::string::npos) << bad.message();
  }
}

Rgba8 flat(int w, int h, std::uint8_t value) {
  return Rgba8{w, h, std::vector<std::uint8_t>(std::size_t(w * h * 4), value)};
}

TEST(ImageCompare, ThresholdFractionAndShiftRadius) {
  Rgba8 golden = flat(8, 8, 100), actual = golden;
  actual.pixels[(3 * 8 + 3) * 4] = 110;  // one pixel 10 codes off
  std::vector<std::uint8_t> all(64, 1);
  auto strict = compare_images(actual, golden, all, {5, 0.0});
  ASSERT_TRUE(strict.ok());
  EXPECT_EQ(strict->failing, 1u);
  EXPECT_FALSE(strict->passed);
  EXPECT_TRUE(compare_images(actual, golden, all, {5, 1.0 / 64})->passed);
  EXPECT_TRUE(compare_images(actual, golden, all, {10, 0.0})->passed);
  // A one-pixel shift of an edge passes with shift_radius 1.
  Rgba8 edge = flat(8, 8, 0), moved = flat(8, 8, 0);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      for (int c = 0; c < 3; ++c) edge.pixels[std::size_t((y * 8 + x) * 4 + c)] = x >= 4 ? 200 : 0;
      for (int c = 0; c < 3; ++c) moved.pixels[std::size_t((y * 8 + x) * 4 + c)] = x >= 5 ? 200 : 0;
    }
  ImageTolerance shifted{2, 0.0};
  EXPECT_FALSE(compare_images(moved, edge, all, shifted)->passed);
  shifted.shift_radius = 1;
  EXPECT_TRUE(compare_images(moved, edge, all, shifted)->passed);
  // The region restricts what counts.
  std::vector<std::uint8_t> none(64, 0);
  EXPECT_TRUE(compare_images(actual, golden, none, {5, 0.0})->passed);
  EXPECT_FALSE(compare_images(flat(4, 4, 0), golden, all, {}).ok());
}

TEST(Tracks, ProxyCountChangeIsReportedAsAppearing) {
  Tracks golden{{5, {InstanceTrack{{}, {}, {}, {glm::dvec4(0, 1, 0, 0.1)}}}}};
  Tracks actual = golden;
  actual[0].instances[0].proxies.push_back(glm::dvec4(1, 1, 0, 0.1));
  Check check;
  CheckResult result;
  compare_tracks(actual, golden, check, 1.0, result);
  EXPECT_EQ(result.outcome, Outcome::fail);
  EXPECT_NE(result.message.find("1 proxies appeared at frame 5 (1 -> 2)"), std::string::npos) << result.message;
  // A 0.2 mm move fails at 0.1 mm and names the proxy and frame.
  actual = golden;
  actual[0].instances[0].proxies[0].x += 0.0002;
  CheckResult moved;
  compare_tracks(actual, golden, check, 1.0, moved);
  EXPECT_NE(moved.message.find("instance 0 proxy 0 center diverges from frame 5 by 0.200 mm"), std::string::npos) << moved.message;
  auto round = tracks_from_json(tracks_to_json(actual), "t");
  ASSERT_TRUE(round.ok());
  EXPECT_EQ((*round)[0].instances[0].proxies[0], actual[0].instances[0].proxies[0]);  // full precision
}

TEST(Runner, PatternsAndFamilies) {
  EXPECT_TRUE(matches_pattern("walk/*", "walk", "frame"));
  EXPECT_TRUE(matches_pattern("frame", "crowd", "frame"));
  EXPECT_FALSE(matches_pattern("walk/frame", "walk", "ground"));
  EXPECT_EQ(device_family("llvmpipe (LLVM 15.0.6, 256 bits)"), "llvmpipe");
  EXPECT_EQ(device_family("NVIDIA GeForce RTX 4090"), "nvidia");
  EXPECT_EQ(device_family("AMD Radeon RX 7900 (RADV NAVI31)"), "amd");
  EXPECT_EQ(device_family("Something"), "other");
}

TEST(Results, JsonRoundTripMergeAndReports) {
  RunResults a{"dev", "llvmpipe", {}}, b{"dev", "llvmpipe", {}};
  CheckResult failing;
  failing.scenario = "walk";
  failing.scenario_file = "tests/regress/walk.json";
  failing.check = "frame";
  failing.type = "image";
  failing.outcome = Outcome::fail;
  failing.message = "frame 30: 40 of 9216 pixels <beyond>";
  failing.series = {{0, 0.0, false}, {30, 0.004, true}};
  failing.first_failing_frame = 30;
  failing.threshold = 0.001;
  CheckResult passing = failing;
  passing.check = "tracks";
  passing.outcome = Outcome::pass;
  b.checks = {failing};
  a.checks = {passing};
  auto merged = merge_results({a, b});
  ASSERT_TRUE(merged.ok());
  ASSERT_EQ(merged->checks.size(), 2u);
  EXPECT_EQ(merged->checks[0].check, "frame");  // sorted
  EXPECT_EQ(merged->exit_code(), 1);
  const std::string json = to_json(*merged);
  auto back = results_from_json(json, "r");
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(to_json(*back), json);
  EXPECT_FALSE(merge_results({a, a}).ok());  // the same check in two shards
  const std::string html = report_html(*merged);
  EXPECT_NE(html.find("proxygi regress tests/regress/walk.json --bless walk/frame"), std::string::npos);
  EXPECT_NE(html.find("&lt;beyond&gt;"), std::string::npos);
  EXPECT_NE(html.find("<svg class=\"plot\""), std::string::npos);
  const std::string xml = junit_xml(*merged);
  EXPECT_NE(xml.find("failures=\"1\""), std::string::npos);
}

// Budget times live in timings.json only: results.json, junit.xml and report.html of two runs
// that measured different times are byte-identical, and timings.json carries the times back.
TEST(Results, TimingsStayOutOfTheDeterministicFiles) {
  CheckResult budget;
  budget.scenario = "walk";
  budget.scenario_file = "tests/regress/walk.json";
  budget.check = "budget";
  budget.type = "budget";
  budget.message = "median within the 400.0 ms per frame budget";
  budget.timings_ms = {12.5, 11.25, 13.0};
  RunResults first{"dev", "llvmpipe", {budget}};
  RunResults second = first;
  second.checks[0].timings_ms = {99.0, 98.0, 97.5};
  EXPECT_EQ(to_json(first), to_json(second));
  EXPECT_EQ(junit_xml(first), junit_xml(second));
  EXPECT_EQ(report_html(first), report_html(second));
  EXPECT_NE(timings_to_json(first), timings_to_json(second));
  EXPECT_DOUBLE_EQ(median_ms(first.checks[0].timings_ms), 12.5);

  auto back = results_from_json(to_json(first), "results.json");
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_TRUE(back->checks[0].timings_ms.empty());
  ASSERT_TRUE(attach_timings(timings_to_json(first), "timings.json", *back).ok());
  EXPECT_EQ(back->checks[0].timings_ms, first.checks[0].timings_ms);
  EXPECT_EQ(timings_to_json(*back), timings_to_json(first));
  RunResults other{"dev", "llvmpipe", {}};
  const Status unknown = attach_timings(timings_to_json(first), "timings.json", other);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.message().find("walk/budget: not in results.json"), std::string::npos) << unknown.message();
}

// --calibrate --write edits values in place: the layout stays, absent keys are appended to their
// check, strings holding braces or the key's name are not mistaken for structure.
TEST(JsonEdit, ReplacesAndAppendsKeepingTheLayout) {
  const std::string text =
      "{\n  \"description\": \"a {tricky} \\\"checks\\\" text\",\n  \"checks\": [\n"
      "    {\"name\": \"frame\", \"type\": \"image\", \"pixel_threshold\": 3, \"max_failing_fraction\": 0.001},\n"
      "    {\"name\": \"tracks\", \"type\": \"tracks\", \"frames\": [1, 2]}\n  ]\n}\n";
  auto edited = edit_check_fields(text, {{0, "pixel_threshold", "1"}, {1, "joint_mm", "0.01"}, {1, "proxy_mm", "0.02"}});
  ASSERT_TRUE(edited.ok()) << edited.message();
  const std::string expected =
      "{\n  \"description\": \"a {tricky} \\\"checks\\\" text\",\n  \"checks\": [\n"
      "    {\"name\": \"frame\", \"type\": \"image\", \"pixel_threshold\": 1, \"max_failing_fraction\": 0.001},\n"
      "    {\"name\": \"tracks\", \"type\": \"tracks\", \"frames\": [1, 2], \"joint_mm\": 0.01, \"proxy_mm\": 0.02}\n  ]\n}\n";
  EXPECT_EQ(*edited, expected);
  const std::string diff = line_diff(text, *edited, "s.json");
  EXPECT_NE(diff.find("@@ line 4 @@\n-    {\"name\": \"frame\", \"type\": \"image\", \"pixel_threshold\": 3"), std::string::npos) << diff;
  EXPECT_NE(diff.find("@@ line 5 @@"), std::string::npos) << diff;
  EXPECT_EQ(diff.find("@@ line 2 @@"), std::string::npos) << diff;
  EXPECT_EQ(line_diff(text, text, "s.json"), "");
  EXPECT_FALSE(edit_check_fields(text, {{2, "joint_mm", "1"}}).ok());  // no third check
  EXPECT_FALSE(edit_check_fields("[1, 2]", {{0, "a", "1"}}).ok());
}

// AOV goldens are linear EXR: compared in sRGB codes without rounding, so a change of a fraction
// of a code is seen (an 8-bit golden could not), and values above 1 do not clip.
TEST(ImageCompare, LinearImagesCompareWithoutRounding) {
  image::ImageF golden(2, 1, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  image::ImageF actual = golden;
  actual.pixels[1].x = image::srgb_to_linear((image::linear_to_srgb(0.5f) * 255.0f + 0.4f) / 255.0f);  // +0.4 codes
  const std::vector<std::uint8_t> all(2, 1);
  auto d = compare_images(codes_of(actual), codes_of(golden), all, {0, 0.0});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->failing, 1u);
  EXPECT_NEAR(d->largest, 0.4, 1e-3);
  EXPECT_TRUE(compare_images(codes_of(actual), codes_of(golden), all, {1, 0.0})->passed);
  image::ImageF bright = golden, brighter = golden;
  bright.pixels[0].x = 2.0f;
  brighter.pixels[0].x = 2.5f;
  EXPECT_GT(compare_images(codes_of(brighter), codes_of(bright), all, {0, 0.0})->largest, 20.0);
}

}  // namespace
}  // namespace proxygi::regress
