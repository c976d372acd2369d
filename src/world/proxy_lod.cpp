#include "world/proxy_lod.h"

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/posed_character.h"
#include "proxies/culling.h"
#include "scene/character_motion.h"
#include "settings/render_settings.h"

namespace proxygi::world {
namespace {

bool same_camera(const scene::CameraState& a, const scene::CameraState& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_y_degrees == b.fov_y_degrees;
}

float largest_scale(const glm::mat4& m) {
  return std::max({glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

}  // namespace

Result<std::unique_ptr<ProxyLod>> ProxyLod::build(const World& world) {
  std::unique_ptr<ProxyLod> lod(new ProxyLod(world));
  for (const auto& model : world.models()) {
    ModelLod out;
    proxies::LodChooser chooser{{}, settings::kProxyLodPixelsPerSphere, settings::kProxyLodHysteresis,
                                settings::kProxyLodFadeFrames};
    const std::size_t count = model->tracking.spheres.size();
    if (count == 0) {
      out.levels.levels.resize(1);
    } else {
      anim::PoseBuffers rest;
      if (Status posed = anim::evaluate_pose(model->character, -1, 0.0f, anim::WrapMode::loop, rest); !posed)
        return make_error("proxy lod: " + model->file.string() + ": " + posed.message());
      std::vector<proxies::WorldSphere> spheres(count);
      proxies::TrackProxiesJob track{&model->tracking, rest.world, spheres};
      if (Status tracked = track.run(); !tracked) return make_error("proxy lod: " + model->file.string() + ": " + tracked.message());
      const std::vector<int> groups = proxies::chain_groups(model->rig, model->character);
      std::vector<int> nodes;
      for (const auto& sphere : model->rig.spheres) nodes.push_back(sphere.node);
      proxies::BuildLodLevelsJob job{spheres, groups, nodes, settings::kProxyLodMinSpheres, &out.levels};
      if (Status built = job.run(); !built) return make_error("proxy lod: " + model->file.string() + ": " + built.message());
      if (Status valid = proxies::validate_lod_levels(out.levels, spheres); !valid)
        return make_error("proxy lod: " + model->file.string() + ": " + valid.message());
      const proxies::WorldSphere whole = proxies::bounding_sphere(spheres);
      out.bound_center = whole.center;
      out.bound_radius = whole.radius;
    }
    chooser.counts = out.levels.counts();
    lod->models_.push_back(std::move(out));
    lod->choosers_.push_back(std::move(chooser));
  }
  lod->instances_.resize(world.instances().size());
  return lod;
}

float ProxyLod::radius_px(std::size_t instance, double time_s, const scene::CameraState& camera, std::uint32_t height) const {
  const CharacterInstance& character = world_.instances()[instance];
  const ModelLod& model = models_[character.model_index];
  const glm::mat4 root = scene::character_world_matrix(world_.scene().characters[character.scene_character], time_s);
  const glm::vec3 center = glm::vec3(root * glm::vec4(model.bound_center, 1.0f));
  const float focal = float(height) / (2.0f * std::tan(glm::radians(camera.fov_y_degrees) * 0.5f));
  return proxies::projected_radius_pixels(center, model.bound_radius * largest_scale(root), camera.eye, focal);
}

void ProxyLod::step_all(int frame, const scene::CameraState& camera, std::uint32_t height) {
  const double time_s = scene::frame_time_s(world_.scene().output, frame);
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    InstanceLod& instance = instances_[i];
    instance.radius_px = radius_px(i, time_s, camera, height);
    instance.choice = choosers_[world_.instances()[i].model_index].step(instance.choice, instance.radius_px);
  }
}

Status ProxyLod::select(const WorldState& state, std::uint32_t output_height, std::vector<render::Sphere>& out) {
  if (state.instances.size() != instances_.size())
    return make_error("proxy lod: the world state holds " + std::to_string(state.instances.size()) + " characters, the world " +
                      std::to_string(instances_.size()));
  const scene::Scene& scene = world_.scene();
  const int frame = int(std::lround(state.time_s * scene.output.fps));
  const bool restart = !cached_ || frame < cached_frame_ || output_height != cached_height_;
  if (restart) {
    // Frame 0 starts settled at the level its size asks for; earlier frames see the scene camera.
    const scene::CameraState first = frame == 0 ? state.camera : scene::evaluate_scene_camera(scene, 0.0);
    for (std::size_t i = 0; i < instances_.size(); ++i) {
      const proxies::LodChooser& chooser = choosers_[world_.instances()[i].model_index];
      instances_[i].radius_px = radius_px(i, 0.0, first, output_height);
      const int level = chooser.level_for(instances_[i].radius_px);
      instances_[i].choice = {level, level, 0};
    }
    cached_frame_ = 0;
    cached_camera_ = first;
  }
  if (frame > cached_frame_) {
    for (int f = cached_frame_ + 1; f < frame; ++f)
      step_all(f, scene::evaluate_scene_camera(scene, scene::frame_time_s(scene.output, f)), output_height);
    step_all(frame, state.camera, output_height);
  } else if (!same_camera(state.camera, cached_camera_)) {
    step_all(frame, state.camera, output_height);  // the same frame under another camera: one more step
  }
  cached_ = true;
  cached_frame_ = frame;
  cached_height_ = output_height;
  cached_camera_ = state.camera;

  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const std::size_t model = world_.instances()[i].model_index;
    weighted_.clear();
    const auto& tracked = state.instances[i].spheres;
    if (!tracked.empty())
      proxies::append_lod_spheres(models_[model].levels, instances_[i].choice, choosers_[model].fade(instances_[i].choice),
                                  tracked, scratch_, weighted_);
    instances_[i].streamed = weighted_.size();
    for (const auto& w : weighted_) out.push_back({w.sphere.center, w.sphere.radius, w.sphere.albedo, w.weight});
  }
  return {};
}

}  // namespace proxygi::world
