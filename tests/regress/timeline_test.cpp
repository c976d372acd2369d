// Scene schema v2 clip timelines: parsing (version 1 still loads, errors name the field) and
// evaluation through world::World (segment boundaries, cross-fade = anim::BlendJob).
#include <gtest/gtest.h>

#include <string>

#include "anim/blending.h"
#include "anim/sampling.h"
#include "scene/scene_parse.h"
#include "scene/scene_write.h"
#include "world/world.h"

namespace proxygi {
namespace {

std::string scene_with(const std::string& character, int version = 2) {
  return R"({"schema_version": )" + std::to_string(version) + R"(, "characters": [)" + character + "]}";
}

const char* kTwoSegments = R"({"model": "builtin:mannequin", "timeline": [
  {"clip": "walk", "start": 0, "duration": 2, "crossfade": 0.5},
  {"clip": "run", "start": 2, "repeat": 2, "mode": "ping_pong", "speed": 1.5},
  {"clip": "wave", "start": 6, "duration": 1, "mode": "once"}]})";

TEST(TimelineParse, ReadsSegmentsAndWritesVersion2) {
  auto scene = scene::parse_scene(scene_with(kTwoSegments), "t.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  const auto& timeline = scene->characters[0].timeline;
  ASSERT_EQ(timeline.size(), 3u);
  EXPECT_EQ(std::get<std::string>(timeline[1].clip), "run");
  EXPECT_EQ(timeline[1].repeat, 2);
  EXPECT_EQ(timeline[1].mode, scene::ClipSegment::Mode::ping_pong);
  EXPECT_FLOAT_EQ(timeline[0].crossfade_s, 0.5f);
  const std::string written = *scene::to_json(*scene);
  EXPECT_NE(written.find("\"schema_version\": 2"), std::string::npos) << written;
  auto again = scene::parse_scene(written, "t.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->characters, scene->characters);
}

TEST(TimelineParse, Version1StillLoadsAndWritesAsVersion1) {
  auto scene = scene::parse_scene(scene_with(R"({"model": "builtin:mannequin", "clip": "walk"})", 1), "t.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_TRUE(scene->characters[0].timeline.empty());
  EXPECT_NE(scene::to_json(*scene)->find("\"schema_version\": 1"), std::string::npos);
}

void expect_error(const std::string& text, const std::string& needle) {
  auto scene = scene::parse_scene(text, "t.json");
  ASSERT_FALSE(scene.ok()) << "accepted: " << text;
  EXPECT_NE(scene.message().find(needle), std::string::npos) << scene.message();
}

TEST(TimelineParse, RefusesBadSegmentsNamingTheField) {
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": 0, "duration": 1}]})", 1),
               "characters[0].timeline: needs schema_version 2");
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": -1, "duration": 1}]})"),
               "characters[0].timeline[0].start: must be >= 0");
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": 0, "duration": 2},
                                                              {"clip": 1, "start": 1.5, "duration": 1}]})"),
               "characters[0].timeline[1].start: overlaps characters[0].timeline[0]");
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": 0, "duration": 0}]})"),
               "characters[0].timeline[0].duration: must be > 0");
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": 0, "duration": 1, "repeat": 2}]})"),
               "characters[0].timeline[0].repeat: give duration or repeat");
  expect_error(scene_with(R"({"model": "m.glb", "clip": 0, "timeline": [{"clip": 0, "start": 0, "duration": 1}]})"),
               "characters[0].clip: not allowed with a timeline");
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": 0, "duration": 1, "crossfade": 1}]})"),
               "characters[0].timeline[0].crossfade: the last segment");
  expect_error(scene_with(R"({"model": "m.glb", "timeline": [{"clip": 0, "start": 0, "duraton": 1}]})"),
               "characters[0].timeline[0]");
}

