#include "gpu/scene_renderer.h"

#include <cstring>
#include <functional>
#include <map>

#include "anim/gltf_import.h"
#include "anim/posed_character.h"
#include "anim/skinning.h"
#include "base/log.h"
#include "gpu/scene_frame_settings.h"
#include "gpu/transfer.h"
#include "proxies/rig_cache.h"
#include "proxies/rig_file.h"
#include "render/environment_lighting.h"
#include "render/ground_grid.h"
#include "scene/camera.h"
#include "scene/character_motion.h"

namespace proxygi::gpu {

// A model shared by every instance that uses it.
struct SceneRenderer::Model {
  std::filesystem::path file;
  anim::Character character;
  proxies::TrackingRig tracking;
  MaterialTextures textures;
};

// One mesh node of one instance: its primitives skinned by the node's skin, or (no skin) by a
// one-joint palette holding the node's world matrix.
struct MeshDraw {
  int node = -1;
  int skin = -1;
  std::vector<SkinnedPrimitive> primitives;
  std::vector<Buffer> indices;
  std::vector<std::uint32_t> index_counts;
  std::vector<Buffer> uvs;  // static TEXCOORD_0 per primitive; no handle when absent
  std::vector<MaterialBinding> materials;
  std::vector<Buffer> palettes;         // skin matrices, one buffer per ring slot, host-visible
  std::vector<Buffer> normal_palettes;  // their inverse-transposes (anim::normal_matrix layout)
  std::size_t morph_offset = 0;         // the node's slice of PoseBuffers::morph_weights
  std::vector<Buffer> morph_weights;    // that slice, one buffer per ring slot; empty: no morphs
};

struct SceneRenderer::Instance {
  const Model* model = nullptr;
  std::size_t scene_character = 0;
  int clip = -1;
  anim::PoseBuffers pose;
  std::vector<proxies::WorldSphere> spheres;
  std::vector<MeshDraw> meshes;
};

namespace {

Result<anim::Character> load_model(const std::filesystem::path& file) {
  auto character = anim::import_gltf(file);
  if (!character) return character.error();
  return std::move(*character);
}

// The cached rig when it belongs to this model file, else a fresh fit (proxies/rig_cache.h).
Result<proxies::ProxyRig> obtain_rig(const std::filesystem::path& model_file, const std::filesystem::path& rig_file,
                                     const anim::Character& character, bool write_cache) {
  auto hash = proxies::hash_file(model_file);
  if (!hash) return hash.error();
  proxies::RigRequest request;
  request.rig_file = rig_file;
  request.model_name = model_file.filename().string();
  request.model_hash = *hash;
  request.write_cache = write_cache;
  auto obtained = proxies::load_or_fit_rig(character, request);
  if (!obtained) return make_error(rig_file.string() + ": " + obtained.message());
  if (!obtained->cache_hit)
    log_info("proxies: fitted " + std::to_string(obtained->rig.spheres.size()) + " spheres to " + model_file.string());
  return std::move(obtained->rig);
}

Result<int> resolve_clip(const anim::Character& character, const scene::ClipRef& clip) {
  if (character.clips.empty()) return -1;  // rest pose
  if (const auto* index = std::get_if<int>(&clip)) {
    if (*index < 0 || std::size_t(*index) >= character.clips.size())
      return make_error(character.source + ": clip index " + std::to_string(*index) + " out of range (" +
                        std::to_string(character.clips.size()) + " clips)");
    return *index;
  }
  return anim::find_clip(character, std::get<std::string>(clip));
}

}  // namespace

SceneRenderer::SceneRenderer(Context& context) : context_(context) {}

SceneRenderer::~SceneRenderer() {
  for (auto& slot : in_flight_) (void)slot.wait();
}

std::size_t SceneRenderer::proxy_count() const {
  std::size_t count = 0;
  for (const auto& instance : instances_) count += instance->spheres.size();
  return count;
}

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(Context& context, const scene::Scene& scene,
                                                             const SceneRendererOptions& options) {
  std::unique_ptr<SceneRenderer> renderer(new SceneRenderer(context));
  renderer->scene_ = scene;
  FrameSettings settings = scene_frame_settings(scene);
  if (settings.splat == SplatMethod::raster && settings.method != ShadingMethod::image_space)
    log_warning("render.splat: 'raster' splats onto image-space receivers only; this method does not use it");
  const std::uint32_t slots = std::max(settings.frames_in_flight, 1u);

  auto skin_pass = SkinPass::create(context);
  if (!skin_pass) return skin_pass.error();
  renderer->skin_pass_ = std::make_unique<SkinPass>(std::move(*skin_pass));

  std::map<std::filesystem::path, Model*> by_file;
  for (std::size_t index = 0; index < scene.characters.size(); ++index) {
    const scene::Character& entry = scene.characters[index];
    const std::filesystem::path file = scene::resolve_model_path(scene, entry.model, options.assets_dir);
    Model* model = nullptr;
    if (auto found = by_file.find(file); found != by_file.end()) {
      model = found->second;
    } else {
      auto loaded = load_model(file);
      if (!loaded) return make_error("characters[" + std::to_string(index) + "]: " + loaded.message());
      auto owned = std::make_unique<Model>();
      owned->file = file;
      owned->character = std::move(*loaded);
      const auto rig_file = scene::resolve_proxy_path(scene, entry, options.assets_dir);
      auto rig = obtain_rig(file, rig_file, owned->character, options.write_rig_cache);
      if (!rig) return make_error("characters[" + std::to_string(index) + "]: " + rig.message());
      auto tracking = proxies::compile_tracking(*rig, owned->character, rig->binding);
      if (!tracking) return make_error(rig_file.string() + ": " + tracking.message());
      owned->tracking = std::move(*tracking);
      auto textures = MaterialTextures::create(context, owned->character);
      if (!textures) return make_error("characters[" + std::to_string(index) + "]: " + textures.message());
      owned->textures = std::move(*textures);
      model = owned.get();
      by_file[file] = model;
      renderer->models_.push_back(std::move(owned));
    }

    auto instance = std::make_unique<Instance>();
    instance->model = model;
    instance->scene_character = index;
    auto clip = resolve_clip(model->character, entry.clip);
    if (!clip) return make_error("characters[" + std::to_string(index) + "].clip: " + clip.message());
    instance->clip = *clip;
    instance->spheres.resize(model->tracking.spheres.size());
    const anim::Character& character = model->character;
    for (std::size_t node = 0; node < character.nodes.size(); ++node) {
      const anim::Node& n = character.nodes[node];
      if (n.mesh < 0) continue;
      MeshDraw draw;
      draw.node = int(node);
      draw.skin = n.skin;
      const std::size_t palette_size = n.skin >= 0 ? character.skins[std::size_t(n.skin)].joints.size() : 1;
      for (const anim::Primitive& source : character.meshes[std::size_t(n.mesh)].primitives) {
        anim::Primitive primitive = source;
        if (n.skin < 0 || primitive.influences_per_vertex < 1) {  // rigid: one joint, the node itself
          primitive.influences_per_vertex = 1;
          primitive.joints.assign(primitive.positions.size(), 0);
          primitive.weights.assign(primitive.positions.size(), 1.0f);
        }
        auto uploaded = SkinPass::upload(context, primitive);
        if (!uploaded) return uploaded.error();
        auto indices = create_buffer_with_data(context, as_bytes(std::span<const std::uint32_t>(primitive.indices)),
                                               VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        if (!indices) return indices.error();
        draw.primitives.push_back(std::move(*uploaded));
        draw.indices.push_back(std::move(*indices));
        draw.index_counts.push_back(std::uint32_t(primitive.indices.size()));
        draw.uvs.emplace_back();
        if (!primitive.uvs.empty()) {
          auto uvs = create_buffer_with_data(context, as_bytes(std::span<const glm::vec2>(primitive.uvs)),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
          if (!uvs) return uvs.error();
          draw.uvs.back() = std::move(*uvs);
        }
        draw.materials.push_back(model->textures.binding(primitive.material));
      }
      for (std::uint32_t slot = 0; slot < slots; ++slot)
        for (auto* palettes : {&draw.palettes, &draw.normal_palettes}) {
          auto palette = Buffer::create(context, palette_size * sizeof(glm::mat4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        MemoryKind::host_visible);
          if (!palette) return palette.error();
          palettes->push_back(std::move(*palette));
        }
      draw.morph_offset = std::size_t(anim::morph_weight_offset(character, int(node)));
      if (const int targets = anim::morph_target_count(character, int(node)); targets > 0)
        for (std::uint32_t slot = 0; slot < slots; ++slot) {
          auto weights = Buffer::create(context, std::size_t(targets) * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        MemoryKind::host_visible);
          if (!weights) return weights.error();
          draw.morph_weights.push_back(std::move(*weights));
        }
      instance->meshes.push_back(std::move(draw));
    }
    renderer->instances_.push_back(std::move(instance));
  }

  if (scene.ground.enabled && settings.method == ShadingMethod::vertex) {
    // Vertex receivers need ground vertices where the characters are (render/ground_grid.h).
    const render::GroundRegion region = render::ground_fine_region(scene);
    const render::GroundGrid grid =
        render::make_ground_grid(scene.ground.size, region.min, region.max, region.vertices_per_metre);
    log_info("vertex method: ground grid of " + std::to_string(grid.positions.size()) + " vertices (" +
             std::to_string(region.vertices_per_metre) + " per metre near the characters)");
    auto ground = upload_static_mesh(context, grid.positions, grid.normals, grid.indices,
                                     glm::vec4(scene.ground.albedo, 1.0f));
    if (!ground) return ground.error();
    renderer->static_meshes_.push_back(std::move(*ground));
  } else if (scene.ground.enabled) {
    const float half = 0.5f * scene.ground.size;
    const glm::vec3 corners[] = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
    const glm::vec3 up[] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const std::uint32_t quad[] = {0, 2, 1, 0, 3, 2};
    auto ground = upload_static_mesh(context, corners, up, quad, glm::vec4(scene.ground.albedo, 1.0f));
    if (!ground) return ground.error();
    renderer->static_meshes_.push_back(std::move(*ground));
  }
  for (std::size_t index = 0; index < scene.static_meshes.size(); ++index) {
    const scene::StaticMesh& entry = scene.static_meshes[index];
    auto loaded = load_model(scene::resolve_scene_path(scene, entry.model));
    if (!loaded) return make_error("static_meshes[" + std::to_string(index) + "]: " + loaded.message());
    anim::PoseBuffers pose;
    if (Status posed = anim::evaluate_pose(*loaded, -1, 0.0f, anim::WrapMode::clamp, pose, entry.transform.to_matrix()); !posed)
      return posed.error();
    auto primitives = anim::pose_meshes(*loaded, pose);
    if (!primitives) return primitives.error();
    auto textures = MaterialTextures::create(context, *loaded);
    if (!textures) return make_error("static_meshes[" + std::to_string(index) + "]: " + textures.message());
    renderer->static_textures_.push_back(std::make_unique<MaterialTextures>(std::move(*textures)));
    for (const auto& primitive : *primitives) {
      if (primitive.normals.size() != primitive.positions.size()) continue;
      // The albedo override replaces the whole base color, texture included (as in the reference).
      const MaterialBinding material = entry.albedo ? MaterialBinding{glm::vec4(*entry.albedo, 1.0f), {}}
                                                    : renderer->static_textures_.back()->binding(primitive.material);
      auto mesh = upload_static_mesh(context, primitive.positions, primitive.normals, primitive.indices,
                                     material.base_color, primitive.uvs, material.texture);
      if (!mesh) return mesh.error();
      renderer->static_meshes_.push_back(std::move(*mesh));
    }
  }

  if (settings.method == ShadingMethod::vertex) {
    // Every vertex of every draw is a receiver, each draw starting a group (frame_settings.h).
    std::uint64_t receivers = 0;
    for (const auto& instance : renderer->instances_)
      for (const auto& mesh : instance->meshes)
        for (const auto& primitive : mesh.primitives) receivers += round_up_to_receiver_group(primitive.vertex_count);
    for (const auto& mesh : renderer->static_meshes_)
      receivers += round_up_to_receiver_group(mesh.draw().vertex_count());
    // Receivers × n² floats of log occlusion must fit one storage buffer binding.
    const std::uint64_t order = std::uint64_t(scene.render.sh_order);
    const std::uint64_t limit = context.report().max_storage_buffer_range / (sizeof(float) * order * order);
    if (receivers > limit)
      return make_error("render.method vertex: " + std::to_string(receivers) + " vertex receivers, at most " +
                        std::to_string(limit) + " fit this device's storage buffers at order " +
                        std::to_string(scene.render.sh_order));
    settings.vertex_receivers = std::uint32_t(receivers);
  }
  auto lighting = render::make_environment_lighting(scene, scene.render.sh_order);
  if (!lighting) return lighting.error();
  const render::FrameTables tables = render::make_frame_tables(lighting->lighting, scene_table_settings(scene.render));
  auto frame = SoftGiFrame::create(context, settings, tables, lighting->background);
  if (!frame) return frame.error();
  renderer->frame_ = std::move(*frame);

  for (std::uint32_t slot = 0; slot < slots; ++slot) {
    auto in_flight = context.create_in_flight();
    if (!in_flight) return in_flight.error();
    renderer->in_flight_.push_back(std::move(*in_flight));
  }
  renderer->slot_frame_.assign(slots, -1);
  renderer->slot_spheres_.assign(slots, {});
  renderer->slot_statistics_.assign(slots, {});
  return renderer;
}

Result<std::vector<DrawItem>> SceneRenderer::prepare_frame(int frame, std::uint32_t slot) {
  const auto start = std::chrono::steady_clock::now();
  const double t = scene::frame_time_s(scene_.output, frame);
  spheres_.clear();
  std::vector<DrawItem> draws;
  for (auto& instance : instances_) {
    const scene::Character& entry = scene_.characters[instance->scene_character];
    const anim::Character& character = instance->model->character;
    const float clip_time = float(scene::clip_time_s(entry, t));
    if (Status posed = anim::evaluate_pose(character, instance->clip, clip_time, anim::WrapMode::loop, instance->pose,
                                           scene::character_world_matrix(entry, t));
        !posed)
      return posed.error();
    for (auto& mesh : instance->meshes) {
      // Normals go through the inverse-transposes, as pose_meshes does (exact under any scale).
      const glm::mat4& node_world = instance->pose.world[std::size_t(mesh.node)];
      const std::vector<glm::mat4> rigid = {node_world}, rigid_normals = {anim::normal_matrix(node_world)};
      const bool skinned = mesh.skin >= 0;
      const auto& palette = skinned ? instance->pose.skin_matrices[std::size_t(mesh.skin)] : rigid;
      const auto& normals = skinned ? instance->pose.normal_matrices[std::size_t(mesh.skin)] : rigid_normals;
      std::memcpy(mesh.palettes[slot].mapped(), palette.data(), palette.size() * sizeof(glm::mat4));
      std::memcpy(mesh.normal_palettes[slot].mapped(), normals.data(), normals.size() * sizeof(glm::mat4));
      if (!mesh.morph_weights.empty())
        std::memcpy(mesh.morph_weights[slot].mapped(), instance->pose.morph_weights.data() + mesh.morph_offset,
                    std::size_t(mesh.morph_weights[slot].size()));
      for (std::size_t i = 0; i < mesh.primitives.size(); ++i)
        draws.push_back({&mesh.primitives[i].world_positions, &mesh.primitives[i].world_normals, &mesh.indices[i],
                         mesh.index_counts[i], mesh.materials[i].base_color,
                         mesh.uvs[i].handle() != VK_NULL_HANDLE ? &mesh.uvs[i] : nullptr, mesh.materials[i].texture});
    }
    proxies::TrackProxiesJob track{&instance->model->tracking, instance->pose.world, instance->spheres};
    if (Status tracked = track.run(); !tracked) return tracked.error();
    for (const auto& sphere : instance->spheres) spheres_.push_back({sphere.center, sphere.radius, sphere.albedo});
  }
  for (const auto& mesh : static_meshes_) draws.push_back(mesh.draw());

  const scene::CameraState camera = scene::evaluate_scene_camera(scene_, t);
  const float aspect = float(scene_.output.width) / float(scene_.output.height);
  FrameView view;
  view.view = scene::view_matrix(camera);
  view.projection = scene::projection_matrix(camera, aspect);
  view.eye = camera.eye;
  view.forward = glm::normalize(camera.target - camera.eye);
  if (Status written = frame_->write_slot(slot, view, spheres_); !written) return written.error();

  slot_statistics_[slot] = {};
  slot_statistics_[slot].proxies = spheres_.size();
  slot_statistics_[slot].cpu_prepare_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return draws;
}

void SceneRenderer::record_skinning(VkCommandBuffer commands, std::uint32_t slot) const {
  memory_barrier(commands);  // the previous frame may still read the skinned vertices
  for (const auto& instance : instances_)
    for (const auto& mesh : instance->meshes)
      for (const auto& primitive : mesh.primitives)
        skin_pass_->record(context_, commands, primitive, mesh.palettes[slot], &mesh.normal_palettes[slot],
                           mesh.morph_weights.empty() ? nullptr : &mesh.morph_weights[slot]);
}

Status SceneRenderer::begin_frame(int frame) {
  const std::uint32_t slot = next_slot_;
  if (slot_frame_[slot] >= 0)
    return make_error("frame " + std::to_string(slot_frame_[slot]) + " still holds ring slot " + std::to_string(slot) +
                      ": finish it before beginning frame " + std::to_string(frame));
  auto draws = prepare_frame(frame, slot);
  if (!draws) return draws.error();
  Status submitted = in_flight_[slot].submit([&](VkCommandBuffer commands) {
    record_skinning(commands, slot);
    frame_->record(commands, slot, *draws);
  });
  if (!submitted) return submitted;
  slot_frame_[slot] = frame;
  slot_spheres_[slot] = spheres_;
  next_slot_ = (next_slot_ + 1) % std::uint32_t(in_flight_.size());
  return {};
}

Result<PassTimings> SceneRenderer::time_passes(int frame) {
  for (std::size_t slot = 0; slot < in_flight_.size(); ++slot)
    if (slot_frame_[slot] >= 0) return make_error("time_passes: finish every begun frame first");
  const auto start = std::chrono::steady_clock::now();
  auto draws = prepare_frame(frame, 0);
  if (!draws) return draws.error();
  PassTimings timings;
  timings.cpu_prepare_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  timings.proxies = spheres_.size();
  auto timed = [&](const std::function<void(VkCommandBuffer)>& record) -> Result<double> {
    const auto begin = std::chrono::steady_clock::now();
    if (Status done = context_.submit_and_wait(record); !done) return done.error();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  };
  auto skin = timed([&](VkCommandBuffer commands) { record_skinning(commands, 0); });
  if (!skin) return skin.error();
  timings.milliseconds[std::size_t(FramePass::skin)] = *skin;
  for (FramePass pass : frame_pass_order(frame_->settings().method)) {
    auto ms = timed([&](VkCommandBuffer commands) { frame_->record_pass(commands, 0, pass, *draws); });
    if (!ms) return ms.error();
    timings.milliseconds[std::size_t(pass)] = *ms;
  }
  return timings;
}

Result<FinishedFrame> SceneRenderer::finish_frame(int frame) {
  std::uint32_t slot = 0;
  while (slot < slot_frame_.size() && slot_frame_[slot] != frame) ++slot;
  if (slot == slot_frame_.size()) return make_error("frame " + std::to_string(frame) + " was not begun");
  if (Status waited = in_flight_[slot].wait(); !waited) return waited.error();
  FinishedFrame finished;
  finished.frame = frame;
  const auto ldr = frame_->slot_ldr(slot);
  finished.ldr.assign(ldr.begin(), ldr.end());
  finished.hdr = frame_->slot_hdr(slot);
  finished.statistics = slot_statistics_[slot];
  finished.spheres = std::move(slot_spheres_[slot]);
  slot_frame_[slot] = -1;
  return finished;
}

Result<FinishedFrame> SceneRenderer::render(int frame) {
  if (Status begun = begin_frame(frame); !begun) return begun.error();
  return finish_frame(frame);
}

}  // namespace proxygi::gpu
