// Clip sampling: every interpolation mode at key times, between keys, before the first and after
// the last key, on clips written by the project's writer and read back by the importer.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/sampling.h"
#include "runtime_rigs.h"

namespace proxygi::anim {
namespace {

using testing::chain;
using testing::make_channel;
using testing::round_trip;

// Samples translation.x of node 1 of a two-node chain animated by `channel`.
struct OneChannel {
  Character character;
  OneChannel(Channel channel, float duration) {
    character = chain(2);
    Clip clip;
    clip.name = "clip";
    clip.duration = duration;
    clip.channels.push_back(std::move(channel));
    character.clips.push_back(std::move(clip));
    character = round_trip(character);
  }
  Transform at(float time, WrapMode wrap = WrapMode::clamp) const {
    std::vector<Transform> locals(character.nodes.size());
    SampleClipJob job;
    job.character = &character;
    job.clip = &character.clips.at(0);
    job.time = time;
    job.wrap = wrap;
    job.locals = locals;
    EXPECT_TRUE(job.run().ok());
    return locals.at(1);
  }
};

glm::quat about_z(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1)); }

TEST(Sampling, StepHoldsEachKeyUntilTheNext) {
  const OneChannel rig(make_channel(1, ChannelPath::translation, Interpolation::step, {1.0f, 2.0f, 3.0f},
                                    {10, 0, 0, 20, 0, 0, 30, 0, 0}),
                       3.0f);
  EXPECT_EQ(rig.at(0.0f).translation.x, 10.0f);  // playback starts at 0, clamped to the first key
  EXPECT_EQ(rig.at(0.5f).translation.x, 10.0f);
  EXPECT_EQ(rig.at(1.0f).translation.x, 10.0f);
  EXPECT_EQ(rig.at(1.999f).translation.x, 10.0f);
  EXPECT_EQ(rig.at(2.0f).translation.x, 20.0f);  // exact key time: that key, not the previous one
  EXPECT_EQ(rig.at(2.5f).translation.x, 20.0f);
  EXPECT_EQ(rig.at(3.0f).translation.x, 30.0f);
  EXPECT_EQ(rig.at(7.0f).translation.x, 30.0f);  // after the last key: clamped
}

TEST(Sampling, LinearTranslationLerpsAndClamps) {
  const OneChannel rig(make_channel(1, ChannelPath::translation, Interpolation::linear, {1.0f, 2.0f, 4.0f},
                                    {10, -1, 0, 20, -2, 0, 40, -4, 8}),
                       4.0f);
  EXPECT_EQ(rig.at(0.25f).translation, glm::vec3(10, -1, 0));
  EXPECT_EQ(rig.at(1.0f).translation, glm::vec3(10, -1, 0));
  EXPECT_EQ(rig.at(1.5f).translation, glm::vec3(15, -1.5f, 0));
  EXPECT_EQ(rig.at(1.25f).translation, glm::vec3(12.5f, -1.25f, 0));
  EXPECT_EQ(rig.at(2.0f).translation, glm::vec3(20, -2, 0));
  EXPECT_EQ(rig.at(3.0f).translation, glm::vec3(30, -3, 4));
  EXPECT_EQ(rig.at(5.0f).translation, glm::vec3(40, -4, 8));
}

TEST(Sampling, LinearRotationSlerpsTheShortWay) {
  const glm::quat q0 = about_z(0.0f);
  const glm::quat q90 = -about_z(90.0f);  // same rotation, opposite sign: must not go the long way
  const glm::quat q270 = about_z(270.0f);  // equals −90°: the short way passes through −45°
  const OneChannel rig(make_channel(1, ChannelPath::rotation, Interpolation::linear, {0.0f, 1.0f, 2.0f},
                                    {q0.x, q0.y, q0.z, q0.w, q90.x, q90.y, q90.z, q90.w, q270.x, q270.y, q270.z, q270.w}),
                       2.0f);
  const glm::vec3 x(1, 0, 0);
  const glm::vec3 at_half = rig.at(0.5f).rotation * x;
  EXPECT_NEAR(at_half.x, std::cos(glm::radians(45.0f)), 1e-6f);
  EXPECT_NEAR(at_half.y, std::sin(glm::radians(45.0f)), 1e-6f);
  const glm::vec3 at_quarter = rig.at(0.25f).rotation * x;  // slerp is uniform in angle: 22.5°
  EXPECT_NEAR(at_quarter.x, std::cos(glm::radians(22.5f)), 1e-6f);
  EXPECT_NEAR(at_quarter.y, std::sin(glm::radians(22.5f)), 1e-6f);
  // An exact key hit returns the stored key unchanged (as imported: the importer renormalizes).
  const std::vector<float>& stored = rig.character.clips[0].channels[0].values;
  EXPECT_EQ(rig.at(1.0f).rotation, glm::quat(stored[7], stored[4], stored[5], stored[6]));
  EXPECT_NEAR(stored[7], q90.w, 1e-7f);
  EXPECT_NEAR(glm::length(rig.at(1.3f).rotation), 1.0f, 1e-6f);
}

