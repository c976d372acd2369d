// SceneRenderer's GPU meshes: every model's primitives uploaded once in bind pose for the skin
// pass, skinned for all the model's instances in one dispatch per primitive (SkinGroup, with
// palettes per ring slot), the ground and the static meshes in world space.
#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>

#include "anim/bone_groups.h"
#include "anim/posed_character.h"
#include "anim/skinning.h"
#include "base/log.h"
#include "gpu/scene_renderer_parts.h"
#include "gpu/transfer.h"
#include "ref/sender_exposure.h"
#include "render/ground_grid.h"

namespace proxygi::gpu {
namespace {

// The primitive's triangles in bone-group order for every K (render.vsgl_grouping bone_groups).
template <class AllGroups>
Result<std::shared_ptr<const VsglTriangleOrders>> upload_vsgl_orders(Context& context, const anim::Character& character,
                                                                     int node, const anim::Primitive& primitive,
                                                                     const AllGroups& groups) {
  auto orders = std::make_shared<VsglTriangleOrders>();
  std::vector<std::uint32_t> indices;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const std::vector<int> vertex_group = anim::primitive_vertex_groups(character, node, primitive, groups[k]);
    const anim::GroupedTriangles grouped = anim::group_triangles(primitive.indices, vertex_group, groups[k].groups);
    const std::uint32_t base = std::uint32_t(indices.size() / 3);
    for (std::uint32_t first : grouped.first) orders->first[k].push_back(base + first);
    indices.insert(indices.end(), grouped.indices.begin(), grouped.indices.end());
  }
  // Index usage too: the sun map draws each light's range (rsm_pass.h).
  auto buffer = create_buffer_with_data(context, as_bytes(std::span<const std::uint32_t>(indices)),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!buffer) return buffer.error();
  orders->indices = std::move(*buffer);
  return std::shared_ptr<const VsglTriangleOrders>(std::move(orders));
}

}  // namespace