class TimelineWorld : public testing::Test {
 protected:
  void load(const std::string& character) {
    auto scene = scene::parse_scene(scene_with(character), "t.json");
    ASSERT_TRUE(scene.ok()) << scene.message();
    auto loaded = world::World::load(*scene, {PROXYGI_SOURCE_DIR "/assets", true, false});
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    world = std::move(*loaded);
  }
  const anim::Character& character() const { return world->instances()[0].model->character; }
  int clip(const char* name) const { return *anim::find_clip(character(), name); }
  std::vector<anim::Transform> locals_at(double t) {
    world::WorldState state;
    EXPECT_TRUE(world->evaluate(t, std::nullopt, state).ok());
    return state.instances[0].pose.locals;
  }
  std::vector<anim::Transform> sampled(int clip_index, float time) const {
    std::vector<anim::Transform> locals(character().nodes.size());
    std::vector<float> morph(std::size_t(anim::morph_weight_count(character())));
    anim::SampleClipJob job;
    job.character = &character();
    job.clip = &character().clips[std::size_t(clip_index)];
    job.time = time;
    job.locals = locals;
    job.morph_weights = morph;
    EXPECT_TRUE(job.run().ok());
    return locals;
  }
  static void expect_same(const std::vector<anim::Transform>& a, const std::vector<anim::Transform>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].translation, b[i].translation) << "node " << i;
      EXPECT_EQ(a[i].rotation, b[i].rotation) << "node " << i;
    }
  }
  std::unique_ptr<world::World> world;
};

TEST_F(TimelineWorld, SegmentBoundaries) {
  load(R"({"model": "builtin:mannequin", "timeline": [
    {"clip": "walk", "start": 0.5, "duration": 1},
    {"clip": "run", "start": 2, "duration": 1, "mode": "once", "speed": 0.5}]})");
  const float walk_d = character().clips[std::size_t(clip("walk"))].duration;
  const float run_d = character().clips[std::size_t(clip("run"))].duration;
  expect_same(locals_at(0.0), sampled(clip("walk"), 0.0f));                        // before: first pose
  expect_same(locals_at(1.0), sampled(clip("walk"), std::fmod(0.5f, walk_d)));    // inside
  expect_same(locals_at(1.75), locals_at(1.5));                                     // gap: held end
  expect_same(locals_at(2.0), sampled(clip("run"), 0.0f));                          // next start
  expect_same(locals_at(2.5), sampled(clip("run"), std::min(0.25f, run_d)));
  expect_same(locals_at(10.0), locals_at(3.0));                                     // after: held end
}

TEST_F(TimelineWorld, CrossFadeHalfwayEqualsTheBlendJob) {
  load(R"({"model": "builtin:mannequin", "timeline": [
    {"clip": "walk", "start": 0, "duration": 1, "crossfade": 0.4},
    {"clip": "run", "start": 1, "duration": 2}]})");
  const float walk_d = character().clips[std::size_t(clip("walk"))].duration;
  const world::TimelineSample half = world::sample_timeline(world->instances()[0].timeline, 1.2);
  EXPECT_EQ(half.clip_a, clip("walk"));
  EXPECT_EQ(half.clip_b, clip("run"));
  EXPECT_NEAR(half.weight, 0.5f, 1e-6f);
  EXPECT_NEAR(half.time_a, std::fmod(1.2f, walk_d), 1e-6f);  // the outgoing walk plays on
  EXPECT_NEAR(half.time_b, 0.2f, 1e-6f);
  const auto a = sampled(clip("walk"), half.time_a);
  const auto b = sampled(clip("run"), half.time_b);
  std::vector<anim::Transform> blended(a.size());
  anim::BlendJob job;
  job.a = a;
  job.b = b;
  job.weight = half.weight;
  job.output = blended;
  ASSERT_TRUE(job.run().ok());
  expect_same(locals_at(1.2), blended);
  expect_same(locals_at(1.4), sampled(clip("run"), 0.4f));  // fade over
}

TEST_F(TimelineWorld, RepeatCountsGiveLengthsAndOverlapsAreRefused) {
  auto scene = scene::parse_scene(scene_with(R"({"model": "builtin:mannequin", "timeline": [
    {"clip": "walk", "start": 0, "repeat": 3}, {"clip": "run", "start": 0.5, "duration": 1}]})"), "t.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  auto loaded = world::World::load(*scene, {PROXYGI_SOURCE_DIR "/assets", true, false});
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.message().find("characters[0].timeline[1].start: overlaps characters[0].timeline[0]"), std::string::npos)
      << loaded.message();
}

}  // namespace
}  // namespace proxygi
