// The scenes of the bounce study (issue 20): where proxies or VSGL should win. Built from the
// default stage; the wall is a box written once as a GLB (no asset file in the repository).
#include <cstdio>

#include "anim/gltf_writer.h"
#include "study/chart_scenes.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"

namespace proxygi::study {
namespace {

// A unit cube centred at the origin, flat-shaded (4 vertices per face, outward normals).
anim::Character unit_box() {
  anim::Character box;
  box.source = "chart box";
  anim::Primitive primitive;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      const glm::vec3 n = sign * axes[axis];
      const glm::vec3 u = sign * axes[(axis + 1) % 3], v = axes[(axis + 2) % 3];  // u x v = n
      const auto base = std::uint32_t(primitive.positions.size());
      for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        primitive.positions.push_back(0.5f * (n + corner.x * u + corner.y * v));
        primitive.normals.push_back(n);
      }
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) primitive.indices.push_back(base + i);
    }
  primitive.material = 0;
  anim::Material material;
  material.name = "wall";
  box.materials.push_back(material);
  anim::Mesh mesh;
  mesh.name = "box";
  mesh.primitives.push_back(std::move(primitive));
  box.meshes.push_back(std::move(mesh));
  anim::Node node;
  node.name = "box";
  node.mesh = 0;
  box.nodes.push_back(node);
  box.roots = {0};
  box.evaluation_order = {0};
  return box;
}

// The mannequin of the default scene walking in place at x, facing +Z (no walk path).
scene::Character standing_mannequin(float x, float time_offset_s) {
  scene::Character character = scene::default_scene().characters.front();
  character.path.reset();
  character.transform.translation = glm::vec3(x, 0.0f, 0.0f);
  character.time_offset_s = time_offset_s;
  return character;
}

ChartScene stage(const std::string& name, const std::string& description, glm::vec3 eye, glm::vec3 target) {
  ChartScene chart{name, scene::default_scene(), {}};
  chart.scene.description = "Chart scene: " + description;
  scene::FixedCamera camera;
  camera.position = eye;
  camera.target = target;
  camera.fov_degrees = 50.0f;
  chart.scene.camera.kind = camera;
  return chart;
}

std::string metres(float d) {
  char text[16];
  std::snprintf(text, sizeof text, "%g", double(d));
  return text;
}

}  // namespace

const std::vector<float>& wall_distances_m() {
  static const std::vector<float> distances = {0.5f, 1.0f, 2.0f, 4.0f};
  return distances;
}
const std::vector<float>& pair_distances_m() {
  static const std::vector<float> distances = {0.5f, 1.0f, 2.0f, 5.0f};
  return distances;
}

Result<std::vector<ChartScene>> bounce_study_scenes(const ChartSceneOptions& options,
                                                    const std::function<bool(const std::string&)>& named) {
  std::vector<ChartScene> scenes;
  if (named("contact")) {
    ChartScene contact = stage("contact", "one mannequin walking in place, the camera low on its feet and their contact shadow.",
                               {1.1f, 0.9f, 2.2f}, {0.0f, 0.35f, 0.0f});
    contact.scene.characters = {standing_mannequin(0.0f, 0.0f)};
    scenes.push_back(std::move(contact));
  }
  bool box_written = false;
  const std::filesystem::path box_file =
      (options.prop_dir.empty() ? options.rig_cache_dir : options.prop_dir) / "chart-wall-box.glb";
  for (float d : wall_distances_m()) {
    const std::string name = "wall-" + metres(d);
    if (!named(name)) continue;
    if (!box_written) {
      std::error_code error;
      std::filesystem::create_directories(box_file.parent_path(), error);
      if (error) return make_error(box_file.parent_path().string() + ": cannot create: " + error.message());
      if (Status written = anim::write_glb(unit_box(), box_file); !written) return written.error();
      box_written = true;
    }
    // The wall stands left of the mannequin, its face on x = -d (the sun, from +X and behind,
    // lights that face and casts no wall shadow on the mannequin).
    ChartScene wall = stage(name, "one mannequin walking in place " + metres(d) + " m from a wall on its left.",
                            {1.6f, 1.5f, 3.0f + 0.6f * d}, {-0.5f * d, 0.85f, 0.0f});
    wall.scene.characters = {standing_mannequin(0.0f, 0.0f)};
    scene::StaticMesh mesh;
    mesh.model = box_file.string();
    mesh.transform.scale = glm::vec3(0.2f, 2.5f, 8.0f);
    mesh.transform.translation = glm::vec3(-d - 0.1f, 1.25f, 0.0f);
    mesh.albedo = glm::vec3(0.8f);
    wall.scene.static_meshes = {mesh};
    scenes.push_back(std::move(wall));
  }
  for (float d : pair_distances_m()) {
    const std::string name = "pair-" + metres(d);
    if (!named(name)) continue;
    ChartScene pair = stage(name, "two mannequins walking in place side by side, " + metres(d) + " m between their axes.",
                            {0.0f, 1.5f, 3.4f + 0.9f * d}, {0.0f, 0.85f, 0.0f});
    pair.scene.characters = {standing_mannequin(-0.5f * d, 0.0f), standing_mannequin(0.5f * d, 0.4f)};
    scenes.push_back(std::move(pair));
  }
  if (named("wall-corner")) {  // the project's PRT scene (assets/scenes/wall_corner.json)
    auto corner = scene::load_scene(options.assets_dir / "scenes" / "wall_corner.json");
    if (!corner) return corner.error();
    ChartScene chart{"wall-corner", std::move(*corner), {}};
    scenes.push_back(std::move(chart));
  }
  if (named("crowd")) {
    ChartScene crowd{"crowd", scene::crowd_scene(), {}};
    crowd.scene.description = "Chart scene: the built-in crowd (20 mannequins), its orbiting camera.";
    scenes.push_back(std::move(crowd));
  }
  return scenes;
}

std::vector<std::string> expand_scene_groups(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& name : names) {
    if (name == "wall")
      for (float d : wall_distances_m()) out.push_back("wall-" + metres(d));
    else if (name == "pair-distance")
      for (float d : pair_distances_m()) out.push_back("pair-" + metres(d));
    else
      out.push_back(name);
  }
  return out;
}

std::vector<std::string> chart_scene_names() {
  std::vector<std::string> names = {"default", "CesiumMan", "Fox", "RiggedSimple", "pair", "contact", "wall", "pair-distance", "crowd",
                                    "wall-corner"};
  for (float d : wall_distances_m()) names.push_back("wall-" + metres(d));
  for (float d : pair_distances_m()) names.push_back("pair-" + metres(d));
  return names;
}

}  // namespace proxygi::study
