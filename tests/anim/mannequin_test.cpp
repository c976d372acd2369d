// The built-in mannequin: committed bytes equal the generator's output, it round-trips through
// the importer, and its figure and clips keep their documented properties.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "anim/gltf_writer.h"
#include "anim/mannequin.h"
#include "anim/posed_character.h"
#include "base/atomic_file.h"

namespace proxygi::anim {
namespace {

const Character& mannequin() {
  static const Character character = build_mannequin();
  return character;
}

struct Bounds {
  glm::vec3 low{std::numeric_limits<float>::max()};
  glm::vec3 high{std::numeric_limits<float>::lowest()};
};

Bounds bounds_of(const std::vector<PosedPrimitive>& meshes, int material = -1) {
  Bounds b;
  for (const PosedPrimitive& mesh : meshes) {
    if (material >= 0 && mesh.material != material) continue;
    for (const glm::vec3& p : mesh.positions) {
      b.low = glm::min(b.low, p);
      b.high = glm::max(b.high, p);
    }
  }
  return b;
}

std::vector<PosedPrimitive> posed(const Character& character, int clip, float time) {
  PoseBuffers pose;
  EXPECT_TRUE(evaluate_pose(character, clip, time, WrapMode::loop, pose).ok());
  Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
  EXPECT_TRUE(meshes.ok());
  return meshes ? *meshes : std::vector<PosedPrimitive>{};
}

TEST(Mannequin, CommittedAssetEqualsTheGeneratedBytes) {
  Result<std::vector<std::uint8_t>> generated = encode_glb(mannequin());
  ASSERT_TRUE(generated.ok()) << generated.message();
  Result<std::vector<std::uint8_t>> committed = read_file(PROXYGI_SOURCE_DIR "/assets/mannequin.glb", 64u << 20);
  ASSERT_TRUE(committed.ok()) << committed.message();
  EXPECT_TRUE(*generated == *committed)
      << "assets/mannequin.glb is stale: regenerate it with `proxygi mannequin -o assets/mannequin.glb`";
}

TEST(Mannequin, GenerationIsDeterministic) {
  Result<std::vector<std::uint8_t>> a = encode_glb(build_mannequin());
  Result<std::vector<std::uint8_t>> b = encode_glb(build_mannequin());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(*a == *b);
}

TEST(Mannequin, RoundTripsThroughTheImporter) {
  Result<Character> imported = import_gltf(PROXYGI_SOURCE_DIR "/assets/mannequin.glb");
  ASSERT_TRUE(imported.ok()) << imported.message();
  const Character& original = mannequin();
  ASSERT_EQ(imported->nodes.size(), original.nodes.size());
  for (std::size_t n = 0; n < original.nodes.size(); ++n) {
    EXPECT_EQ(imported->nodes[n].name, original.nodes[n].name);
    EXPECT_EQ(imported->nodes[n].parent, original.nodes[n].parent);
    EXPECT_EQ(imported->nodes[n].rest.translation, original.nodes[n].rest.translation);
  }
  ASSERT_EQ(imported->meshes.size(), 1u);
  ASSERT_EQ(imported->meshes[0].primitives.size(), original.meshes[0].primitives.size());
  for (std::size_t p = 0; p < original.meshes[0].primitives.size(); ++p) {
    const Primitive& a = original.meshes[0].primitives[p];
    const Primitive& b = imported->meshes[0].primitives[p];
    EXPECT_EQ(a.positions, b.positions);
    ASSERT_EQ(a.normals.size(), b.normals.size());
    for (std::size_t i = 0; i < a.normals.size(); ++i) {  // the importer renormalizes: 1-ulp changes
      ASSERT_NEAR(glm::distance(a.normals[i], b.normals[i]), 0.0f, 1e-6f);
    }
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.joints, b.joints);
    EXPECT_EQ(a.influences_per_vertex, b.influences_per_vertex);
    EXPECT_EQ(a.material, b.material);
    ASSERT_EQ(a.weights.size(), b.weights.size());
    for (std::size_t i = 0; i < a.weights.size(); ++i) EXPECT_NEAR(a.weights[i], b.weights[i], 1e-7f);  // renormalized
  }
  ASSERT_EQ(imported->skins.size(), 1u);
  EXPECT_EQ(imported->skins[0].joints, original.skins[0].joints);
  EXPECT_EQ(imported->skins[0].inverse_bind_matrices, original.skins[0].inverse_bind_matrices);
  ASSERT_EQ(imported->materials.size(), original.materials.size());
  for (std::size_t m = 0; m < original.materials.size(); ++m) {
    EXPECT_EQ(imported->materials[m].name, original.materials[m].name);
    EXPECT_EQ(imported->materials[m].base_color_factor, original.materials[m].base_color_factor);
  }
  ASSERT_EQ(imported->clips.size(), 3u);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(imported->clips[c].name, original.clips[c].name);
    EXPECT_EQ(imported->clips[c].duration, original.clips[c].duration);
    ASSERT_EQ(imported->clips[c].channels.size(), original.clips[c].channels.size());
    for (std::size_t k = 0; k < original.clips[c].channels.size(); ++k) {
      EXPECT_EQ(imported->clips[c].channels[k].times, original.clips[c].channels[k].times);
      EXPECT_EQ(imported->clips[c].channels[k].node, original.clips[c].channels[k].node);
    }
  }
}

