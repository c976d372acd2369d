// Materials (base color factor and texture) and the images they use, decoded to RGBA8.
#include <cmath>
#include <set>

#include "anim/import_accessor.h"
#include "anim/import_context.h"
#include "anim/import_sandbox.h"
#include "anim/import_stb.h"
#include "base/log.h"

namespace proxygi::anim::detail {
namespace {

Result<TextureWrap> convert_wrap(int mode, const std::string& what) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::clamp_to_edge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::mirrored_repeat;
    default: return error_at(what, "wrap mode " + std::to_string(mode) + " is not a glTF wrap mode");
  }
}

Result<TextureSampler> convert_sampler(const tinygltf::Model& model, int index) {
  TextureSampler sampler;
  if (index < 0) return sampler;
  const std::string what = "sampler " + std::to_string(index);
  if (static_cast<std::size_t>(index) >= model.samplers.size())
    return error_at(what, "out of range (" + std::to_string(model.samplers.size()) + " samplers)");
  const tinygltf::Sampler& source = model.samplers[static_cast<std::size_t>(index)];
  switch (source.magFilter) {
    case -1:
    case TINYGLTF_TEXTURE_FILTER_LINEAR: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: sampler.magnification = TextureFilter::nearest; break;
    default: return error_at(what, "magFilter " + std::to_string(source.magFilter) + " is not a glTF filter");
  }
  using enum TextureFilter;
  switch (source.minFilter) {
    case -1: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: sampler = {sampler.magnification, nearest, false, nearest}; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: sampler = {sampler.magnification, linear, false, nearest}; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: sampler = {sampler.magnification, nearest, true, nearest}; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: sampler = {sampler.magnification, linear, true, nearest}; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: sampler = {sampler.magnification, nearest, true, linear}; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: sampler = {sampler.magnification, linear, true, linear}; break;
    default: return error_at(what, "minFilter " + std::to_string(source.minFilter) + " is not a glTF filter");
  }
  auto wrap_s = convert_wrap(source.wrapS, what + " wrapS");
  if (!wrap_s) return wrap_s.error();
  auto wrap_t = convert_wrap(source.wrapT, what + " wrapT");
  if (!wrap_t) return wrap_t.error();
  sampler.wrap_s = *wrap_s;
  sampler.wrap_t = *wrap_t;
  return sampler;
}

// KHR_texture_transform on a textureInfo: the uv matrix (extension README: translation *
// rotation * scale, rotation counter-clockwise) and its texCoord override.
Status convert_texture_transform(const tinygltf::TextureInfo& info, const std::string& what, Material& material) {
  const auto found = info.extensions.find("KHR_texture_transform");
  if (found == info.extensions.end()) return {};
  const tinygltf::Value& value = found->second;
  auto number = [&](const tinygltf::Value& v, const std::string& name) -> Result<float> {
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
      return error_at(what + " KHR_texture_transform", name + " is not a finite number");
    return static_cast<float>(v.GetNumberAsDouble());
  };
  auto pair = [&](const std::string& name, glm::vec2 fallback) -> Result<glm::vec2> {
    if (!value.Has(name)) return fallback;
    const tinygltf::Value& v = value.Get(name);
    if (!v.IsArray() || v.ArrayLen() != 2) return error_at(what + " KHR_texture_transform", name + " is not 2 numbers");
    auto x = number(v.Get(0), name);
    auto y = number(v.Get(1), name);
    if (!x) return x.error();
    if (!y) return y.error();
    return glm::vec2(*x, *y);
  };
  auto offset = pair("offset", glm::vec2(0.0f));
  auto scale = pair("scale", glm::vec2(1.0f));
  if (!offset) return offset.error();
  if (!scale) return scale.error();
  float rotation = 0.0f;
  if (value.Has("rotation")) {
    auto r = number(value.Get("rotation"), "rotation");
    if (!r) return r.error();
    rotation = *r;
  }
  if (value.Has("texCoord")) {
    const tinygltf::Value& t = value.Get("texCoord");
    if (!t.IsInt() || t.Get<int>() < 0) return error_at(what + " KHR_texture_transform", "texCoord is not an index");
    material.base_color_texcoord = t.Get<int>();
  }
  const float c = std::cos(rotation), s = std::sin(rotation);
  const glm::mat3 translate(1, 0, 0, 0, 1, 0, offset->x, offset->y, 1);  // columns
  const glm::mat3 rotate(c, s, 0, -s, c, 0, 0, 0, 1);
  const glm::mat3 scaling(scale->x, 0, 0, 0, scale->y, 0, 0, 0, 1);
  material.base_color_uv_transform = translate * rotate * scaling;
  return {};
}

