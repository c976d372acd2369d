// proxygi info MODEL [--json]: what the importer sees in a glTF file (counts per object kind,
// per mesh, per skin, per material and per clip). Bad or unsupported input exits with code 2.
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

#include "anim/gltf_import.h"
#include "apps/commands.h"
#include "proxies/proxy_rig.h"
#include "proxies/rig_file.h"

namespace proxygi::app {
namespace {

struct MeshCounts {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t morph_targets = 0;
  int influences = 0;  // most influences per vertex over the mesh's primitives
};

MeshCounts count_mesh(const anim::Mesh& mesh) {
  MeshCounts counts;
  for (const auto& primitive : mesh.primitives) {
    counts.vertices += primitive.positions.size();
    counts.triangles += primitive.indices.size() / 3;
    counts.morph_targets = std::max(counts.morph_targets, primitive.morph_targets.size());
    counts.influences = std::max(counts.influences, primitive.influences_per_vertex);
  }
  return counts;
}

std::size_t distinct_joints(const anim::Character& character) {
  std::set<int> joints;
  for (const auto& skin : character.skins) joints.insert(skin.joints.begin(), skin.joints.end());
  return joints.size();
}

nlohmann::json to_json(const anim::Character& character) {
  nlohmann::json out;
  out["source"] = character.source;
  out["nodes"] = character.nodes.size();
  out["roots"] = character.roots.size();
  out["joints"] = distinct_joints(character);
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  out["meshes"] = nlohmann::json::array();
  for (const auto& mesh : character.meshes) {
    const MeshCounts counts = count_mesh(mesh);
    vertices += counts.vertices;
    triangles += counts.triangles;
    out["meshes"].push_back({{"name", mesh.name}, {"primitives", mesh.primitives.size()},
                             {"vertices", counts.vertices}, {"triangles", counts.triangles},
                             {"morph_targets", counts.morph_targets},
                             {"influences_per_vertex", counts.influences}});
  }
  out["vertices"] = vertices;
  out["triangles"] = triangles;
  out["skins"] = nlohmann::json::array();
  for (const auto& skin : character.skins) {
    out["skins"].push_back({{"name", skin.name}, {"joints", skin.joints.size()}, {"skeleton", skin.skeleton}});
  }
  out["materials"] = nlohmann::json::array();
  for (const auto& material : character.materials) {
    const auto& f = material.base_color_factor;
    out["materials"].push_back({{"name", material.name},
                                {"base_color_factor", {f.r, f.g, f.b, f.a}},
                                {"base_color_image", material.base_color_image},
                                {"double_sided", material.double_sided}});
  }
  out["images"] = nlohmann::json::array();
  for (const auto& image : character.images) {
    out["images"].push_back({{"name", image.name}, {"width", image.width}, {"height", image.height}});
  }
  out["clips"] = nlohmann::json::array();
  for (const auto& clip : character.clips) {
    out["clips"].push_back({{"name", clip.name}, {"duration", clip.duration}, {"channels", clip.channels.size()}});
  }
  return out;
}

std::string quoted_name(const std::string& name) { return name.empty() ? "-" : "\"" + name + "\""; }

void print_table(const nlohmann::json& info) {
  std::printf("%s\n", info["source"].get<std::string>().c_str());
  std::printf("  nodes %zu (roots %zu), joints %zu, skins %zu, meshes %zu, materials %zu, images %zu, clips %zu\n",
              info["nodes"].get<std::size_t>(), info["roots"].get<std::size_t>(),
              info["joints"].get<std::size_t>(), info["skins"].size(), info["meshes"].size(),
              info["materials"].size(), info["images"].size(), info["clips"].size());
  std::printf("  vertices %zu, triangles %zu\n", info["vertices"].get<std::size_t>(),
              info["triangles"].get<std::size_t>());
  std::size_t index = 0;
  if (!info["meshes"].empty()) std::printf("\n  %-5s %-24s %10s %10s %10s %7s %10s\n", "mesh", "name", "primitives", "vertices", "triangles", "morphs", "influences");
  for (const auto& mesh : info["meshes"]) {
    std::printf("  %-5zu %-24s %10zu %10zu %10zu %7zu %10d\n", index++, quoted_name(mesh["name"]).c_str(),
                mesh["primitives"].get<std::size_t>(), mesh["vertices"].get<std::size_t>(),
                mesh["triangles"].get<std::size_t>(), mesh["morph_targets"].get<std::size_t>(),
                mesh["influences_per_vertex"].get<int>());
  }
  index = 0;
  if (!info["skins"].empty()) std::printf("\n  %-5s %-24s %10s %10s\n", "skin", "name", "joints", "skeleton");
  for (const auto& skin : info["skins"]) {
    std::printf("  %-5zu %-24s %10zu %10d\n", index++, quoted_name(skin["name"]).c_str(),
                skin["joints"].get<std::size_t>(), skin["skeleton"].get<int>());
  }
  index = 0;
  if (!info["materials"].empty()) std::printf("\n  %-5s %-24s %-30s %7s\n", "mat", "name", "base color factor", "image");
  for (const auto& material : info["materials"]) {
    const auto& f = material["base_color_factor"];
    char factor[64];
    std::snprintf(factor, sizeof factor, "%.3g %.3g %.3g %.3g", f[0].get<double>(), f[1].get<double>(),
                  f[2].get<double>(), f[3].get<double>());
    std::printf("  %-5zu %-24s %-30s %7d\n", index++, quoted_name(material["name"]).c_str(), factor,
                material["base_color_image"].get<int>());
  }
  index = 0;
  if (!info["clips"].empty()) std::printf("\n  %-5s %-24s %10s %10s\n", "clip", "name", "duration s", "channels");
  for (const auto& clip : info["clips"]) {
    std::printf("  %-5zu %-24s %10.4f %10zu\n", index++, quoted_name(clip["name"]).c_str(),
                clip["duration"].get<double>(), clip["channels"].get<std::size_t>());
  }
}

}  // namespace

void add_info_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("info", "Describe a glTF model: nodes, joints, skins, meshes, materials, clips");
  static std::string model;
  static bool json = false;
  command->add_option("model", model, "glTF (.gltf) or binary glTF (.glb) file")->required();
  command->add_flag("--json", json, "Print one JSON object instead of tables");
  command->callback([&runner] {
    runner = [] {
      auto character = anim::import_gltf(model);
      if (!character) return fail_bad_input(character.message());
      nlohmann::json info = to_json(*character);
      // Proxy statistics when a rig is cached next to the model (proxies/rig_file.h).
      const std::filesystem::path rig_path = proxies::default_rig_path(model);
      std::optional<proxies::ProxyRig> rig;
      if (std::filesystem::exists(rig_path)) {
        auto read = proxies::read_rig(rig_path, *character);
        if (!read) return fail_bad_input(read.message());
        rig = std::move(*read);
        const proxies::RigSummary summary = proxies::summarize_rig(*rig);
        info["proxies"] = {{"rig", rig_path.string()},          {"spheres", summary.sphere_count},
                           {"bones", summary.bone_count},         {"min_radius_m", summary.min_radius},
                           {"max_radius_m", summary.max_radius},  {"total_volume_m3", summary.total_volume},
                           {"binding", proxies::binding_name(rig->binding)}};
      }
      if (json) {
        std::printf("%s\n", info.dump(2).c_str());
      } else {
        print_table(info);
        if (rig) std::printf("\n%s\n", proxies::format_rig_summary(*rig).c_str());
      }
      return kExitOk;
    };
  });
}

}  // namespace proxygi::app
