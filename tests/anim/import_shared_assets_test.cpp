// The shared sample characters (../shared/assets/gltf) import with the counts their JSON states.
// Expected counts are read from the GLB's JSON chunk with nlohmann (independent of tinygltf).
#include <cstring>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "anim/gltf_import.h"
#include "base/atomic_file.h"

namespace proxygi::anim {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf";

nlohmann::json glb_json(const std::filesystem::path& path) {
  auto bytes = read_file(path, 1u << 28);
  EXPECT_TRUE(bytes.ok());
  std::uint32_t length = 0;
  std::memcpy(&length, bytes->data() + 12, 4);
  return nlohmann::json::parse(bytes->begin() + 20, bytes->begin() + 20 + length);
}

struct Expected {
  std::size_t vertices = 0, triangles = 0;
};

Expected expected_geometry(const nlohmann::json& j) {
  Expected e;
  for (const auto& mesh : j["meshes"]) {
    for (const auto& primitive : mesh["primitives"]) {
      const std::size_t count = j["accessors"][primitive["attributes"]["POSITION"].get<std::size_t>()]["count"];
      e.vertices += count;
      e.triangles += (primitive.contains("indices") ? j["accessors"][primitive["indices"].get<std::size_t>()]["count"].get<std::size_t>() : count) / 3;
    }
  }
  return e;
}

void check_against_json(const std::string& file) {
  const auto path = kAssets / file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
  auto result = import_gltf(path);
  ASSERT_TRUE(result.ok()) << result.message();
  const Character& c = *result;
  const nlohmann::json j = glb_json(path);
  EXPECT_EQ(c.nodes.size(), j["nodes"].size());
  EXPECT_EQ(c.meshes.size(), j["meshes"].size());
  ASSERT_EQ(c.skins.size(), j["skins"].size());
  for (std::size_t s = 0; s < c.skins.size(); ++s) {
    EXPECT_EQ(c.skins[s].joints.size(), j["skins"][s]["joints"].size());
    EXPECT_EQ(c.skins[s].inverse_bind_matrices.size(), c.skins[s].joints.size());
  }
  EXPECT_EQ(c.materials.size(), j.value("materials", nlohmann::json::array()).size());
  EXPECT_EQ(c.images.size(), j.value("images", nlohmann::json::array()).size());
  ASSERT_EQ(c.clips.size(), j.value("animations", nlohmann::json::array()).size());
  for (std::size_t a = 0; a < c.clips.size(); ++a) {
    const auto& animation = j["animations"][a];
    EXPECT_EQ(c.clips[a].channels.size(), animation["channels"].size());
    double max_time = 0.0;
    for (const auto& sampler : animation["samplers"]) {
      max_time = std::max(max_time, j["accessors"][sampler["input"].get<std::size_t>()]["max"][0].get<double>());
    }
    EXPECT_NEAR(c.clips[a].duration, max_time, 1e-5) << "clip " << a;
  }
  const Expected e = expected_geometry(j);
  std::size_t vertices = 0, triangles = 0;
  for (const auto& mesh : c.meshes) {
    for (const auto& p : mesh.primitives) {
      vertices += p.positions.size();
      triangles += p.indices.size() / 3;
      EXPECT_EQ(p.normals.size(), p.positions.size());
      EXPECT_EQ(p.weights.size(), p.positions.size() * static_cast<std::size_t>(p.influences_per_vertex));
    }
  }
  EXPECT_EQ(vertices, e.vertices);
  EXPECT_EQ(triangles, e.triangles);
  EXPECT_EQ(c.evaluation_order.size(), c.nodes.size());
}

TEST(ImportSharedAssets, CesiumMan) {
  check_against_json("CesiumMan.glb");
  if (HasFatalFailure() || IsSkipped()) return;
  auto c = import_gltf(kAssets / "CesiumMan.glb");
  ASSERT_TRUE(c.ok());
  ASSERT_EQ(c->skins.size(), 1u);
  EXPECT_EQ(c->skins[0].joints.size(), 19u);
  // The base color texture (a JPEG) is decoded.
  ASSERT_EQ(c->materials.size(), 1u);
  const int image = c->materials[0].base_color_image;
  ASSERT_GE(image, 0);
  const Image& texture = c->images[static_cast<std::size_t>(image)];
  EXPECT_GT(texture.width, 0);
  EXPECT_EQ(texture.rgba.size(), static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height) * 4);
}

TEST(ImportSharedAssets, Fox) { check_against_json("Fox.glb"); }

TEST(ImportSharedAssets, RiggedSimple) { check_against_json("RiggedSimple.glb"); }

}  // namespace
}  // namespace proxygi::anim
