// Import of base color texture details: the glTF sampler (filters, wrap modes, defaults) and
// KHR_texture_transform (offset, rotation, scale, texCoord override).
#include <cmath>

#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "anim/import_builder.h"

namespace proxygi::anim {
namespace {

using testing::GltfBuilder;

// 1x1 RGBA PNG, pixel (255, 0, 0, 255).
const std::vector<std::uint8_t> kPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
    0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00, 0x0d, 0x49,
    0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x00, 0x05, 0x00, 0x01, 0xff, 0x89, 0x99, 0x3d,
    0x1d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

GltfBuilder textured_quad(const nlohmann::json& texture_info, const nlohmann::json& samplers) {
  auto b = testing::skinned_quad();
  auto& j = b.json();
  j["images"] = {{{"uri", "data:image/png;base64," + GltfBuilder::base64(kPng)}}};
  j["textures"] = {{{"source", 0}}};
  if (!samplers.is_null()) {
    j["samplers"] = samplers;
    j["textures"][0]["sampler"] = 0;
  }
  j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", texture_info}}}}};
  j["meshes"][0]["primitives"][0]["material"] = 0;
  return b;
}

Result<Character> import(const GltfBuilder& b) { return import_gltf_bytes(b.gltf_bytes(), "test.gltf", {}); }

TEST(ImportMaterial, SamplerDefaultsToRepeatLinearMipmapLinear) {
  auto c = import(textured_quad({{"index", 0}}, nullptr));
  ASSERT_TRUE(c.ok()) << c.message();
  const TextureSampler& s = c->materials[0].base_color_sampler;
  EXPECT_EQ(s.magnification, TextureFilter::linear);
  EXPECT_EQ(s.minification, TextureFilter::linear);
  EXPECT_TRUE(s.mipmaps);
  EXPECT_EQ(s.mipmap, TextureFilter::linear);
  EXPECT_EQ(s.wrap_s, TextureWrap::repeat);
  EXPECT_EQ(s.wrap_t, TextureWrap::repeat);
  EXPECT_EQ(c->materials[0].base_color_uv_transform, glm::mat3(1.0f));
}

TEST(ImportMaterial, SamplerFiltersAndWrapModes) {
  auto c = import(textured_quad({{"index", 0}}, {{{"magFilter", 9728}, {"minFilter", 9985}, {"wrapS", 33071}, {"wrapT", 33648}}}));
  ASSERT_TRUE(c.ok()) << c.message();
  const TextureSampler& s = c->materials[0].base_color_sampler;
  EXPECT_EQ(s.magnification, TextureFilter::nearest);
  EXPECT_EQ(s.minification, TextureFilter::linear);  // LINEAR_MIPMAP_NEAREST
  EXPECT_TRUE(s.mipmaps);
  EXPECT_EQ(s.mipmap, TextureFilter::nearest);
  EXPECT_EQ(s.wrap_s, TextureWrap::clamp_to_edge);
  EXPECT_EQ(s.wrap_t, TextureWrap::mirrored_repeat);

  auto plain = import(textured_quad({{"index", 0}}, {{{"minFilter", 9728}}}));
  ASSERT_TRUE(plain.ok()) << plain.message();
  EXPECT_FALSE(plain->materials[0].base_color_sampler.mipmaps);  // NEAREST: level 0 only
  EXPECT_EQ(plain->materials[0].base_color_sampler.minification, TextureFilter::nearest);
}

TEST(ImportMaterial, BadSamplerValuesAreErrors) {
  auto wrap = import(textured_quad({{"index", 0}}, {{{"wrapS", 1234}}}));
  ASSERT_FALSE(wrap.ok());
  EXPECT_NE(wrap.message().find("wrapS"), std::string::npos) << wrap.message();
  auto filter = import(textured_quad({{"index", 0}}, {{{"magFilter", 9987}}}));
  ASSERT_FALSE(filter.ok());
  EXPECT_NE(filter.message().find("magFilter"), std::string::npos) << filter.message();
}

TEST(ImportMaterial, TextureTransformMatrixAndTexCoordOverride) {
  const nlohmann::json transform = {{"offset", {0.5, 0.25}}, {"rotation", 1.5707963267948966}, {"scale", {2.0, 3.0}},
                                    {"texCoord", 1}};
  auto c = import(textured_quad({{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}, nullptr));
  ASSERT_TRUE(c.ok()) << c.message();
  const glm::mat3& m = c->materials[0].base_color_uv_transform;
  // translation * rotation (counter-clockwise: columns (c, s), (−s, c)) * scale.
  const glm::vec3 u = m * glm::vec3(1, 0, 1), v = m * glm::vec3(0, 1, 1);
  EXPECT_NEAR(u.x, 0.5f, 1e-6f);
  EXPECT_NEAR(u.y, 2.25f, 1e-6f);
  EXPECT_NEAR(v.x, -2.5f, 1e-6f);
  EXPECT_NEAR(v.y, 0.25f, 1e-6f);
  EXPECT_EQ(c->materials[0].base_color_texcoord, 1);

  auto bad = import(textured_quad(
      {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {1.0}}}}}}}, nullptr));
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("KHR_texture_transform"), std::string::npos) << bad.message();
}

}  // namespace
}  // namespace proxygi::anim
