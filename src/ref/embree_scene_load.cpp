#include "ref/embree_scene_load.h"

#include <string>
#include <utility>
#include <variant>

#include "anim/gltf_import.h"
#include "anim/mannequin.h"
#include "anim/posed_character.h"
#include "image/image.h"
#include "render/texture_sampling.h"
#include "scene/character_motion.h"

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

Result<LoadedModel> load_model(const scene::Scene& scene, const std::string& model,
                               const std::filesystem::path& assets_dir) {
  LoadedModel out;
  const std::filesystem::path file = scene::resolve_model_path(scene, model, assets_dir);
  std::error_code ec;
  if (scene::is_builtin_mannequin(model) && !std::filesystem::exists(file, ec)) {
    out.character = anim::build_mannequin();  // the same figure the asset file holds
  } else {
    auto character = anim::import_gltf(file);
    if (!character) return character.error();
    out.character = std::move(*character);
  }
  out.textures.resize(out.character.images.size());
  for (const anim::Material& material : out.character.materials) {
    const int image = material.base_color_image;
    if (image >= 0 && std::size_t(image) < out.character.images.size() && !out.textures[std::size_t(image)])
      out.textures[std::size_t(image)] = decode_texture(out.character.images[std::size_t(image)]);
  }
  return out;
}

SurfaceMaterial material_of(const LoadedModel& model, int material_index) {
  SurfaceMaterial out;
  out.albedo = glm::vec3(1.0f);  // glTF default material: white
  if (material_index < 0 || std::size_t(material_index) >= model.character.materials.size()) return out;
  const anim::Material& material = model.character.materials[std::size_t(material_index)];
  out.albedo = glm::vec3(material.base_color_factor);
  const int image = material.base_color_image;
  if (image < 0 || std::size_t(image) >= model.textures.size()) return out;
  if (material.base_color_texcoord != 0) {  // only TEXCOORD_0 is imported: the GPU's fallback too
    out.albedo *= render::mean_linear_color(model.character.images[std::size_t(image)]);
    return out;
  }
  out.texture = model.textures[std::size_t(image)];
  out.sampler = material.base_color_sampler;
  out.uv_transform = material.base_color_uv_transform;
  return out;
}

Status append_posed(const LoadedModel& model, float clip_time, const glm::mat4& root,
                    const std::optional<glm::vec3>& albedo_override, std::vector<TriangleMesh>& out) {
  anim::PoseBuffers pose;
  if (Status s = anim::evaluate_pose(model.character, model.clip, clip_time, anim::WrapMode::loop, pose, root); !s)
    return s;
  auto primitives = anim::pose_meshes(model.character, pose);
  if (!primitives) return primitives.error();
  for (anim::PosedPrimitive& primitive : *primitives) {
    TriangleMesh mesh;
    mesh.name = model.character.source + ":" + primitive.name;
    mesh.positions = std::move(primitive.positions);
    mesh.normals = std::move(primitive.normals);
    mesh.uvs = std::move(primitive.uvs);
    mesh.indices = std::move(primitive.indices);
    mesh.material = material_of(model, primitive.material);
    if (albedo_override) {
      mesh.material.albedo = *albedo_override;
      mesh.material.texture = nullptr;  // the override replaces the whole base color
    }
    out.push_back(std::move(mesh));
  }
  return {};
}

}  // namespace

Result<SceneAssets> load_scene_assets(const scene::Scene& scene, const std::filesystem::path& assets_dir) {
  SceneAssets assets;
  for (std::size_t i = 0; i < scene.characters.size(); ++i) {
    const scene::Character& character = scene.characters[i];
    auto model = load_model(scene, character.model, assets_dir);
    const std::string where = "characters[" + std::to_string(i) + "]: ";
    if (!model) return make_error(where + model.message());
    const std::string clip_name = std::holds_alternative<int>(character.clip)
                                      ? std::to_string(std::get<int>(character.clip))
                                      : std::get<std::string>(character.clip);
    auto clip = anim::find_clip(model->character, clip_name);
    if (!clip) return make_error(where + clip.message());
    model->clip = *clip;
    assets.characters.push_back(std::move(*model));
  }
  for (std::size_t i = 0; i < scene.static_meshes.size(); ++i) {
    auto model = load_model(scene, scene.static_meshes[i].model, assets_dir);
    if (!model) return make_error("static_meshes[" + std::to_string(i) + "]: " + model.message());
    assets.static_meshes.push_back(std::move(*model));
  }
  return assets;
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

Result<std::vector<TriangleMesh>> pose_scene_meshes(const scene::Scene& scene, const SceneAssets& assets,
                                                    double scene_time_s) {
  if (assets.characters.size() != scene.characters.size() || assets.static_meshes.size() != scene.static_meshes.size())
    return make_error("scene assets do not match the scene (load them from the same scene)");
  std::vector<TriangleMesh> meshes = ground_meshes(scene.ground);
  for (std::size_t i = 0; i < scene.characters.size(); ++i) {
    const scene::Character& character = scene.characters[i];
    const float clip_time = float(scene::clip_time_s(character, scene_time_s));
    const glm::mat4 root = scene::character_world_matrix(character, scene_time_s);
    if (Status s = append_posed(assets.characters[i], clip_time, root, std::nullopt, meshes); !s)
      return make_error("characters[" + std::to_string(i) + "]: " + s.message());
  }
  for (std::size_t i = 0; i < scene.static_meshes.size(); ++i) {
    const scene::StaticMesh& mesh = scene.static_meshes[i];
    if (Status s = append_posed(assets.static_meshes[i], 0.0f, mesh.transform.to_matrix(), mesh.albedo, meshes); !s)
      return make_error("static_meshes[" + std::to_string(i) + "]: " + s.message());
  }
  return meshes;
}

}  // namespace proxygi::ref
