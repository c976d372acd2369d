// Rig files (round trip, validation with line numbers, content hash) and tracking.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "proxies/binding_eval.h"
#include "proxies/bind_surface.h"
#include "proxies/fit.h"
#include "proxies/rig_file.h"
#include "proxies/tracking.h"
#include "proxies/test_shapes.h"

namespace proxygi::proxies {
namespace {

FitResult fit_arm(const anim::Character& ch) {
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  EXPECT_TRUE(job.run().ok());
  return fit;
}

// 1-based line of the first line of `text` containing `needle`.
int line_containing(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return -1;
}

TEST(RigFile, ContentHashIsFnv1a64) {
  EXPECT_EQ(content_hash({}), "fnv1a64:cbf29ce484222325");
  const std::uint8_t a[] = {'a'};
  EXPECT_EQ(content_hash(a), "fnv1a64:af63dc4c8601ec8c");
  EXPECT_EQ(default_rig_path("dir/hero.glb"), std::filesystem::path("dir/hero.proxies.json"));
}

TEST(RigFile, RoundTripsEverySphere) {
  const anim::Character ch = testing::arm_character();
  FitResult fit = fit_arm(ch);
  fit.rig.model = "arm.glb";
  fit.rig.model_hash = "fnv1a64:0123456789abcdef";
  const std::string text = rig_to_json(fit.rig, ch);
  Result<ProxyRig> back = parse_rig(text, "arm.proxies.json", ch);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(back->model_hash, fit.rig.model_hash);
  EXPECT_EQ(back->binding, fit.rig.binding);
  ASSERT_EQ(back->spheres.size(), fit.rig.spheres.size());
  for (std::size_t i = 0; i < fit.rig.spheres.size(); ++i) {
    const ProxySphere& a = fit.rig.spheres[i];
    const ProxySphere& b = back->spheres[i];
    EXPECT_EQ(a.bone, b.bone);
    EXPECT_EQ(a.node, b.node);
    EXPECT_NEAR(glm::length(a.center - b.center), 0.0f, 1e-6f);
    EXPECT_NEAR(a.radius, b.radius, 1e-6f * a.radius);
    EXPECT_NEAR(glm::length(a.albedo - b.albedo), 0.0f, 1e-6f);
    for (int k = 0; k < kSphereWeights; ++k) {
      EXPECT_EQ(a.weight_nodes[std::size_t(k)], b.weight_nodes[std::size_t(k)]);
      EXPECT_NEAR(a.weights[std::size_t(k)], b.weights[std::size_t(k)], 1e-6f);
    }
    // One sphere per line: the loader's line is the line holding that sphere's entry.
    EXPECT_EQ(b.source_line, line_containing(text, "\"spheres\": [") + 1 + int(i));
  }
}

TEST(RigFile, NamesTheLineOfABadSphere) {
  const anim::Character ch = testing::arm_character();
  FitResult fit = fit_arm(ch);
  ASSERT_GE(fit.rig.spheres.size(), 2u);
  std::string text = rig_to_json(fit.rig, ch);
  // Hand edit: sphere 1 gets a negative radius.
  char old_radius[64];
  std::snprintf(old_radius, sizeof old_radius, "\"radius\": %.7g", double(fit.rig.spheres[1].radius));
  const std::size_t first_sphere = text.find("\"bone\"");
  const std::size_t second_sphere = text.find("\"bone\"", first_sphere + 1);
  const std::size_t at = text.find(old_radius, second_sphere);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::strlen(old_radius), "\"radius\": -0.1");
  const int expected_line = line_containing(text, "\"radius\": -0.1");
  Result<ProxyRig> bad = parse_rig(text, "arm.proxies.json", ch);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(), "arm.proxies.json:" + std::to_string(expected_line) + ": sphere 1: radius must be > 0");
}

TEST(RigFile, RejectsUnknownBonesBadNumbersAndNewerVersions) {
  const anim::Character ch = testing::arm_character();
  const std::string head = "{\"schema\": \"proxygi.proxies\", \"version\": 1, \"spheres\": [\n";
  auto parse = [&](const std::string& sphere) { return parse_rig(head + sphere + "\n]}", "f.json", ch); };
  Result<ProxyRig> unknown = parse("{\"bone\": \"elbow\", \"center\": [0,0,0], \"radius\": 1}");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.message().find("f.json:2: sphere 0: bone \"elbow\" is not a node"), std::string::npos) << unknown.message();
  Result<ProxyRig> not_number = parse("{\"bone\": \"upper\", \"center\": [0,\"x\",0], \"radius\": 1}");
  ASSERT_FALSE(not_number.ok());
  EXPECT_NE(not_number.message().find("center"), std::string::npos);
  Result<ProxyRig> wrong_node = parse("{\"bone\": \"upper\", \"node\": 2, \"center\": [0,0,0], \"radius\": 1}");
  ASSERT_FALSE(wrong_node.ok());
  EXPECT_NE(wrong_node.message().find("node 2 is not named \"upper\""), std::string::npos);
  Result<ProxyRig> bad_weight = parse("{\"bone\": \"upper\", \"center\": [0,0,0], \"radius\": 1, \"weights\": {\"upper\": -1}}");
  ASSERT_FALSE(bad_weight.ok());
  Result<ProxyRig> added = parse("{\"bone\": \"lower\", \"center\": [0.1,0,0], \"radius\": 0.2}");
  ASSERT_TRUE(added.ok()) << added.message();
  EXPECT_EQ(added->spheres[0].node, 2);
  Result<ProxyRig> newer = parse_rig("{\"schema\": \"proxygi.proxies\", \"version\": 2, \"spheres\": []}", "f.json", ch);
  ASSERT_FALSE(newer.ok());
  EXPECT_NE(newer.message().find("version 2"), std::string::npos);
  Result<ProxyRig> broken = parse_rig("{\n\"schema\": \"proxygi.proxies\",\n\"version\": 1,\n\"spheres\": [ {]\n}", "f.json", ch);
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.message().rfind("f.json:4: not valid JSON", 0), 0u) << broken.message();
  // A number beyond a double made the JSON library throw out of the parser (fuzz_rig_parse).
  Result<ProxyRig> overflow = parse("{\"bone\": \"upper\", \"center\": [0,0,0], \"radius\": -0.0054e0682}");
  ASSERT_FALSE(overflow.ok());
  EXPECT_EQ(overflow.message().rfind("f.json: invalid rig file", 0), 0u) << overflow.message();
}

