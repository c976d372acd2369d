#include "ref/scene_geometry.h"

#include <optional>
#include <string>
#include <utility>

#include "image/image.h"
#include "render/texture_sampling.h"

namespace proxygi::ref {
namespace {

std::shared_ptr<const LinearTexture> decode_texture(const anim::Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() < std::size_t(image.width) * std::size_t(image.height) * 4)
    return nullptr;
  auto texture = std::make_shared<LinearTexture>();
  texture->width = image.width;
  texture->height = image.height;
  texture->texels.resize(std::size_t(image.width) * std::size_t(image.height));
  for (std::size_t i = 0; i < texture->texels.size(); ++i)
    texture->texels[i] = glm::vec3(image::srgb8_to_linear(image.rgba[4 * i]), image::srgb8_to_linear(image.rgba[4 * i + 1]),
                                   image::srgb8_to_linear(image.rgba[4 * i + 2]));
  return texture;
}

ModelTextures decode_textures(const anim::Character& character) {
  ModelTextures textures(character.images.size());
  for (const anim::Material& material : character.materials) {
    const int image = material.base_color_image;
    if (image >= 0 && std::size_t(image) < character.images.size() && !textures[std::size_t(image)])
      textures[std::size_t(image)] = decode_texture(character.images[std::size_t(image)]);
  }
  return textures;
}

SurfaceMaterial material_of(const anim::Character& character, const ModelTextures& textures, int material_index) {
  SurfaceMaterial out;
  out.albedo = glm::vec3(1.0f);  // glTF default material: white
  if (material_index < 0 || std::size_t(material_index) >= character.materials.size()) return out;
  const anim::Material& material = character.materials[std::size_t(material_index)];
  out.albedo = glm::vec3(material.base_color_factor);
  const int image = material.base_color_image;
  if (image < 0 || std::size_t(image) >= textures.size()) return out;
  if (material.base_color_texcoord != 0) {  // only TEXCOORD_0 is imported: the GPU's fallback too
    out.albedo *= render::mean_linear_color(character.images[std::size_t(image)]);
    return out;
  }
  out.texture = textures[std::size_t(image)];
  out.sampler = material.base_color_sampler;
  out.uv_transform = material.base_color_uv_transform;
  return out;
}

// Appends `primitives` (world space) as meshes; `albedo_override` replaces the base color.
void append_meshes(const anim::Character& character, const ModelTextures& textures,
                   std::vector<anim::PosedPrimitive> primitives, const std::optional<glm::vec3>& albedo_override,
                   std::vector<TriangleMesh>& out) {
  for (anim::PosedPrimitive& primitive : primitives) {
    TriangleMesh mesh;
    mesh.name = character.source + ":" + primitive.name;
    mesh.positions = std::move(primitive.positions);
    mesh.normals = std::move(primitive.normals);
    mesh.uvs = std::move(primitive.uvs);
    mesh.indices = std::move(primitive.indices);
    mesh.material = material_of(character, textures, primitive.material);
    if (albedo_override) {
      mesh.material.albedo = *albedo_override;
      mesh.material.texture = nullptr;  // the override replaces the whole base color
    }
    out.push_back(std::move(mesh));
  }
}

}  // namespace

SceneGeometry make_scene_geometry(const world::World& world) {
  SceneGeometry geometry;
  for (const auto& model : world.models()) geometry.models.push_back(decode_textures(model->character));
  for (const world::StaticModel& model : world.static_models())
    geometry.static_models.push_back(decode_textures(model.character));
  return geometry;
}

std::vector<TriangleMesh> ground_meshes(const scene::Ground& ground) {
  if (!ground.enabled) return {};
  const float h = 0.5f * ground.size;
  TriangleMesh mesh;
  mesh.name = "ground";
  mesh.positions = {{-h, 0.0f, -h}, {h, 0.0f, -h}, {h, 0.0f, h}, {-h, 0.0f, h}};
  mesh.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
  mesh.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
  mesh.material.albedo = ground.albedo;
  return {std::move(mesh)};
}

Result<std::vector<TriangleMesh>> world_meshes(const world::World& world, const world::WorldState& state,
                                               const SceneGeometry& geometry) {
  if (geometry.models.size() != world.models().size() || geometry.static_models.size() != world.static_models().size())
    return make_error("scene geometry does not match the world (make it from the same world)");
  std::vector<TriangleMesh> meshes = ground_meshes(world.scene().ground);
  for (std::size_t i = 0; i < world.instances().size(); ++i) {
    const world::CharacterInstance& instance = world.instances()[i];
    auto primitives = world.pose_instance(state, i);
    if (!primitives) return primitives.error();
    const std::size_t first = meshes.size();
    append_meshes(instance.model->character, geometry.models[instance.model_index], std::move(*primitives),
                  std::nullopt, meshes);
    for (std::size_t m = first; m < meshes.size(); ++m) meshes[m].character = true;
  }
  for (std::size_t i = 0; i < world.static_models().size(); ++i) {
    const world::StaticModel& model = world.static_models()[i];
    append_meshes(model.character, geometry.static_models[i], model.primitives, model.albedo, meshes);
  }
  return meshes;
}

}  // namespace proxygi::ref
