// proxygi info MODEL [--json] [--validate] [--quiet]: what the importer sees in a glTF file (counts
// per object kind, per mesh, per skin, per material and per clip). Bad or unsupported input exits
// with code 2. --validate lists every problem found (anim/gltf_validate.h), glTF-Validator style,
// on stderr ("error: FILE/accessors/3/max: ...") and under "validation" in --json; exit 2 when
// any is an error, 0 with warnings only.
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "anim/gltf_import.h"
#include "anim/gltf_validate.h"
#include "anim/posed_character.h"
#include "apps/model_input.h"
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

// Rest-pose bounds (world space of the model, meters) of every primitive, or nullopt without geometry.
std::optional<std::pair<glm::vec3, glm::vec3>> rest_bounds(const anim::Character& character) {
  anim::PoseBuffers pose;
  if (!anim::evaluate_pose(character, -1, 0.0f, anim::WrapMode::clamp, pose)) return std::nullopt;
  auto primitives = anim::pose_meshes(character, pose);
  if (!primitives) return std::nullopt;
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const auto& primitive : *primitives)
    for (const glm::vec3& p : primitive.positions) low = glm::min(low, p), high = glm::max(high, p);
  if (!(low.x <= high.x)) return std::nullopt;
  return std::make_pair(low, high);
}

struct InfoArgs {
  std::string model;
  bool json = false;
  bool validate = false;
};

nlohmann::json to_json(const anim::ValidationReport& report) {
  nlohmann::json issues = nlohmann::json::array();
  for (const anim::ValidationIssue& issue : report.issues)
    issues.push_back({{"severity", anim::severity_name(issue.severity)}, {"pointer", issue.pointer}, {"message", issue.message}});
  return {{"errors", report.errors()}, {"warnings", report.warnings()}, {"issues", issues}};
}

// --validate: every issue on stderr, then the count; exit 2 with any error.
int finish_validation(const anim::ValidationReport& report, const std::string& model) {
  for (const anim::ValidationIssue& issue : report.issues)
    std::fprintf(stderr, "%s: %s%s: %s\n", anim::severity_name(issue.severity), report.source.c_str(), issue.pointer.c_str(),
                 issue.message.c_str());
  if (report.errors() > 0) {
    std::fprintf(stderr, "proxygi: %s: %zu error%s, %zu warning%s\n", model.c_str(), report.errors(), report.errors() > 1 ? "s" : "",
                 report.warnings(), report.warnings() == 1 ? "" : "s");
    return kExitBadInput;
  }
  return kExitOk;
}