TEST(Sampling, LinearRotationAcrossTheSignFlipGoesThroughMinus45) {
  const glm::quat q0 = about_z(0.0f);
  const glm::quat q270 = about_z(270.0f);  // w < 0: dot with q0 is negative
  const OneChannel rig(make_channel(1, ChannelPath::rotation, Interpolation::linear, {0.0f, 1.0f},
                                    {q0.x, q0.y, q0.z, q0.w, q270.x, q270.y, q270.z, q270.w}),
                       1.0f);
  const glm::vec3 v = rig.at(0.5f).rotation * glm::vec3(1, 0, 0);
  EXPECT_NEAR(v.x, std::cos(glm::radians(-45.0f)), 1e-6f);
  EXPECT_NEAR(v.y, std::sin(glm::radians(-45.0f)), 1e-6f);
}

TEST(Sampling, CubicSplineScalesTangentsByTheKeyInterval) {
  // Keys at t = 1 and 3 (t_d = 2): values 0 → 0, out-tangent of key 0 = 1, in-tangent of key 1 = 0.
  // At u = 0.5: t_d · (u³ − 2u² + u) · b0 = 2 · 0.125 = 0.25 (0.125 if t_d were forgotten).
  const OneChannel rig(make_channel(1, ChannelPath::translation, Interpolation::cubic_spline, {1.0f, 3.0f},
                                    {/*a0*/ 9, 9, 9, /*v0*/ 0, 5, 0, /*b0*/ 1, 0, 0,
                                     /*a1*/ 0, 0, 4, /*v1*/ 0, 5, 8, /*b1*/ 9, 9, 9}),
                       3.0f);
  EXPECT_EQ(rig.at(2.0f).translation.x, 0.25f);
  EXPECT_EQ(rig.at(2.0f).translation.y, 5.0f);
  // z: h01(0.5) · 8 + t_d · (u³ − u²) · a1 = 0.5 · 8 + 2 · (−0.125) · 4 = 3.
  EXPECT_EQ(rig.at(2.0f).translation.z, 3.0f);
  EXPECT_EQ(rig.at(1.0f).translation, glm::vec3(0, 5, 0));  // key hit returns v, not a tangent
  EXPECT_EQ(rig.at(3.0f).translation, glm::vec3(0, 5, 8));
  EXPECT_EQ(rig.at(0.0f).translation, glm::vec3(0, 5, 0));  // before the first key
  EXPECT_EQ(rig.at(9.0f).translation, glm::vec3(0, 5, 8));  // after the last key
}

TEST(Sampling, CubicSplineRotationIsNormalized) {
  const glm::quat q0 = about_z(0.0f);
  const glm::quat q1 = about_z(90.0f);
  // Zero tangents: the spline between two unit quaternions dips below unit length mid-way.
  const OneChannel rig(make_channel(1, ChannelPath::rotation, Interpolation::cubic_spline, {0.0f, 1.0f},
                                    {0, 0, 0, 0, q0.x, q0.y, q0.z, q0.w, 0, 0, 0, 0,
                                     0, 0, 0, 0, q1.x, q1.y, q1.z, q1.w, 0, 0, 0, 0}),
                       1.0f);
  const glm::quat q = rig.at(0.5f).rotation;
  EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
  // Symmetric Hermite weights (0.5, 0.5) then normalization: exactly the 45° rotation.
  const glm::vec3 v = q * glm::vec3(1, 0, 0);
  EXPECT_NEAR(v.x, std::cos(glm::radians(45.0f)), 1e-6f);
  EXPECT_NEAR(v.y, std::sin(glm::radians(45.0f)), 1e-6f);
}

TEST(Sampling, UnanimatedPropertiesKeepRestValuesAndOneKeyChannelsHold) {
  Character character = chain(3);
  character.nodes[1].rest.scale = glm::vec3(2, 3, 4);
  character.nodes[1].rest.rotation = about_z(30.0f);
  Clip clip;
  clip.name = "clip";
  clip.duration = 2.0f;
  clip.channels.push_back(make_channel(1, ChannelPath::translation, Interpolation::linear, {0.0f, 2.0f}, {0, 0, 0, 2, 0, 0}));
  clip.channels.push_back(make_channel(2, ChannelPath::scale, Interpolation::linear, {0.5f}, {7, 7, 7}));
  character.clips.push_back(clip);
  character = round_trip(character);

  std::vector<Transform> locals(character.nodes.size());
  SampleClipJob job{&character, &character.clips[0], 1.0f, WrapMode::clamp, locals, {}};
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(locals[1].translation, glm::vec3(1, 0, 0));
  EXPECT_EQ(locals[1].scale, glm::vec3(2, 3, 4));
  EXPECT_EQ(locals[1].rotation, character.nodes[1].rest.rotation);
  EXPECT_EQ(locals[2].scale, glm::vec3(7, 7, 7));            // one key: held at every time
  EXPECT_EQ(locals[2].translation, glm::vec3(0, 1, 0));      // rest translation
  EXPECT_EQ(locals[0].translation, glm::vec3(0, 0, 0));
}