TEST(Tracking, RigidFollowsTheBoneAndBlendedFollowsTheWeights) {
  const anim::Character ch = testing::arm_character();
  FitResult fit = fit_arm(ch);
  // A pose: "lower" bent 90 degrees about Z at the elbow, everything scaled by 2 at the root.
  std::vector<glm::mat4> world = rest_world_matrices(ch);
  const glm::mat4 root = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
  world[1] = root * world[1];
  world[2] = world[1] * glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0, 0)) *
             glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1));
  world[3] = world[2] * glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0, 0));
  const std::vector<glm::mat4> bind_to_bone = bind_to_bone_matrices(ch, rest_world_matrices(ch));

  Result<TrackingRig> rigid = compile_tracking(fit.rig, ch, Binding::rigid);
  Result<TrackingRig> blended = compile_tracking(fit.rig, ch, Binding::blended);
  ASSERT_TRUE(rigid.ok() && blended.ok());
  std::vector<WorldSphere> a(fit.rig.spheres.size()), b(fit.rig.spheres.size());
  ASSERT_TRUE((TrackProxiesJob{&*rigid, world, a}.run().ok()));
  ASSERT_TRUE((TrackProxiesJob{&*blended, world, b}.run().ok()));
  for (std::size_t i = 0; i < fit.rig.spheres.size(); ++i) {
    const ProxySphere& s = fit.rig.spheres[i];
    const glm::vec3 expected_rigid = glm::vec3(world[std::size_t(s.node)] * glm::vec4(s.center, 1.0f));
    EXPECT_NEAR(glm::length(a[i].center - expected_rigid), 0.0f, 1e-5f);
    EXPECT_NEAR(a[i].radius, 2.0f * s.radius, 1e-5f);
    glm::vec3 expected_blended(0.0f);
    for (int k = 0; k < kSphereWeights && s.weight_nodes[std::size_t(k)] >= 0; ++k) {
      const std::size_t n = std::size_t(s.weight_nodes[std::size_t(k)]);
      expected_blended += s.weights[std::size_t(k)] * glm::vec3(world[n] * bind_to_bone[n] * glm::vec4(fit.fitted[i].center, 1.0f));
    }
    EXPECT_NEAR(glm::length(b[i].center - expected_blended), 0.0f, 1e-5f);
    EXPECT_NEAR(b[i].radius, 2.0f * fit.fitted[i].radius, 1e-5f);
    EXPECT_EQ(a[i].albedo, s.albedo);
  }
  // Wrong sizes are refused, not read past.
  std::vector<glm::mat4> short_world(1);
  EXPECT_FALSE((TrackProxiesJob{&*rigid, short_world, a}.validate().ok()));
  EXPECT_FALSE((TrackProxiesJob{&*rigid, world, std::span<WorldSphere>(a).first(1)}.validate().ok()));
}

TEST(Tracking, BindingEvaluationCoversEveryFrame) {
  anim::Character ch = testing::arm_character();
  anim::Clip clip;
  clip.name = "bend";
  anim::Channel channel;
  channel.node = 2;
  channel.path = anim::ChannelPath::rotation;
  channel.components = 4;
  channel.times = {0.0f, 1.0f};
  const glm::quat bent = glm::angleAxis(glm::radians(70.0f), glm::vec3(0, 0, 1));
  channel.values = {0, 0, 0, 1, bent.x, bent.y, bent.z, bent.w};
  clip.channels.push_back(channel);
  clip.duration = 1.0f;
  ch.clips.push_back(clip);
  const FitResult fit = fit_arm(ch);
  Result<BindingEvaluation> eval = evaluate_bindings(ch, fit, 30.0f);
  ASSERT_TRUE(eval.ok()) << eval.message();
  EXPECT_EQ(eval->frames, 31);
  for (const BindingError& e : {eval->rigid, eval->blended}) {
    EXPECT_TRUE(std::isfinite(e.worst_poke_out));
    EXPECT_GE(e.worst_poke_out, e.mean_poke_out);
    EXPECT_GE(e.mean_poke_out, 0.0f);
  }
  // Bending the elbow must pull some skinned point out of some sphere under rigid binding.
  EXPECT_GT(eval->rigid.worst_poke_out, 0.0f);
  EXPECT_EQ(eval->better, eval->blended.worst_poke_out < eval->rigid.worst_poke_out ? Binding::blended : Binding::rigid);
}

}  // namespace
}  // namespace proxygi::proxies
