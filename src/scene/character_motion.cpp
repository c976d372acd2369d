#include "scene/character_motion.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace proxygi::scene {

double clip_time_s(const Character& character, double scene_time_s) {
  return static_cast<double>(character.time_offset_s) +
         static_cast<double>(character.speed) * scene_time_s;
}

PathPoint walk_path_at(const WalkPath& path, double scene_time_s) {
  const glm::dvec3 start(path.start);
  const glm::dvec3 delta = glm::dvec3(path.end) - start;
  const double length = glm::length(delta);
  PathPoint point;
  if (!(length > 0.0)) {  // validation refuses this; stay put rather than divide by zero
    point.position = path.start;
    return point;
  }
  const glm::dvec3 direction = delta / length;
  const double travelled = static_cast<double>(path.speed) * std::max(scene_time_s, 0.0);
  double along = 0.0;  // distance from start
  bool backwards = false;
  switch (path.repeat) {
    case WalkPath::Repeat::none:
      along = std::min(travelled, length);
      break;
    case WalkPath::Repeat::loop:
      along = std::fmod(travelled, length);
      break;
    case WalkPath::Repeat::ping_pong: {
      const double phase = std::fmod(travelled, 2.0 * length);
      backwards = phase > length;
      along = backwards ? 2.0 * length - phase : phase;
      break;
    }
  }
  point.position = glm::vec3(start + direction * along);
  const glm::dvec3 travel = backwards ? -direction : direction;
  if (travel.x * travel.x + travel.z * travel.z > 1e-12) {
    point.heading_radians = static_cast<float>(std::atan2(travel.x, travel.z));
  }
  return point;
}

glm::mat4 character_world_matrix(const Character& character, double scene_time_s) {
  const glm::mat4 model = character.transform.to_matrix();
  if (!character.path) return model;
  const PathPoint point = walk_path_at(*character.path, scene_time_s);
  glm::mat4 frame = glm::translate(glm::mat4(1.0f), point.position);
  frame = glm::rotate(frame, point.heading_radians, glm::vec3(0.0f, 1.0f, 0.0f));
  return frame * model;
}

glm::vec3 character_root_position(const Character& character, double scene_time_s) {
  return glm::vec3(character_world_matrix(character, scene_time_s)[3]);
}

}  // namespace proxygi::scene
