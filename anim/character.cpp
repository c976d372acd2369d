#include "anim/character.h"

namespace proxygi::anim {

glm::mat4 to_matrix(const Transform& transform) {
  glm::mat4 rotation = glm::mat4_cast(transform.rotation);
  rotation[0] *= transform.scale.x;
  rotation[1] *= transform.scale.y;
  rotation[2] *= transform.scale.z;
  rotation[3] = glm::vec4(transform.translation, 1.0f);
  return rotation;
}

}  // namespace proxygi::anim
