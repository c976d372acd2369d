// compare --sequence's exact reprojection and temporal scores (study/sequence_temporal.h) on the
// default scene (fixed camera, a walking character) and the crowd (an orbiting camera).
#include "study/sequence_temporal.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_defaults.h"

namespace proxygi::study {
namespace {

TracedSequence traced(const scene::Scene& scene, int first, int last, int size) {
  auto world = world::World::load(scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = false});
  EXPECT_TRUE(world) << world.message();
  const ref::SceneGeometry geometry = ref::make_scene_geometry(**world);
  auto sequence = trace_sequence(**world, geometry, first, last, size, size);
  EXPECT_TRUE(sequence) << sequence.message();
  return *sequence;
}

TEST(SequenceTemporal, EveryPointReprojectsToItsOwnPixelInItsOwnFrame) {
  const TracedSequence s = traced(scene::default_scene(), 20, 20, 48);
  const Reprojection same = reproject_exact(s, 0, 0);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < same.source.size(); ++i) {
    if (s.frames[0].depth[i] <= 0.0f) continue;
    ++covered;
    EXPECT_EQ(same.source[i], int(i));
  }
  EXPECT_GT(covered, 1000u);
}

// Fixed camera, walking character: the ground stays where it is (or is hidden by the character
// in the next frame); the character's points move with its skin and land on the character.
TEST(SequenceTemporal, FixedCameraKeepsTheGroundAndFollowsTheCharactersSkin) {
  const TracedSequence s = traced(scene::default_scene(), 20, 21, 64);
  const Reprojection next = reproject_exact(s, 0, 1);
  std::size_t ground = 0, ground_kept = 0, character = 0, character_moved = 0;
  for (std::size_t i = 0; i < next.source.size(); ++i) {
    if (s.frames[0].depth[i] <= 0.0f) continue;
    const int j = next.source[i];
    if (!s.frames[0].character[i]) {
      ++ground;
      if (j >= 0) {
        EXPECT_EQ(j, int(i));
        ++ground_kept;
      }
      continue;
    }
    ++character;
    if (j < 0) continue;
    EXPECT_TRUE(s.frames[1].character[std::size_t(j)]) << i;
    character_moved += j != int(i);
  }
  EXPECT_GT(ground_kept, ground * 95 / 100);
  ASSERT_GT(character, 20u);
  EXPECT_GT(character_moved, 0u);
}

// Orbiting camera: ground points change pixel, and the point seen at the target pixel is the
// same world point to within about a pixel's footprint.
TEST(SequenceTemporal, OrbitingCameraMapsGroundPointsOntoTheSamePoint) {
  scene::Scene crowd = scene::crowd_scene();
  const TracedSequence s = traced(crowd, 10, 14, 48);
  const Reprojection across = reproject_exact(s, 0, 4);
  std::size_t mapped = 0, moved = 0;
  for (std::size_t i = 0; i < across.source.size(); ++i) {
    const int j = across.source[i];
    if (j < 0 || s.frames[0].character[i]) continue;
    ++mapped;
    moved += j != int(i);
    const glm::vec3 a = s.frames[0].hits[i].position, b = s.frames[4].hits[std::size_t(j)].position;
    const float footprint = 2.0f * s.frames[4].depth[std::size_t(j)] * std::tan(glm::radians(0.5f * s.frames[4].camera.fov_y_degrees)) / 48.0f;
    EXPECT_LT(glm::length(a - b), 1.5f * footprint) << i;
  }
  EXPECT_GT(mapped, 500u);
  EXPECT_GT(moved, mapped / 2);
}

// The scores on hand-made sequences: a test equal to the reference scores 0; a test brighter by δ
// in the middle frame of three gives E_Δ = δ, a pop of 2δ, and flicker of the error δ√2/3.
TEST(SequenceTemporal, ScoresOfHandMadeSequences) {
  const TracedSequence s = traced(scene::default_scene(), 20, 22, 32);
  std::vector<ref::Plane> reference;
  for (int t = 0; t < 3; ++t) {
    reference.emplace_back(32, 32);
    for (std::size_t i = 0; i < reference.back().values.size(); ++i) reference.back().values[i] = 0.1f + 0.01f * float(i % 7) + 0.02f * float(t);
  }
  auto same = score_sequence(reference, reference, s);
  ASSERT_TRUE(same) << same.message();
  EXPECT_EQ(same->all.gradient.mean, 0.0);
  EXPECT_EQ(same->all.pop.max, 0.0);
  EXPECT_EQ(same->all.flicker_error.max, 0.0);
  EXPECT_GT(same->all.flicker_test.mean, 0.0);  // the reference itself changes over frames
  EXPECT_EQ(same->all.flicker_test.mean, same->all.flicker_reference.mean);

  const float delta = 0.05f;
  std::vector<ref::Plane> test = reference;
  for (float& v : test[1].values) v += delta;
  auto bumped = score_sequence(test, reference, s);
  ASSERT_TRUE(bumped) << bumped.message();
  EXPECT_NEAR(bumped->all.gradient.mean, delta, 1e-5);
  EXPECT_NEAR(bumped->all.pop.mean, 2.0 * delta, 1e-5);
  EXPECT_NEAR(bumped->static_world.flicker_error.mean, delta * std::sqrt(2.0) / 3.0, 1e-5);
  EXPECT_GT(bumped->character.gradient.pixels, 0u);
  EXPECT_GT(bumped->static_world.gradient.pixels, bumped->character.gradient.pixels);

  std::vector<ref::Plane> short_test(test.begin(), test.begin() + 2);
  EXPECT_FALSE(score_sequence(short_test, reference, s));  // 2 test frames for 3
}

}  // namespace
}  // namespace proxygi::study
