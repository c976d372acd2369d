#include "view/overlays.h"

#include <cmath>
#include <functional>
#include <optional>
#include <set>

#include <imgui.h>

namespace proxygi::view {
namespace {

struct Projector {
  scene::CameraState camera;
  int width = 1, height = 1;
  glm::vec3 forward{0.0f, 0.0f, -1.0f};
  float focal_px = 1.0f;  // pixels per unit of (lateral distance / depth)

  Projector(const scene::CameraState& c, int w, int h) : camera(c), width(w), height(h) {
    forward = glm::normalize(c.target - c.eye);
    focal_px = 0.5f * float(h) / std::tan(glm::radians(c.fov_y_degrees) * 0.5f);
  }
  float depth(const glm::vec3& p) const { return glm::dot(p - camera.eye, forward); }
  std::optional<ImVec2> project(const glm::vec3& p) const {
    if (depth(p) <= camera.near_m) return std::nullopt;
    const glm::vec2 px = scene::project_to_pixel(camera, width, height, p);
    return ImVec2(px.x, px.y);
  }
};

// A stable, distinct colour per bone name.
ImU32 bone_color(const std::string& bone) {
  const std::size_t hash = std::hash<std::string>{}(bone);
  const float hue = float(hash % 360) / 360.0f;
  float r, g, b;
  ImGui::ColorConvertHSVtoRGB(hue, 0.75f, 1.0f, r, g, b);
  return ImGui::GetColorU32({r, g, b, 0.9f});
}

// A world segment clipped to the part in front of the near plane (a point just in front of the
// eye projects far off screen, so unclipped segments streak across the window).
void draw_segment(ImDrawList& list, const Projector& projector, glm::vec3 a, glm::vec3 b, ImU32 color, float width) {
  const float near = projector.camera.near_m * 2.0f;
  const float da = projector.depth(a), db = projector.depth(b);
  if (da < near && db < near) return;
  if (da < near) a = a + (b - a) * ((near - da) / (db - da));
  if (db < near) b = b + (a - b) * ((near - db) / (da - db));
  const auto pa = projector.project(a), pb = projector.project(b);
  if (pa && pb) list.AddLine(*pa, *pb, color, width);
}

void draw_grid(ImDrawList& list, const Projector& projector) {
  const ImU32 color = IM_COL32(60, 60, 70, 140);  // dark: the default ground is light gray
  constexpr int kHalf = 5;  // ±5 m, lines every metre
  for (int i = -kHalf; i <= kHalf; ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      // Split each line so segments behind the camera are dropped, not the whole line.
      for (int s = -kHalf; s < kHalf; ++s) {
        const glm::vec3 a = axis ? glm::vec3(float(i), 0, float(s)) : glm::vec3(float(s), 0, float(i));
        const glm::vec3 b = axis ? glm::vec3(float(i), 0, float(s + 1)) : glm::vec3(float(s + 1), 0, float(i));
        draw_segment(list, projector, a, b, color, 1.0f);
      }
    }
  }
}

// Every triangle edge of the instance's meshes, skinned on the CPU (world::World::pose_instance),
// drawn over the frame without a depth test (an x-ray view: hidden edges show too). At most
// kMaxWireframeEdges per frame, so a crowd stays interactive.
constexpr std::size_t kMaxWireframeEdges = 150000;

void draw_wireframe(ImDrawList& list, const Projector& projector, const world::World& world,
                    const world::WorldState& state, std::size_t instance, std::size_t& edges) {
  auto primitives = world.pose_instance(state, instance);
  if (!primitives) return;
  const ImU32 color = IM_COL32(120, 255, 200, 110);
  for (const anim::PosedPrimitive& primitive : *primitives)
    for (std::size_t t = 0; t + 2 < primitive.indices.size() && edges < kMaxWireframeEdges; t += 3, edges += 3)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = primitive.indices[t + std::size_t(e)], b = primitive.indices[t + std::size_t((e + 1) % 3)];
        if (a < primitive.positions.size() && b < primitive.positions.size())
          draw_segment(list, projector, primitive.positions[a], primitive.positions[b], color, 1.0f);
      }
}

}  // namespace

void draw_overlays(const scene::CameraState& camera, const world::World* world, const world::WorldState& state,
                   const Toggles& toggles, float shadow_eta) {
  if (!toggles.grid && !toggles.proxies && !toggles.bones && !toggles.wireframe) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const Projector projector(camera, int(size.x), int(size.y));
  ImDrawList& list = *ImGui::GetBackgroundDrawList();
  if (toggles.grid) draw_grid(list, projector);
  if (!world) return;
  std::size_t wireframe_edges = 0;
  for (std::size_t i = 0; i < state.instances.size() && i < world->instances().size(); ++i) {
    const world::Model& model = *world->instances()[i].model;
    const world::InstanceState& instance = state.instances[i];
    if (toggles.wireframe) draw_wireframe(list, projector, *world, state, i, wireframe_edges);
    if (toggles.proxies) {
      for (std::size_t s = 0; s < instance.spheres.size(); ++s) {
        const auto& sphere = instance.spheres[s];
        const auto center = projector.project(sphere.center);
        if (!center) continue;
        const float radius_px = sphere.radius * projector.focal_px / projector.depth(sphere.center);
        const std::string& bone = s < model.rig.spheres.size() ? model.rig.spheres[s].bone : std::string();
        const bool selected = !toggles.selected_bone.empty() && bone == toggles.selected_bone;
        list.AddCircle(*center, radius_px, selected ? IM_COL32(255, 255, 255, 255) : bone_color(bone), 32,
                       selected ? 3.5f : 1.5f);
        // The shell's outline as the sphere's, scaled: exact only away from the eye, enough to see reach.
        if (toggles.shells) list.AddCircle(*center, radius_px * shadow_eta, (bone_color(bone) & 0x00FFFFFFu) | 0x50000000u, 48);
      }
    }
    if (toggles.bones) {
      std::set<int> joints;
      for (const auto& skin : model.character.skins) joints.insert(skin.joints.begin(), skin.joints.end());
      for (int node : joints) {
        const int parent = model.character.nodes[std::size_t(node)].parent;
        if (parent < 0 || !joints.count(parent) || std::size_t(node) >= instance.pose.world.size()) continue;
        const glm::vec3 joint(instance.pose.world[std::size_t(node)][3]);
        draw_segment(list, projector, joint, glm::vec3(instance.pose.world[std::size_t(parent)][3]),
                     IM_COL32(255, 230, 80, 230), 2.0f);
        if (const auto at = projector.project(joint)) list.AddCircleFilled(*at, 3.0f, IM_COL32(255, 120, 40, 230));
      }
    }
  }
}

}  // namespace proxygi::view
