#pragma once
// Where a scene character is and which clip time it shows at a scene time. Pure functions of
// the scene and t (seconds), so every frame can be evaluated on its own (shards, regress).
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace proxygi::scene {

// Clip time in seconds: time_offset_s + speed * t. Not wrapped: the clip sampler decides
// whether a clip loops or clamps.
double clip_time_s(const Character& character, double scene_time_s);

// A point on a walk path: world position (meters) and heading, the rotation about +Y in
// radians that turns +Z (glTF forward) onto the current direction of travel.
struct PathPoint {
  glm::vec3 position{0.0f};
  float heading_radians = 0.0f;
};

// The root motion described in scene.h (WalkPath): s = speed * max(t, 0) meters along the line,
// then stop / loop / ping_pong. A path with no horizontal extent keeps heading 0.
PathPoint walk_path_at(const WalkPath& path, double scene_time_s);

// Model space -> world at time t: translate(path position) * rotateY(heading) * transform when
// the character has a path, else transform.to_matrix().
glm::mat4 character_world_matrix(const Character& character, double scene_time_s);

// World position of the model's origin at time t (what a follow camera tracks by default;
// clips with root motion of their own need the sampled root joint instead).
glm::vec3 character_root_position(const Character& character, double scene_time_s);

}  // namespace proxygi::scene
