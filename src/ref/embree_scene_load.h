#pragma once
// A scene file's geometry for the reference path tracer, as world-space triangle meshes at one
// scene time: every character posed with anim::evaluate_pose (clip time from
// scene::clip_time_s, looping) and placed by scene::character_world_matrix, skinned by
// anim::pose_meshes; the ground square (y = 0, scene.ground.size, its albedo); static meshes in
// their rest pose under their transform. Albedo = glTF base color factor × base color texture
// (sRGB texels decoded to linear once, at load), or the static mesh's albedo override.
//
//   auto assets = load_scene_assets(scene, assets_dir);           // import once
//   auto meshes = pose_scene_meshes(scene, *assets, frame_time);   // per frame
//   auto embree = EmbreeScene::build(std::move(*meshes));
#include <filesystem>
#include <memory>
#include <vector>

#include "anim/character.h"
#include "base/result.h"
#include "ref/embree_scene.h"
#include "scene/scene.h"

namespace proxygi::ref {

struct LoadedModel {
  anim::Character character;
  int clip = -1;  // resolved clip index (-1: rest pose, used for static meshes)
  std::vector<std::shared_ptr<const LinearTexture>> textures;  // per character image, null if unused
};

struct SceneAssets {
  std::vector<LoadedModel> characters;     // one per scene.characters entry
  std::vector<LoadedModel> static_meshes;  // one per scene.static_meshes entry
};

// Imports every model of the scene. "builtin:mannequin" reads assets_dir/mannequin.glb and, when
// that file does not exist, builds the same mannequin in code (anim::build_mannequin).
Result<SceneAssets> load_scene_assets(const scene::Scene& scene, const std::filesystem::path& assets_dir);

// World-space meshes of the whole scene at scene time t (seconds).
Result<std::vector<TriangleMesh>> pose_scene_meshes(const scene::Scene& scene, const SceneAssets& assets,
                                                    double scene_time_s);

// The ground square as two triangles (normal +Y), or nothing when the ground is disabled.
std::vector<TriangleMesh> ground_meshes(const scene::Ground& ground);

}  // namespace proxygi::ref