TEST(Mannequin, FigureStandsOnTheGroundFacingPlusZ) {
  const Character& character = mannequin();
  EXPECT_EQ(character.skins[0].joints.size(), 22u);
  std::size_t vertices = 0;
  for (const Primitive& p : character.meshes[0].primitives) {
    vertices += p.positions.size();
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
      float sum = 0.0f;
      for (int k = 0; k < 4; ++k) sum += p.weights[v * 4 + static_cast<std::size_t>(k)];
      ASSERT_NEAR(sum, 1.0f, 1e-6f);
    }
  }
  EXPECT_GT(vertices, 2000u);
  EXPECT_LT(vertices, 10000u);
  float lowest_bind = 1.0f;
  for (const Primitive& p : character.meshes[0].primitives) {
    for (const glm::vec3& v : p.positions) lowest_bind = std::min(lowest_bind, v.y);
  }
  EXPECT_EQ(lowest_bind, 0.0f);  // exactly on the ground in bind space
  const std::vector<PosedPrimitive> rest = posed(character, -1, 0.0f);
  const Bounds all = bounds_of(rest);
  EXPECT_NEAR(all.low.y, 0.0f, 1e-6f);  // skinned: translation · inverse translation rounding
  EXPECT_NEAR(all.high.y, 1.8f, 0.02f);
  const Bounds shoes = bounds_of(rest, 3);
  EXPECT_GT(shoes.high.z, 0.15f);   // toes point to +Z
  EXPECT_LT(shoes.low.z, -0.05f);   // heels behind the ankles
  EXPECT_EQ(character.nodes[9].name, "left_hand");
  EXPECT_LT(character.skins[0].inverse_bind_matrices[9][3].x, 0.0f);  // IBM = T(−p): left hand at +X
  // Four distinct materials: red shirt, blue trousers, skin, dark shoes.
  ASSERT_EQ(character.materials.size(), 4u);
  EXPECT_GT(character.materials[0].base_color_factor.r, 0.6f);
  EXPECT_GT(character.materials[1].base_color_factor.b, 0.4f);
}

TEST(Mannequin, CyclesLoopSeamlesslyAndWaveReturnsToRest) {
  const Character& character = mannequin();
  for (const char* name : {"walk", "run", "wave"}) {
    const int clip = *find_clip(character, name);
    for (const Channel& channel : character.clips[static_cast<std::size_t>(clip)].channels) {
      const std::size_t n = static_cast<std::size_t>(channel.components);
      const std::vector<float> first(channel.values.begin(), channel.values.begin() + static_cast<std::ptrdiff_t>(n));
      const std::vector<float> last(channel.values.end() - static_cast<std::ptrdiff_t>(n), channel.values.end());
      EXPECT_EQ(first, last) << name << " channel on node " << channel.node;
    }
  }
  // Wave starts and ends in the rest pose.
  const std::vector<PosedPrimitive> rest = posed(character, -1, 0.0f);
  const int wave = *find_clip(character, "wave");
  for (const float t : {0.0f, character.clips[static_cast<std::size_t>(wave)].duration}) {
    PoseBuffers pose;
    ASSERT_TRUE(evaluate_pose(character, wave, t, WrapMode::clamp, pose).ok());
    Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
    ASSERT_TRUE(meshes.ok());
    for (std::size_t m = 0; m < rest.size(); ++m) {
      for (std::size_t v = 0; v < rest[m].positions.size(); ++v) {
        ASSERT_NEAR(glm::distance((*meshes)[m].positions[v], rest[m].positions[v]), 0.0f, 1e-5f);
      }
    }
  }
  // Mid-wave the right hand (−X side) is above the head.
  const Bounds waving = bounds_of(posed(character, wave, 1.2f));
  EXPECT_GT(waving.high.y, 1.9f);
}

// In-place locomotion: the stance foot slides backward at the documented speed and stays on the
// ground; the body never sinks below it.
TEST(Mannequin, WalkAndRunFeetMatchTheDocumentedSpeed) {
  const Character& character = mannequin();
  struct Case {
    const char* clip;
    float speed;
    float stance_time;  // a time inside the left foot's stance (left stance starts at phase 0)
  };
  for (const Case& c : {Case{"walk", kWalkSpeed, 0.2f}, Case{"run", kRunSpeed, 0.1f}}) {
    const int clip = *find_clip(character, c.clip);
    const int left_foot = 16;
    ASSERT_EQ(character.nodes[left_foot].name, "left_foot");
    PoseBuffers a, b;
    const float dt = 1.0f / 30.0f;
    ASSERT_TRUE(evaluate_pose(character, clip, c.stance_time, WrapMode::loop, a).ok());
    ASSERT_TRUE(evaluate_pose(character, clip, c.stance_time + dt, WrapMode::loop, b).ok());
    const float velocity = (b.world[left_foot][3].z - a.world[left_foot][3].z) / dt;
    EXPECT_NEAR(velocity, -c.speed, 0.03f * c.speed) << c.clip;
    EXPECT_NEAR(a.world[left_foot][3].y, character.skins[0].inverse_bind_matrices[left_foot][3].y * -1.0f, 2e-3f);
    const float duration = character.clips[static_cast<std::size_t>(clip)].duration;
    for (int k = 0; k < 12; ++k) {
      const Bounds body = bounds_of(posed(character, clip, duration * static_cast<float>(k) / 12.0f));
      EXPECT_GT(body.low.y, -0.02f) << c.clip << " at key " << k;
      EXPECT_LT(body.low.y, 0.03f) << c.clip << " at key " << k;
      EXPECT_TRUE(std::isfinite(body.high.x + body.high.y + body.high.z));
    }
  }
}

}  // namespace
}  // namespace proxygi::anim
