// proxygi pose MODEL [--clip NAME|INDEX] [--time SECONDS] [--loop] [--proxies] [-o OUT.obj|OUT.ply]
// Poses every mesh of a model at one time of one clip (CPU skinning, world space) and writes
// the result as OBJ or PLY (chosen by extension, written atomically), or prints a summary.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "anim/gltf_import.h"
#include "anim/posed_character.h"
#include "apps/commands.h"
#include "apps/model_input.h"
#include "proxies/rig_cache.h"
#include "proxies/rig_file.h"
#include "proxies/sphere_mesh.h"
#include "proxies/tracking.h"
#include "base/atomic_file.h"

namespace proxygi::app {
namespace {

struct PoseOptions {
  std::string model;
  std::string clip;
  double time = 0.0;
  bool time_given = false;
  bool loop = false;
  std::string output;
  bool proxies = false;
};

std::string material_name(const anim::Character& character, int material) {
  if (material < 0 || static_cast<std::size_t>(material) >= character.materials.size()) return "default";
  const std::string& name = character.materials[static_cast<std::size_t>(material)].name;
  return name.empty() ? "material_" + std::to_string(material) : name;
}

std::string to_obj(const anim::Character& character, const std::vector<anim::PosedPrimitive>& meshes) {
  std::string out = "# proxygi pose: " + character.source + "\n";
  char line[160];
  std::size_t base = 1;
  for (const anim::PosedPrimitive& mesh : meshes) {
    out += "o " + mesh.name + "\nusemtl " + material_name(character, mesh.material) + "\n";
    for (const glm::vec3& p : mesh.positions) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
      out += line;
    }
    for (const glm::vec3& n : mesh.normals) {
      std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
      out += line;
    }
    const bool normals = !mesh.normals.empty();
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::size_t a = base + mesh.indices[t], b = base + mesh.indices[t + 1], c = base + mesh.indices[t + 2];
      if (normals) {
        std::snprintf(line, sizeof line, "f %zu//%zu %zu//%zu %zu//%zu\n", a, a, b, b, c, c);
      } else {
        std::snprintf(line, sizeof line, "f %zu %zu %zu\n", a, b, c);
      }
      out += line;
    }
    base += mesh.positions.size();
  }
  return out;
}

template <class T>
void put(std::vector<std::uint8_t>& out, T value) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
  out.insert(out.end(), bytes, bytes + sizeof(T));  // PLY binary_little_endian: x86-64/ARM64 order
}

// Binary PLY: float position and normal, uchar color (material base color, sRGB-encoded).
std::vector<std::uint8_t> to_ply(const anim::Character& character, const std::vector<anim::PosedPrimitive>& meshes) {
  std::size_t vertices = 0, faces = 0;
  for (const anim::PosedPrimitive& mesh : meshes) {
    vertices += mesh.positions.size();
    faces += mesh.indices.size() / 3;
  }
  const std::string header = "ply\nformat binary_little_endian 1.0\ncomment proxygi pose: " + character.source +
                             "\nelement vertex " + std::to_string(vertices) +
                             "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
                             "property float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\n"
                             "property uchar blue\nelement face " + std::to_string(faces) +
                             "\nproperty list uchar uint vertex_indices\nend_header\n";
  std::vector<std::uint8_t> out(header.begin(), header.end());
  for (const anim::PosedPrimitive& mesh : meshes) {
    glm::vec4 color(1.0f);
    if (mesh.material >= 0 && static_cast<std::size_t>(mesh.material) < character.materials.size()) {
      color = character.materials[static_cast<std::size_t>(mesh.material)].base_color_factor;
    }
    std::uint8_t rgb[3];
    for (int c = 0; c < 3; ++c) {
      const float linear = std::clamp(color[c], 0.0f, 1.0f);
      const float srgb = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
      rgb[c] = static_cast<std::uint8_t>(std::lround(srgb * 255.0f));
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec3 p = mesh.positions[v];
      const glm::vec3 n = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[v];
      for (const float f : {p.x, p.y, p.z, n.x, n.y, n.z}) put(out, f);
      out.insert(out.end(), rgb, rgb + 3);
    }
  }
  std::uint32_t base = 0;
  for (const anim::PosedPrimitive& mesh : meshes) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      out.push_back(3);
      for (std::size_t k = 0; k < 3; ++k) put(out, base + mesh.indices[t + k]);
    }
    base += static_cast<std::uint32_t>(mesh.positions.size());
  }
  return out;
}

