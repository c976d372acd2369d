// Materials (base color factor and texture) and the images they use, decoded to RGBA8.
#include <cmath>
#include <set>

#include "anim/import_accessor.h"
#include "anim/import_context.h"
#include "anim/import_sandbox.h"
#include "anim/import_stb.h"

namespace proxygi::anim::detail {
namespace {

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
  const int image = model.textures[static_cast<std::size_t>(info.index)].source;
  if (image < 0) return material;  // texture given only through an extension: untextured
  if (static_cast<std::size_t>(image) >= model.images.size()) {
    return error_at("texture " + std::to_string(info.index),
                    "source image " + std::to_string(image) + " out of range (" +
                        std::to_string(model.images.size()) + " images)");
  }
  material.base_color_image = image;
  material.base_color_texcoord = info.texCoord;
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
    if (!decoded) return error_at(what, decoded.message());
    ctx.image_pixels_decoded += static_cast<std::uint64_t>(decoded->width) * static_cast<std::uint64_t>(decoded->height);
    Image& image = character.images[i];
    image.width = decoded->width;
    image.height = decoded->height;
    image.rgba = std::move(decoded->rgba);
  }
  return {};
}

}  // namespace proxygi::anim::detail
