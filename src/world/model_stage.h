#pragma once
// A model on the default stage: the scene `proxygi record MODEL.glb` (and `reference`) renders
// when the user names a model instead of a scene file, and the helpers the speed–accuracy chart
// (src/study/chart_scenes.h) frames its characters with.
//
// The stage is scene::default_scene()'s ground (2 km, so it reaches the horizon), sky and sun.
// The character is placed at its own size (no scaling), its lowest point over the clip on the
// ground (y = 0) and the middle of its bounds over the clip above the origin. A fixed camera
// looks at the middle of those bounds from the front-right and above, far enough that the
// bounding sphere of the whole motion fits the vertical field of view with a margin; the scene's
// frames cover one pass of the clip (at least one frame).
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "base/result.h"
#include "scene/scene.h"
#include "world/world.h"

namespace proxygi::world {

using Bounds = std::pair<glm::vec3, glm::vec3>;  // low, high corners, meters, world space

// Bounds of instance `instance`'s skinned meshes at scene time t; an error without geometry.
Result<Bounds> posed_bounds(const World& world, double t, std::size_t instance = 0);
// The union of posed_bounds at `samples` times spread evenly over [first_s, last_s].
Result<Bounds> bounds_over_time(const World& world, double first_s, double last_s, int samples, std::size_t instance = 0);

// A fixed camera seeing `bounds` whole: looking at their middle from `direction` (from the
// target toward the eye) at the distance where their bounding sphere fills 80 % of the vertical
// field of view `fov_degrees`.
scene::FixedCamera frame_bounds(const Bounds& bounds, float fov_degrees = 40.0f,
                                const glm::vec3& direction = glm::vec3(0.45f, 0.35f, 1.0f));

struct StageOptions {
  scene::ClipRef clip{std::in_place_type<int>, 0};
  std::optional<int> frame_count;  // default: one pass of the clip at the scene's fps
};

// The default stage around `model` (a glTF path, or "builtin:mannequin"). Errors name the model
// ("hero.glb: clip \"run\" not found ...").
Result<scene::Scene> stage_scene(const std::string& model, const std::filesystem::path& assets_dir,
                                 const StageOptions& options = {});

}  // namespace proxygi::world
