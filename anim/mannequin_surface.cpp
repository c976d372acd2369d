// The mannequin's skinned surface: one tapered capsule (elliptical cross-section) per body part,
// tessellated as rings between two poles, weights blended across the joints at each end.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "anim/mannequin_parts.h"

namespace proxygi::anim::mannequin {
namespace {

struct BodyPart {
  int material;
  int joint;         // the bone that carries the part
  glm::vec3 start;   // axis from start to end; caps of radius r0 / r1 extend beyond them
  glm::vec3 end;
  float r0, r1;
  float side_scale;   // cross-section scale along the side axis (X-ish)
  float front_scale;  // and along the axis perpendicular to side and bone
  int parent_blend;   // joint blended in around `start` (-1: none)
  int child_blend;    // joint blended in around `end` (-1: none)
};

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

std::vector<BodyPart> body_parts(const std::array<glm::vec3, kJointCount>& p) {
  std::vector<BodyPart> parts = {
      // Torso: pelvis (trousers), abdomen and chest (shirt), neck and head (skin).
      {kTrousers, kHips, p[kHips] + glm::vec3(0, -0.05f, 0), p[kSpine], 0.15f, 0.15f, 1.0f, 0.72f, -1, kSpine},
      {kShirt, kSpine, p[kSpine], p[kChest], 0.14f, 0.15f, 1.0f, 0.70f, kHips, kChest},
      {kShirt, kChest, p[kChest], p[kNeck] + glm::vec3(0, -0.06f, 0), 0.15f, 0.16f, 1.0f, 0.66f, kSpine, -1},
      {kSkin, kNeck, p[kNeck] + glm::vec3(0, -0.04f, 0), p[kHead], 0.05f, 0.045f, 1.0f, 1.0f, kChest, kHead},
      {kSkin, kHead, p[kHead] + glm::vec3(0, 0.02f, 0.01f), p[kHead] + glm::vec3(0, 0.11f, 0.01f), 0.085f, 0.09f,
       0.92f, 1.08f, kNeck, -1},
  };
  for (const int side : {0, 1}) {
    const int offset_arm = side == 0 ? 0 : kRightShoulder - kLeftShoulder;
    const int offset_leg = side == 0 ? 0 : kRightUpperLeg - kLeftUpperLeg;
    const int shoulder = kLeftShoulder + offset_arm, upper_arm = kLeftUpperArm + offset_arm;
    const int lower_arm = kLeftLowerArm + offset_arm, hand = kLeftHand + offset_arm;
    const int upper_leg = kLeftUpperLeg + offset_leg, lower_leg = kLeftLowerLeg + offset_leg;
    const int foot = kLeftFoot + offset_leg, toes = kLeftToes + offset_leg;
    const float x = p[foot].x;
    const glm::vec3 hand_end = p[hand] + (p[hand] - p[lower_arm]) * 0.36f;
    parts.push_back({kShirt, shoulder, p[shoulder], p[upper_arm], 0.055f, 0.055f, 1.0f, 1.0f, kChest, upper_arm});
    parts.push_back({kShirt, upper_arm, p[upper_arm], p[lower_arm], 0.052f, 0.042f, 1.0f, 1.0f, shoulder, lower_arm});
    parts.push_back({kSkin, lower_arm, p[lower_arm], p[hand], 0.040f, 0.030f, 1.0f, 1.0f, upper_arm, hand});
    parts.push_back({kSkin, hand, p[hand], hand_end, 0.032f, 0.028f, 0.55f, 1.25f, lower_arm, -1});
    parts.push_back({kTrousers, upper_leg, p[upper_leg], p[lower_leg], 0.080f, 0.055f, 1.0f, 1.0f, kHips, lower_leg});
    parts.push_back({kTrousers, lower_leg, p[lower_leg], p[foot], 0.052f, 0.040f, 1.0f, 1.0f, upper_leg, foot});
    parts.push_back({kShoes, foot, glm::vec3(x, p[foot].y - 0.035f, p[foot].z - 0.04f),
                     glm::vec3(x, p[toes].y + 0.01f, p[toes].z - 0.01f), 0.050f, 0.045f, 1.0f, 0.8f, -1, toes});
    parts.push_back({kShoes, toes, p[toes], p[toes] + glm::vec3(0, 0, 0.06f), 0.040f, 0.034f, 1.05f, 0.8f, foot, -1});
  }
  return parts;
}

// Vertex influences: slot order (own joint, parent blend, child blend, unused), unused joint 0.
void part_weights(const BodyPart& part, float a, float length, std::uint16_t joints[4], float weights[4]) {
  const float parent = part.parent_blend >= 0 ? 1.0f - smoothstep(-0.6f * part.r0, 0.6f * part.r0, a) : 0.0f;
  const float child = part.child_blend >= 0 ? smoothstep(length - 0.6f * part.r1, length + 0.6f * part.r1, a) : 0.0f;
  const float own = std::max(0.0f, 1.0f - parent - child);
  const float sum = own + parent + child;
  joints[0] = static_cast<std::uint16_t>(part.joint);
  joints[1] = static_cast<std::uint16_t>(part.parent_blend >= 0 ? part.parent_blend : 0);
  joints[2] = static_cast<std::uint16_t>(part.child_blend >= 0 ? part.child_blend : 0);
  joints[3] = 0;
  weights[0] = own / sum;
  weights[1] = parent / sum;
  weights[2] = child / sum;
  weights[3] = 0.0f;
}

void append_part(const BodyPart& part, const MannequinOptions& options, Primitive& out) {
  const glm::vec3 axis = part.end - part.start;
  const float length = glm::length(axis);
  const glm::vec3 d = axis / length;
  // Side axis: world X projected off the bone (bones are never parallel to X here).
  const glm::vec3 side = glm::normalize(glm::vec3(1, 0, 0) - d * d.x);
  const glm::vec3 front = glm::cross(side, d);

  // Profile rings from the start pole to the end pole as (axial coordinate a, radius rho).
  const int around = std::max(options.segments_around, 3);
  const int cap_rings = std::max(2, around / 4);
  const int middle = std::max(1, static_cast<int>(std::lround(length * static_cast<float>(options.rings_per_meter))));
  std::vector<std::pair<float, float>> rings;
  constexpr float kHalfPi = std::numbers::pi_v<float> / 2.0f;
  for (int i = 1; i <= cap_rings; ++i) {
    const float theta = -kHalfPi + kHalfPi * static_cast<float>(i) / static_cast<float>(cap_rings);
    rings.emplace_back(part.r0 * std::sin(theta), part.r0 * std::cos(theta));
  }
  for (int j = 1; j < middle; ++j) {
    const float u = static_cast<float>(j) / static_cast<float>(middle);
    rings.emplace_back(length * u, part.r0 + (part.r1 - part.r0) * u);
  }
  for (int i = 0; i < cap_rings; ++i) {
    const float theta = kHalfPi * static_cast<float>(i) / static_cast<float>(cap_rings);
    rings.emplace_back(length + part.r1 * std::sin(theta), part.r1 * std::cos(theta));
  }

  const std::uint32_t base = static_cast<std::uint32_t>(out.positions.size());
  auto add_vertex = [&](float a, float rho, float phi) {
    const glm::vec3 radial = side * (std::cos(phi) * part.side_scale) + front * (std::sin(phi) * part.front_scale);
    out.positions.push_back(part.start + d * a + radial * rho);
    std::uint16_t joints[4];
    float weights[4];
    part_weights(part, a, length, joints, weights);
    out.joints.insert(out.joints.end(), joints, joints + 4);
    out.weights.insert(out.weights.end(), weights, weights + 4);
  };
  add_vertex(-part.r0, 0.0f, 0.0f);  // start pole
  for (const auto& [a, rho] : rings) {
    for (int k = 0; k < around; ++k) {
      add_vertex(a, rho, 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(around));
    }
  }
  add_vertex(length + part.r1, 0.0f, 0.0f);  // end pole

  const std::uint32_t ring_count = static_cast<std::uint32_t>(rings.size());
  const std::uint32_t n = static_cast<std::uint32_t>(around);
  const std::uint32_t end_pole = base + 1 + ring_count * n;
  std::vector<std::uint32_t> indices;
  auto ring_vertex = [&](std::uint32_t ring, std::uint32_t k) { return base + 1 + ring * n + k % n; };
  for (std::uint32_t k = 0; k < n; ++k) {
    indices.insert(indices.end(), {base, ring_vertex(0, k + 1), ring_vertex(0, k)});
    indices.insert(indices.end(), {end_pole, ring_vertex(ring_count - 1, k), ring_vertex(ring_count - 1, k + 1)});
  }
  for (std::uint32_t r = 0; r + 1 < ring_count; ++r) {
    for (std::uint32_t k = 0; k < n; ++k) {
      indices.insert(indices.end(), {ring_vertex(r, k), ring_vertex(r, k + 1), ring_vertex(r + 1, k + 1)});
      indices.insert(indices.end(), {ring_vertex(r, k), ring_vertex(r + 1, k + 1), ring_vertex(r + 1, k)});
    }
  }
  // Outward winding (counter-clockwise seen from outside): flip if the enclosed volume is negative.
  double volume = 0.0;
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    const glm::dvec3 a(out.positions[indices[t]] - part.start), b(out.positions[indices[t + 1]] - part.start),
        c(out.positions[indices[t + 2]] - part.start);
    volume += glm::dot(a, glm::cross(b, c));
  }
  if (volume < 0.0) {
    for (std::size_t t = 0; t < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
  }
  out.indices.insert(out.indices.end(), indices.begin(), indices.end());

  // Smooth normals: area-weighted face normals, summed per vertex of this part only.
  out.normals.resize(out.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    const glm::vec3 a = out.positions[indices[t]], b = out.positions[indices[t + 1]], c = out.positions[indices[t + 2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    for (std::size_t k = 0; k < 3; ++k) out.normals[indices[t + k]] += face;
  }
  for (std::size_t v = base; v < out.normals.size(); ++v) out.normals[v] = glm::normalize(out.normals[v]);
}

}  // namespace

void build_surface(const std::array<glm::vec3, kJointCount>& positions, const MannequinOptions& options, Mesh& mesh) {
  mesh.primitives.assign(kMaterialCount, Primitive{});
  for (int m = 0; m < kMaterialCount; ++m) {
    mesh.primitives[static_cast<std::size_t>(m)].material = m;
    mesh.primitives[static_cast<std::size_t>(m)].influences_per_vertex = 4;
  }
  for (const BodyPart& part : body_parts(positions)) {
    append_part(part, options, mesh.primitives[static_cast<std::size_t>(part.material)]);
  }
}

}  // namespace proxygi::anim::mannequin