Result<Material> convert_material(const tinygltf::Model& model, std::size_t index, std::set<int>& used_images) {
  const tinygltf::Material& source = model.materials[index];
  const std::string what = "material " + std::to_string(index);
  Material material;
  material.name = source.name;
  material.double_sided = source.doubleSided;
  const auto& factor = source.pbrMetallicRoughness.baseColorFactor;
  if (factor.size() != 4) {
    return error_at(what, "baseColorFactor has " + std::to_string(factor.size()) + " numbers, expected 4");
  }
  for (std::size_t c = 0; c < 4; ++c) {
    if (!std::isfinite(factor[c])) return error_at(what, "baseColorFactor contains NaN or infinity");
    material.base_color_factor[static_cast<int>(c)] = static_cast<float>(factor[c]);
  }
  const tinygltf::TextureInfo& info = source.pbrMetallicRoughness.baseColorTexture;
  if (info.index < 0) return material;
  if (static_cast<std::size_t>(info.index) >= model.textures.size()) {
    return error_at(what, "baseColorTexture " + std::to_string(info.index) + " out of range (" +
                              std::to_string(model.textures.size()) + " textures)");
  }
  const tinygltf::Texture& texture = model.textures[static_cast<std::size_t>(info.index)];
  const int image = texture.source;
  if (image < 0) return material;  // texture given only through an extension: untextured
  if (static_cast<std::size_t>(image) >= model.images.size()) {
    return error_at("texture " + std::to_string(info.index),
                    "source image " + std::to_string(image) + " out of range (" +
                        std::to_string(model.images.size()) + " images)");
  }
  material.base_color_image = image;
  material.base_color_texcoord = info.texCoord;
  auto sampler = convert_sampler(model, texture.sampler);
  if (!sampler) return error_at("texture " + std::to_string(info.index), sampler.message());
  material.base_color_sampler = *sampler;
  if (Status transformed = convert_texture_transform(info, what + " baseColorTexture", material); !transformed)
    return transformed.error();
  used_images.insert(image);
  return material;
}

Result<std::vector<std::uint8_t>> encoded_bytes(ImportContext& ctx, std::size_t index, const std::string& what) {
  const tinygltf::Image& source = ctx.model.images[index];
  if (source.bufferView >= 0) {
    auto bytes = buffer_view_bytes(ctx, source.bufferView, what);
    if (!bytes) return bytes.error();
    return std::vector<std::uint8_t>(bytes->begin(), bytes->end());
  }
  if (!source.image.empty()) return source.image;  // data: URI, stored by the loader callback
  if (!source.uri.empty()) {
    auto bytes = read_external_file(ctx.base_dir, source.uri, ctx.limits.max_file_bytes);
    if (!bytes) return error_at(what, bytes.message());
    return std::move(*bytes);
  }
  return error_at(what, "has no data");
}

}  // namespace

Status import_materials(ImportContext& ctx, Character& character) {
  const tinygltf::Model& model = ctx.model;
  std::set<int> used_images;
  character.materials.clear();
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    auto material = convert_material(model, m, used_images);
    if (!material) return material.error();
    character.materials.push_back(std::move(*material));
  }
  character.images.assign(model.images.size(), Image{});
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    character.images[i].name = model.images[i].name;
  }
  for (int index : used_images) {
    const auto i = static_cast<std::size_t>(index);
    const std::string what = "image " + std::to_string(index);
    auto bytes = encoded_bytes(ctx, i, what);
    if (!bytes) return bytes.error();
    const std::uint64_t pixels_left = ctx.limits.max_total_image_pixels - ctx.image_pixels_decoded;
    auto decoded = decode_image(*bytes, ctx.limits.max_image_dimension,
                                std::min(ctx.limits.max_image_pixels, pixels_left));
    if (!decoded && decoded.message().find("limit") != std::string::npos) return error_at(what, decoded.message());
    if (!decoded) {
      // A texture that does not decode (truncated, not PNG/JPEG): as glTF viewers do: the material keeps its base color factor, without the texture.
      log_warning(character.source + ": " + what + ": " + decoded.message() + "; using the base color factor instead");
      for (Material& material : character.materials)
        if (material.base_color_image == index) material.base_color_image = -1;
      continue;
    }
    ctx.image_pixels_decoded += static_cast<std::uint64_t>(decoded->width) * static_cast<std::uint64_t>(decoded->height);
    Image& image = character.images[i];
    image.width = decoded->width;
    image.height = decoded->height;
    image.rgba = std::move(decoded->rgba);
  }
  return {};
}

}  // namespace proxygi::anim::detail