int run_info(const InfoArgs& args) {
  std::optional<anim::ValidationReport> report;
  if (args.validate) {
    std::error_code missing;
    const std::filesystem::path file = names_the_mannequin(args.model) ? assets_dir() / "mannequin.glb" : std::filesystem::path(args.model);
    if (!names_the_mannequin(args.model) || std::filesystem::exists(file, missing)) report = anim::validate_gltf(file);
    else report = anim::ValidationReport{args.model, {}};  // the mannequin built in code: no file to check
  }
  auto model = open_model(args.model);
  if (!model) {
    if (!report) return fail_bad_input(model.message());
    if (report->errors() == 0) report->issues.push_back({anim::ValidationIssue::Severity::error, "", model.message()});
    if (args.json) std::printf("%s\n", nlohmann::json{{"source", args.model}, {"validation", to_json(*report)}}.dump(2).c_str());
    return finish_validation(*report, args.model);
  }
  const anim::Character& character = model->character;
  nlohmann::json info = to_json(character);
  // --validate names unnamed and duplicate nodes itself, one issue per node.
  std::vector<std::string> warnings = report ? std::vector<std::string>{} : proxies::node_name_warnings(character);
  // Where the model stands: rest-pose bounds, height, and which way is up.
  if (auto bounds = rest_bounds(character)) {
    const glm::vec3 extent = bounds->second - bounds->first;
    info["bounds_m"] = {{"min", {bounds->first.x, bounds->first.y, bounds->first.z}},
                        {"max", {bounds->second.x, bounds->second.y, bounds->second.z}}};
    info["height_m"] = extent.y;
    info["up_axis"] = "+Y";
    if (extent.z > 1.5f * extent.y && extent.z >= extent.x)
      warnings.push_back(character.source + ": the model is " + std::to_string(extent.z) + " m along Z but " + std::to_string(extent.y) +
                         " m tall (glTF is +Y up): it may have been exported Z-up and will lie on the ground");
    if (extent.y > 50.0f || extent.y < 0.05f)
      warnings.push_back(character.source + ": the model is " + std::to_string(extent.y) +
                         " m tall (glTF is in meters): check the exporter's unit scale");
  } else {
    warnings.push_back(character.source + ": no geometry in the rest pose");
  }
  nlohmann::json node_names = nlohmann::json::array(), joint_names = nlohmann::json::array();
  for (const anim::Node& node : character.nodes) node_names.push_back(node.name);
  std::set<int> joints;
  for (const anim::Skin& skin : character.skins) joints.insert(skin.joints.begin(), skin.joints.end());
  for (int joint : joints) joint_names.push_back(character.nodes[std::size_t(joint)].name);
  info["node_names"] = node_names;
  info["joint_names"] = joint_names;

  // Proxy statistics when a rig is cached next to the model (proxies/rig_file.h); a broken cache
  // is reported (it would be refitted when rendering), not fatal.
  std::optional<proxies::ProxyRig> rig;
  std::error_code missing;
  if (std::filesystem::exists(model->rig_file, missing)) {
    auto read = proxies::read_rig(model->rig_file, character);
    if (!read) {
      warnings.push_back("cached rig " + read.message() + " (it is refitted when rendering; `proxygi fit --force` replaces it)");
    } else {
      rig = std::move(*read);
      const proxies::RigSummary summary = proxies::summarize_rig(*rig);
      info["proxies"] = {{"rig", model->rig_file.string()},  {"spheres", summary.sphere_count},
                         {"bones", summary.bone_count},        {"min_radius_m", summary.min_radius},
                         {"max_radius_m", summary.max_radius}, {"total_volume_m3", summary.total_volume},
                         {"binding", proxies::binding_name(rig->binding)}};
      if (!rig->model_hash.empty() && rig->model_hash != model->hash)
        warnings.push_back(model->rig_file.string() + " was fitted to other model bytes; it is refitted when rendering");
    }
  }
  info["warnings"] = warnings;
  if (!args.json) {
    print_table(info);
    if (info.contains("bounds_m")) {
      const auto& lo = info["bounds_m"]["min"];
      const auto& hi = info["bounds_m"]["max"];
      std::printf("\n  rest-pose bounds [%.3g, %.3g, %.3g] .. [%.3g, %.3g, %.3g] m, height %.3g m, up %s\n",
                  lo[0].get<double>(), lo[1].get<double>(), lo[2].get<double>(), hi[0].get<double>(), hi[1].get<double>(),
                  hi[2].get<double>(), info["height_m"].get<double>(), info["up_axis"].get<std::string>().c_str());
    }
    std::string names;
    for (const auto& name : joint_names) names += " " + quoted_name(name.get<std::string>());
    if (!joint_names.empty()) std::printf("  joints:%s\n", names.c_str());
    if (rig) std::printf("\n%s\n", proxies::format_rig_summary(*rig).c_str());
  }
  if (report) {
    for (const std::string& warning : warnings) report->issues.push_back({anim::ValidationIssue::Severity::warning, "", warning});
    info["validation"] = to_json(*report);
  }
  if (args.json) std::printf("%s\n", info.dump(2).c_str());
  if (report) return finish_validation(*report, args.model);
  for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("info", "Describe a glTF model: nodes, joints, skins, meshes, materials, clips, bounds");
  auto args = std::make_shared<InfoArgs>();
  command->add_option("model", args->model, "glTF (.gltf) or binary glTF (.glb) file, or 'mannequin'")->required();
  command->add_flag("--json", args->json, "Print one JSON object instead of tables");
  command->add_flag("--validate", args->validate,
                    "List every problem found (glTF-Validator style: severity, JSON pointer, message); exit 2 when any is an error");
  add_quiet_flag(*command);
  command->callback([&runner, args] { runner = [args] { return run_info(*args); }; });
}

}  // namespace proxygi::app