int run_pose(const PoseOptions& options) {
  const std::string extension = options.output.empty() ? "" : std::filesystem::path(options.output).extension().string();
  if (!options.output.empty() && extension != ".obj" && extension != ".ply") {
    return fail_bad_input("pose: output '" + options.output + "' must end in .obj or .ply");
  }
  if (!std::isfinite(options.time)) return fail_bad_input("pose: --time must be a finite number of seconds");
  Result<ModelInput> model = open_model(options.model);
  if (!model) return fail_bad_input(model.message());
  const anim::Character* character = &model->character;

  int clip = -1;  // rest pose
  if (!options.clip.empty()) {
    Result<int> found = anim::find_clip(*character, options.clip);
    if (!found) return fail_bad_input("pose: " + found.message());
    clip = *found;
  } else if (options.time_given && !character->clips.empty()) {
    clip = 0;
  }
  anim::PoseBuffers pose;
  const anim::WrapMode wrap = options.loop ? anim::WrapMode::loop : anim::WrapMode::clamp;
  if (Status status = anim::evaluate_pose(*character, clip, static_cast<float>(options.time), wrap, pose); !status) {
    return fail_bad_input("pose: " + status.message());
  }
  Result<std::vector<anim::PosedPrimitive>> meshes = anim::pose_meshes(*character, pose);
  if (!meshes) return fail_bad_input("pose: " + meshes.message());
  if (options.proxies) {
    // The spheres as one extra mesh "proxies": the cached rig (fitted and cached when missing).
    proxies::RigRequest request;
    request.rig_file = model->rig_file;
    request.model_name = model->file.filename().string();
    request.model_hash = model->hash;
    auto rig = proxies::load_or_fit_rig(*character, request);
    if (!rig) return fail_bad_input("pose: " + rig.message());
    for (const std::string& warning : rig->warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    if (!rig->write_error.empty()) std::fprintf(stderr, "warning: rig not cached: %s\n", rig->write_error.c_str());
    auto tracking = proxies::compile_tracking(rig->rig, *character, rig->rig.binding);
    if (!tracking) return fail_bad_input("pose: " + tracking.message());
    std::vector<proxies::WorldSphere> spheres(tracking->spheres.size());
    if (Status tracked = proxies::TrackProxiesJob{&*tracking, pose.world, spheres}.run(); !tracked)
      return fail_runtime("pose: " + tracked.message());
    proxies::SphereGeometry geometry;
    proxies::append_sphere_geometry(spheres, 16, geometry);
    anim::PosedPrimitive sphere_mesh;
    sphere_mesh.name = "proxies";
    sphere_mesh.positions = std::move(geometry.positions);
    sphere_mesh.normals = std::move(geometry.normals);
    sphere_mesh.indices = std::move(geometry.indices);
    meshes->push_back(std::move(sphere_mesh));
  }

  std::size_t vertices = 0, triangles = 0;
  glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (const anim::PosedPrimitive& mesh : *meshes) {
    vertices += mesh.positions.size();
    triangles += mesh.indices.size() / 3;
    for (const glm::vec3& p : mesh.positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  const std::string clip_text = clip < 0 ? std::string("rest pose")
                                         : "clip " + std::to_string(clip) + " '" +
                                               character->clips[static_cast<std::size_t>(clip)].name + "' at " +
                                               std::to_string(options.time) + " s";
  std::printf("%s: %s: %zu primitives, %zu vertices, %zu triangles, bounds [%.4g %.4g %.4g] .. [%.4g %.4g %.4g]\n",
              character->source.c_str(), clip_text.c_str(), meshes->size(), vertices, triangles, low.x, low.y, low.z,
              high.x, high.y, high.z);
  if (options.output.empty()) return kExitOk;

  const Status written = extension == ".obj" ? write_file_atomically(options.output, to_obj(*character, *meshes))
                                             : write_file_atomically(options.output, to_ply(*character, *meshes));
  if (!written) return fail_runtime("pose: " + written.message());
  std::printf("wrote %s\n", options.output.c_str());
  return kExitOk;
}

}  // namespace

void add_pose_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("pose", "Write every mesh of a model, skinned at one time, as OBJ or PLY");
  auto options = std::make_shared<PoseOptions>();
  command->add_option("model", options->model, "glTF model (.gltf or .glb), or 'mannequin'")->required();
  command->add_option("--clip", options->clip, "Clip name or index (default: rest pose, or clip 0 with --time)");
  command->add_option("--time", options->time, "Clip time in seconds (before 0 / after the end: clamped)")
      ->each([options](const std::string&) { options->time_given = true; });
  command->add_flag("--loop", options->loop, "Wrap --time into the clip instead of clamping");
  command->add_flag("--proxies", options->proxies,
                    "Also write the proxy spheres (the rig cached next to the model, fitted when missing)");
  command->add_option("-o,--output", options->output, "Output mesh: .obj or .ply (default: print a summary only)");
  add_quiet_flag(*command);
  command->callback([&runner, options] { runner = [options] { return run_pose(*options); }; });
}

}  // namespace proxygi::app
