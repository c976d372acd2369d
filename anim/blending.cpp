#include "anim/blending.h"

#include <cmath>
#include <string>

namespace proxygi::anim {

glm::quat slerp_shortest(const glm::quat& a, const glm::quat& b_in, float u) {
  float cosine = glm::dot(a, b_in);
  const glm::quat b = cosine < 0.0f ? -b_in : b_in;  // take the short way round
  cosine = std::fabs(cosine);
  float wa = 1.0f - u;
  float wb = u;
  // Nearly parallel: acos/sin lose precision in float, and nlerp is within ~1e-8 of slerp.
  if (cosine < 0.99999f) {
    const float angle = std::acos(std::fmin(cosine, 1.0f));
    const float inv_sine = 1.0f / std::sin(angle);
    wa = std::sin(angle * (1.0f - u)) * inv_sine;
    wb = std::sin(angle * u) * inv_sine;
  }
  return glm::normalize(glm::quat(wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z));
}

Status BlendJob::validate() const {
  if (a.size() != b.size() || output.size() != a.size()) {
    return make_error("blend: pose sizes differ (a " + std::to_string(a.size()) + ", b " + std::to_string(b.size()) +
                      ", output " + std::to_string(output.size()) + ")");
  }
  if (morph_a.size() != morph_b.size() || morph_output.size() != morph_a.size()) {
    return make_error("blend: morph weight sizes differ");
  }
  if (!std::isfinite(weight) || weight < 0.0f || weight > 1.0f) {
    return make_error("blend: weight " + std::to_string(weight) + " outside [0, 1]");
  }
  return {};
}

Status BlendJob::run() const {
  if (Status status = validate(); !status) return status;
  const float wa = 1.0f - weight;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Transform ta = a[i];  // copies: output may alias a or b
    const Transform tb = b[i];
    Transform& out = output[i];
    out.translation = ta.translation * wa + tb.translation * weight;
    out.scale = ta.scale * wa + tb.scale * weight;
    if (weight == 0.0f) {
      out.rotation = ta.rotation;
    } else if (weight == 1.0f) {
      out.rotation = glm::dot(ta.rotation, tb.rotation) < 0.0f ? -tb.rotation : tb.rotation;
    } else {
      out.rotation = slerp_shortest(ta.rotation, tb.rotation, weight);
    }
  }
  for (std::size_t i = 0; i < morph_a.size(); ++i) morph_output[i] = morph_a[i] * wa + morph_b[i] * weight;
  return {};
}

}  // namespace proxygi::anim
