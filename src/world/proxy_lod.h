#pragma once
// ProxyLod: render.proxy_lod auto over a world (proxies/lod.h): nested sphere levels per model,
// built once from the rig tracked in the rest pose, and per character instance a chooser driven
// by the projected size of its bounding sphere, cross-faded over settings::kProxyLodFadeFrames.
//
//   auto lod = world::ProxyLod::build(*world);
//   std::vector<render::Sphere> streamed;
//   lod->select(state, output_height, streamed);   // per frame, instead of state.spheres
//
// Size: the bounding sphere of the rig's spheres in the rest pose, carried by the character's
// root placement (scene::character_world_matrix) at the frame's time and projected with the
// camera's vertical field of view onto `output_height` pixels (so the choice ignores the clip's
// pose: it cannot flicker with the animation).
//
// Deterministic per frame: the chooser steps once per scene frame (frame = round(t × fps)). The
// state at frame f is the chooser run from frame 0 with the scene camera at every earlier frame
// and the state's camera at f, kept from the last call so sequential frames cost one step; so
// `record` frames (and shards starting anywhere) are the same whatever was rendered before. A
// repeated frame with the same camera gives the same spheres; a repeated frame with another
// camera (a paused viewer being orbited) counts as one more frame of the fade, and later frames
// continue from it (the viewer's own history).
#include <cstdint>
#include <memory>
#include <vector>

#include "base/result.h"
#include "proxies/lod.h"
#include "render/shading.h"
#include "scene/camera.h"
#include "world/world.h"

namespace proxygi::world {

struct ModelLod {
  proxies::LodLevels levels;
  glm::vec3 bound_center{0.0f};  // the rest-pose bounding sphere, in the character's root space (m)
  float bound_radius = 0.0f;
};

struct InstanceLod {
  proxies::LodChoice choice;
  float radius_px = 0.0f;    // the size the last step saw
  std::size_t streamed = 0;  // spheres it streamed
};

class ProxyLod {
 public:
  // Levels of every model of `world` (which must outlive this); a model without a rig has one
  // empty level.
  static Result<std::unique_ptr<ProxyLod>> build(const World& world);

  // Appends the weighted spheres of every instance of `state` (from this world's evaluate) to
  // `out`, in instance order.
  Status select(const WorldState& state, std::uint32_t output_height, std::vector<render::Sphere>& out);

  const std::vector<ModelLod>& models() const { return models_; }
  const std::vector<InstanceLod>& instances() const { return instances_; }
  const proxies::LodChooser& chooser(std::size_t model) const { return choosers_[model]; }

 private:
  explicit ProxyLod(const World& world) : world_(world) {}
  float radius_px(std::size_t instance, double time_s, const scene::CameraState& camera, std::uint32_t height) const;
  void step_all(int frame, const scene::CameraState& camera, std::uint32_t height);

  const World& world_;
  std::vector<ModelLod> models_;
  std::vector<proxies::LodChooser> choosers_;  // per model
  std::vector<InstanceLod> instances_;
  bool cached_ = false;
  int cached_frame_ = 0;
  std::uint32_t cached_height_ = 0;
  scene::CameraState cached_camera_;
  std::vector<std::vector<proxies::WorldSphere>> scratch_;
  std::vector<proxies::WeightedSphere> weighted_;
};

}  // namespace proxygi::world