Status SceneRenderer::upload_instances() {
  const std::uint32_t slots = std::uint32_t(slots_.size());
  model_textures_.clear();
  for (const auto& model : world_->models()) {
    auto textures = MaterialTextures::create(context_, model->character);
    if (!textures) return make_error(model->file.string() + ": " + textures.message());
    model_textures_.push_back(std::make_unique<ModelTextures>(ModelTextures{model.get(), std::move(*textures)}));
  }
  instances_.clear();
  skin_groups_.clear();
  // Per model mesh node, its SkinGroup (index into skin_groups_), made at its first instance.
  std::map<std::pair<const world::Model*, std::size_t>, std::size_t> group_of;
  std::map<const world::Model*, std::uint32_t> model_instances;
  for (const world::CharacterInstance& source : world_->instances()) ++model_instances[source.model];
  // Index, uv and bind-pose buffers depend only on the model's primitive: uploaded once per model
  // and shared by its instances (the crowd's 20 mannequins hold one copy).
  struct Shared {
    std::shared_ptr<const SkinBindPose> bind_pose;
    std::shared_ptr<const Buffer> indices, uvs;
    std::shared_ptr<const VsglTriangleOrders> vsgl_orders;
  };
  std::map<std::tuple<const world::Model*, std::size_t, std::size_t>, Shared> shared;
  using AllGroups = std::array<anim::BoneGroups, settings::kVsglLightsPerCharacter.size()>;
  std::map<const world::Model*, AllGroups> bone_groups;  // per model, for each K
  for (std::size_t index = 0; index < world_->instances().size(); ++index) {
    const world::CharacterInstance& source = world_->instances()[index];
    const MaterialTextures* textures = nullptr;
    for (const auto& model : model_textures_)
      if (model->model == source.model) textures = &model->textures;
    auto instance = std::make_unique<Instance>();
    const anim::Character& character = source.model->character;
    if (!bone_groups.contains(source.model)) {
      AllGroups& groups = bone_groups[source.model];
      for (std::size_t k = 0; k < groups.size(); ++k)
        groups[k] = anim::character_bone_groups(character, settings::kVsglLightsPerCharacter[k]);
    }
    for (std::size_t node = 0; node < character.nodes.size(); ++node) {
      const anim::Node& n = character.nodes[node];
      if (n.mesh < 0) continue;
      MeshDraw draw;
      draw.node = int(node);
      draw.skin = n.skin;
      const std::size_t palette_size = n.skin >= 0 ? character.skins[std::size_t(n.skin)].joints.size() : 1;
      const bool first_instance = !group_of.contains({source.model, node});
      if (first_instance) {
        group_of[{source.model, node}] = skin_groups_.size();
        SkinGroup& group = skin_groups_.emplace_back();
        group.palette_joints = std::uint32_t(palette_size);
        group.morph_targets = std::uint32_t(std::max(anim::morph_target_count(character, int(node)), 0));
        const std::uint32_t count = model_instances[source.model];
        for (std::uint32_t slot = 0; slot < slots; ++slot) {
          for (auto* palettes : {&group.palettes, &group.normal_palettes}) {
            auto palette = Buffer::create(context_, count * palette_size * sizeof(glm::mat4), SkinPass::kPaletteUsage,
                                          MemoryKind::host_visible);
            if (!palette) return palette.error();
            palettes->push_back(std::move(*palette));
          }
          if (group.morph_targets > 0) {
            auto weights = Buffer::create(context_, std::size_t(count) * group.morph_targets * sizeof(float),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::host_visible);
            if (!weights) return weights.error();
            group.morph_weights.push_back(std::move(*weights));
          }
        }
      }
      draw.group = group_of[{source.model, node}];
      SkinGroup& group = skin_groups_[draw.group];
      draw.group_instance = group.instances++;
      std::size_t primitive_index = 0;
      for (const anim::Primitive& original : character.meshes[std::size_t(n.mesh)].primitives) {
        anim::Primitive primitive = original;
        if (n.skin < 0 || primitive.influences_per_vertex < 1) {  // rigid: one joint, the node itself
          primitive.influences_per_vertex = 1;
          primitive.joints.assign(primitive.positions.size(), 0);
          primitive.weights.assign(primitive.positions.size(), 1.0f);
        }
        Shared& buffers = shared[{source.model, node, primitive_index++}];
        if (first_instance) {
          auto uploaded = SkinPass::upload_bind_pose(context_, primitive);
          if (!uploaded) return uploaded.error();
          buffers.bind_pose = std::move(*uploaded);
          SkinGroup::Primitive& out = group.primitives.emplace_back();
          out.bind_pose = buffers.bind_pose;
          out.instance_stride = SkinPass::instance_stride(context_, buffers.bind_pose->vertex_count);
          const VkDeviceSize bytes = VkDeviceSize(model_instances[source.model]) * out.instance_stride * sizeof(glm::vec4);
          const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
          for (Buffer* target : {&out.world_positions, &out.world_normals}) {
            auto buffer = Buffer::create(context_, bytes, usage, MemoryKind::device_local);
            if (!buffer) return buffer.error();
            *target = std::move(*buffer);
          }
        }
        if (!buffers.indices) {
          // Storage too: the VSGL lights pass reads the triangles (indirect_method vsgl).
          auto indices = create_buffer_with_data(context_, as_bytes(std::span<const std::uint32_t>(primitive.indices)),
                                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
          if (!indices) return indices.error();
          buffers.indices = std::make_shared<const Buffer>(std::move(*indices));
          if (!primitive.uvs.empty()) {
            auto uvs = create_buffer_with_data(context_, as_bytes(std::span<const glm::vec2>(primitive.uvs)),
                                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
            if (!uvs) return uvs.error();
            buffers.uvs = std::make_shared<const Buffer>(std::move(*uvs));
          }
          auto orders = upload_vsgl_orders(context_, character, int(node), original, bone_groups[source.model]);
          if (!orders) return orders.error();
          buffers.vsgl_orders = std::move(*orders);
        }
        draw.indices.push_back(buffers.indices);
        draw.index_counts.push_back(std::uint32_t(primitive.indices.size()));
        draw.uvs.push_back(buffers.uvs);
        draw.vsgl_orders.push_back(buffers.vsgl_orders);
        draw.vsgl_exposure.push_back(nullptr);  // ensure_sender_exposure, on first need
        draw.materials.push_back(textures->binding(primitive.material));
      }
      draw.morph_offset = std::size_t(anim::morph_weight_offset(character, int(node)));
      instance->meshes.push_back(std::move(draw));
    }
    instances_.push_back(std::move(instance));
  }
  return {};
}

Status SceneRenderer::ensure_sender_exposure() {
  for (std::size_t index = 0; index < instances_.size(); ++index) {
    const world::Model* model = world_->instances()[index].model;
    auto cached = sender_exposure_.find(model);
    if (cached == sender_exposure_.end()) {
      // Per primitive in anim::pose_meshes order: the instance's meshes and their primitives in order.
      auto exposure = ref::rest_pose_sender_exposure(model->character);
      if (!exposure) return make_error(model->file.string() + ": " + exposure.message());
      ++sender_exposure_computations_;
      std::vector<std::shared_ptr<const Buffer>> buffers;
      for (const std::vector<float>& per_vertex : *exposure) {
        auto exposed = create_buffer_with_data(context_, as_bytes(std::span<const float>(per_vertex)),
                                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        if (!exposed) return exposed.error();
        buffers.push_back(std::make_shared<const Buffer>(std::move(*exposed)));
      }
      cached = sender_exposure_.emplace(model, std::move(buffers)).first;
    }
    const std::vector<std::shared_ptr<const Buffer>>& buffers = cached->second;
    std::size_t posed_primitive = 0;
    for (MeshDraw& mesh : instances_[index]->meshes)
      for (std::size_t i = 0; i < mesh.vsgl_exposure.size(); ++i, ++posed_primitive) {
        const SkinGroup::Primitive& skinned = skin_groups_[mesh.group].primitives[i];
        if (posed_primitive >= buffers.size() ||
            buffers[posed_primitive]->size() != skinned.bind_pose->vertex_count * sizeof(float))
          return make_error(model->file.string() + ": node " + std::to_string(mesh.node) +
                            ": sender exposure does not match the primitive's vertices");
        mesh.vsgl_exposure[i] = buffers[posed_primitive];
      }
  }
  return {};
}

Status SceneRenderer::upload_static_meshes() {
  const scene::Scene& scene = world_->scene();
  const settings::ShadingMethod method = frame_ ? frame_->settings().method : static_meshes_method_;
  static_meshes_.clear();
  static_textures_.clear();
  static_meshes_method_ = method;
  if (scene.ground.enabled && method == settings::ShadingMethod::vertex) {
    // Vertex receivers need ground vertices where the characters are (render/ground_grid.h).
    const render::GroundRegion region = render::ground_fine_region(scene);
    const render::GroundGrid grid =
        render::make_ground_grid(scene.ground.size, region.min, region.max, region.vertices_per_metre);
    log_info("vertex method: ground grid of " + std::to_string(grid.positions.size()) + " vertices (" +
             std::to_string(region.vertices_per_metre) + " per metre near the characters)");
    auto ground = upload_static_mesh(context_, grid.positions, grid.normals, grid.indices,
                                     glm::vec4(scene.ground.albedo, 1.0f));
    if (!ground) return ground.error();
    static_meshes_.push_back(std::move(*ground));
  } else if (scene.ground.enabled) {
    const float half = 0.5f * scene.ground.size;
    const glm::vec3 corners[] = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
    const glm::vec3 up[] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const std::uint32_t quad[] = {0, 2, 1, 0, 3, 2};
    auto ground = upload_static_mesh(context_, corners, up, quad, glm::vec4(scene.ground.albedo, 1.0f));
    if (!ground) return ground.error();
    static_meshes_.push_back(std::move(*ground));
  }
  for (const world::StaticModel& model : world_->static_models()) {
    auto textures = MaterialTextures::create(context_, model.character);
    if (!textures)
      return make_error("static_meshes[" + std::to_string(model.scene_static_mesh) + "]: " + textures.message());
    static_textures_.push_back(std::make_unique<MaterialTextures>(std::move(*textures)));
    for (const auto& primitive : model.primitives) {
      if (primitive.normals.size() != primitive.positions.size()) continue;
      // The albedo override replaces the whole base color, texture included (as in the reference).
      const MaterialBinding material = model.albedo ? MaterialBinding{glm::vec4(*model.albedo, 1.0f), {}}
                                                    : static_textures_.back()->binding(primitive.material);
      auto mesh = upload_static_mesh(context_, primitive.positions, primitive.normals, primitive.indices,
                                     material.base_color, primitive.uvs, material.texture);
      if (!mesh) return mesh.error();
      static_meshes_.push_back(std::move(*mesh));
    }
  }
  return {};
}

Result<std::vector<std::vector<std::vector<glm::vec3>>>> SceneRenderer::read_skinned_positions() const {
  // Each group primitive's outputs read back once: every instance's range of them.
  std::map<const Buffer*, std::vector<std::uint8_t>> read;
  std::vector<std::vector<std::vector<glm::vec3>>> out;
  for (const auto& instance : instances_) {
    out.emplace_back();
    for (const auto& mesh : instance->meshes)
      for (const SkinGroup::Primitive& primitive : skin_groups_[mesh.group].primitives) {
        if (!read.contains(&primitive.world_positions)) {
          auto bytes = readback(context_, primitive.world_positions);
          if (!bytes) return bytes.error();
          read[&primitive.world_positions] = std::move(*bytes);
        }
        const auto* vertices = reinterpret_cast<const glm::vec4*>(read[&primitive.world_positions].data()) +
                               std::size_t(mesh.group_instance) * primitive.instance_stride;
        std::vector<glm::vec3> positions(primitive.bind_pose->vertex_count);
        for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = glm::vec3(vertices[v]);
        out.back().push_back(std::move(positions));
      }
  }
  return out;
}

void SceneRenderer::record_skinning(VkCommandBuffer commands, std::uint32_t slot) const {
  memory_barrier(commands);  // the previous frame may still read the skinned vertices
  for (const SkinGroup& group : skin_groups_)
    for (const SkinGroup::Primitive& primitive : group.primitives) {
      SkinBatch batch;
      batch.bind_pose = primitive.bind_pose.get();
      batch.instances = group.instances;
      batch.instance_stride = primitive.instance_stride;
      batch.world_positions = &primitive.world_positions;
      batch.world_normals = &primitive.world_normals;
      batch.palette = {&group.palettes[slot], &group.normal_palettes[slot], group.palette_joints};
      batch.morph_weights = group.morph_weights.empty() ? nullptr : &group.morph_weights[slot];
      skin_pass_->record(context_, commands, batch);
    }
  SkinPass::record_outputs_barrier(commands);  // one for all dispatches: their outputs are disjoint
}

}  // namespace proxygi::gpu