TEST(Sampling, LoopWrapsIntoTheClipAndClampHoldsTheEnds) {
  EXPECT_EQ(wrap_time(3.5f, 3.0f, WrapMode::loop), 0.5f);
  EXPECT_EQ(wrap_time(3.0f, 3.0f, WrapMode::loop), 0.0f);
  EXPECT_EQ(wrap_time(-0.5f, 3.0f, WrapMode::loop), 2.5f);
  EXPECT_EQ(wrap_time(7.25f, 2.0f, WrapMode::loop), 1.25f);
  EXPECT_EQ(wrap_time(3.5f, 3.0f, WrapMode::clamp), 3.0f);
  EXPECT_EQ(wrap_time(-1.0f, 3.0f, WrapMode::clamp), 0.0f);
  EXPECT_EQ(wrap_time(1.0f, 0.0f, WrapMode::loop), 0.0f);  // empty clip
  const OneChannel rig(make_channel(1, ChannelPath::translation, Interpolation::linear, {0.0f, 2.0f},
                                    {0, 0, 0, 2, 0, 0}),
                       2.0f);
  EXPECT_EQ(rig.at(2.5f, WrapMode::loop).translation.x, 0.5f);
  EXPECT_EQ(rig.at(2.5f, WrapMode::clamp).translation.x, 2.0f);
}

TEST(Sampling, MorphWeightsStartFromDefaultsAndFollowTheirChannel) {
  Character character = chain(1);
  testing::add_triangle_node(character, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  Primitive& primitive = character.meshes[0].primitives[0];
  primitive.morph_targets.resize(2);
  primitive.morph_targets[0].position_deltas = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  primitive.morph_targets[1].position_deltas = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  character.meshes[0].default_morph_weights = {0.25f, 0.5f};
  Clip clip;
  clip.name = "morph";
  clip.duration = 1.0f;
  Channel weights;
  weights.node = 1;
  weights.path = ChannelPath::weights;
  weights.interpolation = Interpolation::linear;
  weights.components = 2;
  weights.times = {0.0f, 1.0f};
  weights.values = {0.0f, 1.0f, 1.0f, 0.0f};
  clip.channels.push_back(weights);
  character.clips.push_back(clip);
  character = round_trip(character);

  ASSERT_EQ(morph_weight_count(character), 2);
  ASSERT_EQ(morph_weight_offset(character, 1), 0);
  std::vector<float> defaults(2);
  default_morph_weights(character, defaults);
  EXPECT_EQ(defaults, (std::vector<float>{0.25f, 0.5f}));

  std::vector<Transform> locals(character.nodes.size());
  std::vector<float> sampled(2);
  SampleClipJob job{&character, &character.clips[0], 0.25f, WrapMode::clamp, locals, sampled};
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(sampled, (std::vector<float>{0.25f, 0.75f}));
}

TEST(SamplingValidity, RejectsEveryBrokenInput) {
  Character character = chain(2);
  Clip clip;
  clip.name = "clip";
  clip.duration = 1.0f;
  clip.channels.push_back(make_channel(1, ChannelPath::translation, Interpolation::linear, {0.0f, 1.0f}, {0, 0, 0, 1, 1, 1}));
  std::vector<Transform> locals(2);
  SampleClipJob job{&character, &clip, 0.5f, WrapMode::clamp, locals, {}};
  EXPECT_TRUE(job.validate().ok());

  SampleClipJob no_character = job;
  no_character.character = nullptr;
  EXPECT_FALSE(no_character.validate().ok());
  SampleClipJob no_clip = job;
  no_clip.clip = nullptr;
  EXPECT_FALSE(no_clip.validate().ok());
  std::vector<Transform> short_locals(1);
  SampleClipJob small = job;
  small.locals = short_locals;
  EXPECT_FALSE(small.validate().ok());
  std::vector<float> weights(3);
  SampleClipJob extra_weights = job;
  extra_weights.morph_weights = weights;  // character has no morph targets
  EXPECT_FALSE(extra_weights.validate().ok());

  Clip bad = clip;
  bad.channels[0].node = 2;
  EXPECT_FALSE((SampleClipJob{&character, &bad, 0.0f, WrapMode::clamp, locals, {}}.validate().ok()));
  bad = clip;
  bad.channels[0].components = 4;
  EXPECT_FALSE((SampleClipJob{&character, &bad, 0.0f, WrapMode::clamp, locals, {}}.validate().ok()));
  bad = clip;
  bad.channels[0].values.pop_back();
  EXPECT_FALSE((SampleClipJob{&character, &bad, 0.0f, WrapMode::clamp, locals, {}}.validate().ok()));
  bad = clip;
  bad.channels[0].interpolation = Interpolation::cubic_spline;  // needs 3× values
  EXPECT_FALSE((SampleClipJob{&character, &bad, 0.0f, WrapMode::clamp, locals, {}}.validate().ok()));
  bad = clip;
  bad.channels[0].times.clear();
  bad.channels[0].values.clear();
  EXPECT_FALSE((SampleClipJob{&character, &bad, 0.0f, WrapMode::clamp, locals, {}}.run().ok()));
}

}  // namespace
}  // namespace proxygi::anim
