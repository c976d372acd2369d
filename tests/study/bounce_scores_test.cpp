// The bounce chart's metric: hand-computed cases, and the path tracer without character senders.
#include "study/bounce_scores.h"

#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/path_tracer.h"
#include "ref/scene_geometry.h"
#include "study/bounce_rows.h"

namespace proxygi::study {
namespace {

image::ImageF row_image(std::vector<glm::vec3> colors) {
  image::ImageF image(int(colors.size()), 1);
  for (std::size_t i = 0; i < colors.size(); ++i) image.pixels[i] = glm::vec4(colors[i], 1.0f);
  return image;
}

ref::ReceiverMask row_mask(std::vector<std::uint8_t> receiver) {
  return ref::ReceiverMask{int(receiver.size()), 1, std::move(receiver)};
}

TEST(BounceScores, BounceIsWithMinusWithoutPerChannel) {
  auto bounce = bounce_image(row_image({{1, 2, 3}}), row_image({{0.5f, 2, 1}}));
  ASSERT_TRUE(bounce.ok()) << bounce.message();
  EXPECT_EQ(bounce->pixels[0], glm::vec4(0.5f, 0.0f, 2.0f, 1.0f));
  EXPECT_FALSE(bounce_image(row_image({{1, 1, 1}}), row_image({{1, 1, 1}, {1, 1, 1}})).ok());
}

TEST(BounceScores, RelativeMseIsSquaredErrorOverSquaredReference) {
  // r = (1,1,1), (2,0,0); x = (1,1,1), (0,0,0): sum (x-r)^2 = 4, sum r^2 = 3 + 4 = 7.
  const image::ImageF reference = row_image({{1, 1, 1}, {2, 0, 0}, {9, 9, 9}});
  const image::ImageF test = row_image({{1, 1, 1}, {0, 0, 0}, {0, 0, 0}});
  auto error = bounce_error(test, reference, row_mask({1, 1, 0}));  // the third pixel is not scored
  ASSERT_TRUE(error.ok()) << error.message();
  EXPECT_DOUBLE_EQ(error->relative_mse, 4.0 / 7.0);
  EXPECT_NEAR(error->luminance_ratio, 1.0 / (1.0 + 2.0 * 0.2126), 1e-6);
  EXPECT_EQ(error->pixels, 2u);
}

TEST(BounceScores, NoBounceScoresOneAndAnEmptyMaskNothing) {
  const image::ImageF reference = row_image({{0.3f, 0.2f, 0.1f}, {0.05f, 0.5f, 0.0f}});
  const image::ImageF none = row_image({{0, 0, 0}, {0, 0, 0}});
  auto error = bounce_error(none, reference, row_mask({1, 1}));
  ASSERT_TRUE(error.ok());
  EXPECT_DOUBLE_EQ(error->relative_mse, 1.0);
  EXPECT_DOUBLE_EQ(error->luminance_ratio, 0.0);
  auto empty = bounce_error(none, reference, row_mask({0, 0}));
  ASSERT_TRUE(empty.ok());
  EXPECT_EQ(empty->relative_mse, -1.0);
  EXPECT_EQ(empty->pixels, 0u);
}

TEST(BounceScores, SignificantWhereTheBounceIsAFairShareOfThePixel) {
  // Full luminance 1 everywhere; bounces of luminance 0.01 (below 2 %), 0.05, -0.05, and 0.05 off
  // the receivers.
  const image::ImageF full = row_image({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
  const image::ImageF bounce = row_image({{0.01f, 0.01f, 0.01f}, {0.05f, 0.05f, 0.05f}, {-0.05f, -0.05f, -0.05f}, {0.05f, 0.05f, 0.05f}});
  const ref::ReceiverMask significant = significant_bounce(bounce, full, row_mask({1, 1, 1, 0}));
  EXPECT_EQ(significant.receiver, (std::vector<std::uint8_t>{0, 1, 0, 0}));
}

TEST(BounceScores, ReferenceBounceIsSignificantWhereAFairShareAndScoredPerRegion) {
  FrameReference full, without;
  full.radiance = row_image({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
  without.radiance = row_image({{0.5f, 0.5f, 0.5f}, {1, 1, 1}, {0.9f, 0.9f, 0.9f}, {0.99f, 0.99f, 0.99f}});
  full.receivers = row_mask({1, 1, 1, 1});
  full.character = row_mask({1, 0, 0, 0});
  full.ground = row_mask({0, 1, 1, 0});
  full.contact = row_mask({0, 1, 0, 0});
  full.other = row_mask({0, 0, 0, 1});
  full.samples = without.samples = 16;
  auto reference = make_bounce_reference(full, without);
  ASSERT_TRUE(reference.ok()) << reference.message();
  // Bounces 0.5, 0, 0.1, 0.01: significant from 2 % of the radiance on.
  EXPECT_EQ(reference->significant.receiver, (std::vector<std::uint8_t>{1, 0, 1, 0}));
  EXPECT_EQ(reference->ground.receiver, (std::vector<std::uint8_t>{0, 1, 1, 0}));
  auto scores = score_bounce(row_image({{0.5f, 0.5f, 0.5f}, {0, 0, 0}, {0, 0, 0}, {0.02f, 0.02f, 0.02f}}), *reference);
  ASSERT_TRUE(scores.ok());
  EXPECT_NEAR(scores->significant.relative_mse, 3 * 0.01 / (3 * 0.25 + 3 * 0.01), 1e-6);  // only pixel 2 wrong
  EXPECT_NEAR(scores->character.relative_mse, 0.0, 1e-12);
  EXPECT_NEAR(scores->ground.relative_mse, 1.0, 1e-6);    // pixel 1 has no bounce to miss, pixel 2 misses all
  EXPECT_EQ(scores->contact.relative_mse, -1.0);          // the contact pixel's reference bounce is 0
  EXPECT_NEAR(scores->other.relative_mse, 1.0, 1e-5);     // twice the bounce: (0.02 - 0.01)^2 / 0.01^2
  EXPECT_NEAR(scores->other.luminance_ratio, 2.0, 1e-5);
  without.samples = 8;
  EXPECT_FALSE(make_bounce_reference(full, without).ok());  // different samples: noise would not cancel
}

TEST(BounceScores, FrameMeanSkipsEmptyRegions) {
  BounceScores a, b;
  a.significant = {0.5, 1.0, 10};
  b.significant = {0.3, 0.8, 20};
  a.contact = {0.2, 0.9, 4};  // b's contact region was empty
  const BounceScores mean = mean_bounce_scores({a, b});
  EXPECT_DOUBLE_EQ(mean.significant.relative_mse, 0.4);
  EXPECT_DOUBLE_EQ(mean.significant.luminance_ratio, 0.9);
  EXPECT_DOUBLE_EQ(mean.contact.relative_mse, 0.2);
  EXPECT_EQ(mean.character.relative_mse, -1.0);
}

TEST(BounceRows, MeanOverScenesPerMethodSkipsEmptyRegionsAndPartialMethods) {
  const auto row = [](const char* scene, const char* indirect, double ms, double significant, double contact) {
    BounceRow r;
    r.row.scene = scene;
    r.row.method = "proxy";
    r.row.indirect = indirect;
    r.row.milliseconds = ms;
    r.bounce.significant = {significant, 2.0 * significant, 10};
    if (contact >= 0.0) r.bounce.contact = {contact, 1.0, 4};
    return r;
  };
  const std::vector<BounceRow> rows = {row("a", "averaged", 10.0, 0.5, 0.2), row("a", "vsgl1", 4.0, 0.3, -1.0),
                                       row("b", "averaged", 20.0, 1.5, -1.0), row("b", "vsgl1", 6.0, 0.9, 0.4),
                                       row("b", "point", 1.0, 9.0, -1.0)};
  const std::vector<BounceRow> means = mean_bounce_over_scenes(rows);
  ASSERT_EQ(means.size(), 2u);  // point is on one scene only
  EXPECT_EQ(means[0].row.scene, kAllScenes);
  EXPECT_EQ(means[0].row.indirect, "averaged");
  EXPECT_DOUBLE_EQ(means[0].row.milliseconds, 15.0);
  EXPECT_DOUBLE_EQ(means[0].bounce.significant.relative_mse, 1.0);
  EXPECT_DOUBLE_EQ(means[0].bounce.significant.luminance_ratio, 2.0);
  EXPECT_DOUBLE_EQ(means[0].bounce.contact.relative_mse, 0.2);  // b's contact was empty
  EXPECT_EQ(means[0].bounce.other.relative_mse, -1.0);
  EXPECT_DOUBLE_EQ(means[1].bounce.significant.relative_mse, 0.6);
  EXPECT_DOUBLE_EQ(means[1].bounce.contact.relative_mse, 0.4);
  std::vector<BounceRow> with_means = means;
  with_means.insert(with_means.end(), rows.begin(), rows.end());
  EXPECT_EQ(mean_bounce_over_scenes(with_means).size(), 2u) << "rows of kAllScenes are not averaged again";
  const std::string markdown = to_bounce_markdown(with_means);
  EXPECT_NE(markdown.find("### Mean over scenes"), std::string::npos);
  EXPECT_LT(markdown.find("### Mean over scenes"), markdown.find("### a ")) << "the mean first, as given";
}

// A ground and a vertical character quad at x = 0.5 facing it (albedo `quad_albedo`).
ref::EmbreeScene ground_and_quad(glm::vec3 quad_albedo) {
  std::vector<ref::TriangleMesh> meshes = ref::ground_meshes(scene::Ground{true, 6.0f, glm::vec3(0.8f)});
  ref::TriangleMesh quad;
  quad.name = "character:quad";
  quad.character = true;
  quad.positions = {{0.5f, 0.0f, -1.0f}, {0.5f, 0.0f, 1.0f}, {0.5f, 2.0f, 1.0f}, {0.5f, 2.0f, -1.0f}};
  quad.normals.assign(4, glm::vec3(-1.0f, 0.0f, 0.0f));
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.material.albedo = quad_albedo;
  meshes.push_back(quad);
  auto scene = ref::EmbreeScene::build(std::move(meshes));
  EXPECT_TRUE(scene.ok());
  return std::move(*scene);
}

glm::vec3 shade_sum(const ref::EmbreeScene& scene, const ref::SurfaceHit& hit, bool character_senders,
                    bool unshadowed_senders = false) {
  const ref::EnvironmentLight light = ref::EnvironmentLight::constant(glm::vec3(1.0f));
  ref::PathTracerSettings settings;
  settings.character_senders = character_senders;
  settings.unshadowed_character_senders = unshadowed_senders;
  const ref::PathTracer tracer(scene, light, light, settings);
  glm::vec3 sum(0.0f);
  for (std::uint32_t sample = 0; sample < 256; ++sample) {
    ref::SampleStream random(5, 0, sample);
    sum += tracer.shade(hit, random).radiance;
  }
  return sum;
}

TEST(BounceScores, WithoutCharacterSendersTheGroundSeesABlackCharacter) {
  const ref::EmbreeScene red = ground_and_quad(glm::vec3(0.9f, 0.1f, 0.1f));
  const ref::EmbreeScene black = ground_and_quad(glm::vec3(0.0f));
  ref::SurfaceHit ground;
  ground.position = glm::vec3(0.0f, 0.0f, 0.0f);
  ground.geometric_normal = ground.shading_normal = glm::vec3(0.0f, 1.0f, 0.0f);
  ground.albedo = glm::vec3(0.8f);
  // Same seeds: exactly the albedo-0 character, sample for sample; with senders, more red.
  EXPECT_EQ(shade_sum(red, ground, false), shade_sum(black, ground, true));
  const glm::vec3 bounce = shade_sum(red, ground, true) - shade_sum(red, ground, false);
  EXPECT_GT(bounce.r, 0.0f);
  EXPECT_GT(bounce.r, 5.0f * bounce.g);  // the quad's red, not the ground's gray
  // A character point keeps its own albedo (it is lit); this flat quad sees no character, so
  // without senders it shades as with them.
  ref::SurfaceHit on_quad;
  on_quad.position = glm::vec3(0.5f, 1.0f, 0.0f);
  on_quad.geometric_normal = on_quad.shading_normal = glm::vec3(-1.0f, 0.0f, 0.0f);
  on_quad.albedo = glm::vec3(0.9f, 0.1f, 0.1f);
  on_quad.character = true;
  EXPECT_GT(shade_sum(red, on_quad, false).r, 0.0f);
  EXPECT_EQ(shade_sum(red, on_quad, false), shade_sum(red, on_quad, true));
}

TEST(BounceScores, UnshadowedSendersSeeTheWholeSky) {
  // A roof over the quad (not a character) shades it; unshadowed, the quad reflects the full sky.
  std::vector<ref::TriangleMesh> meshes = ref::ground_meshes(scene::Ground{true, 6.0f, glm::vec3(0.8f)});
  ref::TriangleMesh quad;
  quad.character = true;
  quad.positions = {{0.5f, 0.0f, -1.0f}, {0.5f, 0.0f, 1.0f}, {0.5f, 2.0f, 1.0f}, {0.5f, 2.0f, -1.0f}};
  quad.normals.assign(4, glm::vec3(-1.0f, 0.0f, 0.0f));
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.material.albedo = glm::vec3(0.9f);
  ref::TriangleMesh roof;
  roof.positions = {{-0.3f, 2.1f, -3.0f}, {3.0f, 2.1f, -3.0f}, {3.0f, 2.1f, 3.0f}, {-0.3f, 2.1f, 3.0f}};
  roof.normals.assign(4, glm::vec3(0.0f, -1.0f, 0.0f));
  roof.indices = {0, 2, 1, 0, 3, 2};
  meshes.push_back(quad);
  meshes.push_back(roof);
  auto scene = ref::EmbreeScene::build(std::move(meshes));
  ASSERT_TRUE(scene.ok()) << scene.message();
  ref::SurfaceHit ground;
  ground.position = glm::vec3(-1.0f, 0.0f, 0.0f);
  ground.geometric_normal = ground.shading_normal = glm::vec3(0.0f, 1.0f, 0.0f);
  ground.albedo = glm::vec3(0.8f);
  const glm::vec3 without = shade_sum(*scene, ground, false);
  const glm::vec3 shadowed = shade_sum(*scene, ground, true) - without;
  const glm::vec3 unshadowed = shade_sum(*scene, ground, true, true) - without;
  EXPECT_GT(shadowed.r, 0.0f);
  EXPECT_GT(unshadowed.r, 1.2f * shadowed.r);
  // Black senders reflect nothing, shadowed or not.
  EXPECT_EQ(shade_sum(*scene, ground, false, true), without);
}

}  // namespace
}  // namespace proxygi::study
