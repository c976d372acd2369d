#pragma once
// A world's geometry for the reference path tracer, as world-space triangle meshes at one world
// state: the ground square (y = 0, scene.ground.size, its albedo), every character instance as
// World::pose_instance skins it (so the path tracer poses exactly what the world evaluates), and
// the static meshes the world posed once. Mesh names are "<character source>:<primitive name>"
// ("ground" for the ground). Albedo = glTF base color factor × base color texture (sRGB texels
// decoded to linear once, in SceneGeometry), or the static mesh's albedo override (which
// replaces the texture too).
//
//   auto world = world::World::load(scene, {.assets_dir = assets, .load_rigs = false});
//   auto geometry = make_scene_geometry(**world);                // textures decoded once
//   world::WorldState state;
//   (*world)->evaluate(frame_time, std::nullopt, state);          // per frame
//   auto meshes = world_meshes(**world, state, geometry);
//   auto embree = EmbreeScene::build(std::move(*meshes));
#include <memory>
#include <vector>

#include "base/result.h"
#include "ref/embree_scene.h"
#include "scene/scene.h"
#include "world/world.h"

namespace proxygi::ref {

// Decoded base color textures per character image (null where no material uses it).
using ModelTextures = std::vector<std::shared_ptr<const LinearTexture>>;

struct SceneGeometry {
  std::vector<ModelTextures> models;         // one per World::models()
  std::vector<ModelTextures> static_models;  // one per World::static_models()
};

// Decodes the textures every model's materials use.
SceneGeometry make_scene_geometry(const world::World& world);

// World-space meshes of the whole world in `state` (from world.evaluate). `geometry` must be
// made from the same world.
Result<std::vector<TriangleMesh>> world_meshes(const world::World& world, const world::WorldState& state,
                                               const SceneGeometry& geometry);

// The ground square as two triangles (normal +Y), or nothing when the ground is disabled.
std::vector<TriangleMesh> ground_meshes(const scene::Ground& ground);

}  // namespace proxygi::ref
