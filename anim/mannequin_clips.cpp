// The mannequin's clips, generated from gait parameters: feet follow a stance/swing path solved
// with planar two-bone IK (legs move in the YZ plane), arms swing against the legs, hips bob.
// All keys are LINEAR at 30 keys per second; cyclic clips end on an exact copy of their first key.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "anim/mannequin_parts.h"

namespace proxygi::anim::mannequin {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kKeysPerSecond = 30.0f;

// One key of a clip: local rotation per joint (identity = rest) and the hips translation.
struct Keyframe {
  std::array<glm::quat, kJointCount> rotation;
  glm::vec3 hips_translation{0.0f};
  Keyframe() { rotation.fill(glm::quat(1.0f, 0.0f, 0.0f, 0.0f)); }
};

glm::quat about_x(float angle) { return glm::angleAxis(angle, glm::vec3(1, 0, 0)); }
glm::quat about_y(float angle) { return glm::angleAxis(angle, glm::vec3(0, 1, 0)); }
glm::quat about_z(float angle) { return glm::angleAxis(angle, glm::vec3(0, 0, 1)); }

float smoothstep(float x) {
  const float t = std::clamp(x, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Angle about +X that turns the rest "down" direction (0, −1, 0) into dir (y, z components).
float angle_from_down(float dy, float dz) { return std::atan2(-dz, -dy); }

struct LegAngles {
  float hip, knee, ankle;  // local rotations about X
};

// Planar two-bone IK in the (y, z) plane with the knee bending forward (+Z); the foot ends level
// (its world rotation is `foot_pitch` about X). Unreachable targets straighten the leg.
LegAngles solve_leg(glm::vec2 hip, glm::vec2 ankle, float thigh, float shin, float foot_pitch) {
  const glm::vec2 d = ankle - hip;  // (y, z)
  const float distance = std::clamp(glm::length(d), std::fabs(thigh - shin) + 1e-4f, thigh + shin - 1e-5f);
  const float cos_hip = (thigh * thigh + distance * distance - shin * shin) / (2.0f * thigh * distance);
  const float thigh_angle = angle_from_down(d.x, d.y) - std::acos(std::clamp(cos_hip, -1.0f, 1.0f));
  const glm::vec2 knee = hip + thigh * glm::vec2(-std::cos(thigh_angle), -std::sin(thigh_angle));
  const glm::vec2 s = ankle - knee;
  const float shin_angle = angle_from_down(s.x, s.y);
  return {thigh_angle, shin_angle - thigh_angle, foot_pitch - shin_angle};
}

struct Gait {
  float period;         // seconds per cycle (two steps)
  float speed;          // m/s the feet slide back during stance
  float stance;         // fraction of the cycle a foot is on the ground
  float hips_drop;      // mean hips lowering, m
  float hips_bob;       // hips bob amplitude, m (twice per cycle)
  float bob_phase;      // cycle phase of the highest hips
  float swing_height;   // foot lift during swing, m
  float arm_swing;      // upper-arm swing amplitude, rad
  float elbow;          // mean elbow flexion, rad
  float lean;           // forward spine lean, rad
  float twist;          // chest twist amplitude about Y, rad
};

Keyframe gait_key(const std::array<glm::vec3, kJointCount>& p, const Gait& gait, float phase) {
  Keyframe key;
  const float bob = gait.hips_bob * std::cos(2.0f * kPi * 2.0f * (phase - gait.bob_phase));
  key.hips_translation = p[kHips] - p[kRoot] + glm::vec3(0.0f, -gait.hips_drop + bob, 0.0f);
  const float hips_y = p[kRoot].y + key.hips_translation.y;
  const float stride = gait.speed * gait.stance * gait.period;  // foot travel during stance

  for (const int side : {0, 1}) {
    const int upper = side == 0 ? kLeftUpperLeg : kRightUpperLeg;
    const float leg_phase = std::fmod(phase + 0.5f * static_cast<float>(side), 1.0f);
    float z, lift, pitch = 0.0f;
    if (leg_phase < gait.stance) {
      z = stride * (0.5f - leg_phase / gait.stance);
      lift = 0.0f;
    } else {
      const float u = (leg_phase - gait.stance) / (1.0f - gait.stance);
      z = stride * (smoothstep(u) - 0.5f);
      lift = gait.swing_height * std::sin(kPi * u);
      pitch = 0.35f * std::sin(kPi * u);  // toes point down while the foot swings
    }
    const float thigh = glm::length(p[upper + 1] - p[upper]);
    const float shin = glm::length(p[upper + 2] - p[upper + 1]);
    const glm::vec2 hip(hips_y + (p[upper].y - p[kHips].y), p[upper].z);
    const glm::vec2 ankle(p[upper + 2].y + lift, p[upper + 2].z + z);
    const LegAngles leg = solve_leg(hip, ankle, thigh, shin, pitch);
    key.rotation[static_cast<std::size_t>(upper)] = about_x(leg.hip);
    key.rotation[static_cast<std::size_t>(upper + 1)] = about_x(leg.knee);
    key.rotation[static_cast<std::size_t>(upper + 2)] = about_x(leg.ankle);
  }

  // Arms swing opposite to the legs: the left leg strikes forward at phase 0, the left arm is back.
  const float swing = gait.arm_swing * std::cos(2.0f * kPi * phase);
  key.rotation[kLeftUpperArm] = about_x(swing);
  key.rotation[kRightUpperArm] = about_x(-swing);
  key.rotation[kLeftLowerArm] = about_x(-gait.elbow - 0.3f * gait.elbow * std::max(0.0f, -std::cos(2.0f * kPi * phase)));
  key.rotation[kRightLowerArm] = about_x(-gait.elbow - 0.3f * gait.elbow * std::max(0.0f, std::cos(2.0f * kPi * phase)));
  key.rotation[kSpine] = about_x(gait.lean);
  key.rotation[kChest] = about_y(gait.twist * std::cos(2.0f * kPi * phase));
  key.rotation[kHead] = about_x(-0.6f * gait.lean);
  return key;
}

Keyframe wave_key(const std::array<glm::vec3, kJointCount>& p, float t) {
  // Raise (0–0.5 s), wave twice (0.5–1.9 s), lower (1.9–2.4 s); the right arm is on −X.
  const float envelope = smoothstep(t / 0.5f) * (1.0f - smoothstep((t - 1.9f) / 0.5f));
  const float wave = std::sin(2.0f * kPi * (t - 0.5f) / 0.7f) * (t > 0.5f && t < 1.9f ? 1.0f : 0.0f);
  Keyframe key;
  key.hips_translation = p[kHips] - p[kRoot];  // in place, hips at rest height
  key.rotation[kRightShoulder] = about_z(-0.15f * envelope);
  key.rotation[kRightUpperArm] = about_z(-2.0f * envelope);
  key.rotation[kRightLowerArm] = about_z(envelope * (-1.0f + 0.4f * wave));
  key.rotation[kRightHand] = about_z(0.15f * envelope * wave);
  key.rotation[kLeftUpperArm] = about_z(0.08f * envelope);
  key.rotation[kChest] = about_z(0.05f * envelope);
  key.rotation[kHead] = about_z(-0.08f * envelope) * about_y(-0.15f * envelope);
  return key;
}

// Turns keyframes into one LINEAR rotation channel per joint that moves, plus a hips
// translation channel when the hips move. Quaternion signs are made continuous.
Clip make_clip(const std::string& name, const std::vector<Keyframe>& keys, float duration,
               const std::array<glm::vec3, kJointCount>& p) {
  Clip clip;
  clip.name = name;
  clip.duration = duration;
  std::vector<float> times(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    times[k] = k + 1 == keys.size() ? duration : duration * static_cast<float>(k) / static_cast<float>(keys.size() - 1);
  }
  const glm::vec3 hips_rest = p[kHips] - p[kRoot];
  const bool hips_move = std::any_of(keys.begin(), keys.end(), [&](const Keyframe& k) { return k.hips_translation != hips_rest; });
  if (hips_move) {
    Channel channel;
    channel.node = kHips;
    channel.path = ChannelPath::translation;
    channel.times = times;
    for (const Keyframe& key : keys) channel.values.insert(channel.values.end(), {key.hips_translation.x, key.hips_translation.y, key.hips_translation.z});
    clip.channels.push_back(std::move(channel));
  }
  for (int joint = 0; joint < kJointCount; ++joint) {
    const std::size_t j = static_cast<std::size_t>(joint);
    const bool moves = std::any_of(keys.begin(), keys.end(),
                                   [&](const Keyframe& k) { return k.rotation[j] != glm::quat(1.0f, 0.0f, 0.0f, 0.0f); });
    if (!moves) continue;
    Channel channel;
    channel.node = joint;
    channel.path = ChannelPath::rotation;
    channel.components = 4;
    channel.times = times;
    glm::quat previous(1.0f, 0.0f, 0.0f, 0.0f);
    for (const Keyframe& key : keys) {
      glm::quat q = glm::normalize(key.rotation[j]);
      if (glm::dot(q, previous) < 0.0f) q = -q;
      previous = q;
      channel.values.insert(channel.values.end(), {q.x, q.y, q.z, q.w});
    }
    clip.channels.push_back(std::move(channel));
  }
  return clip;
}

std::vector<Keyframe> cycle_keys(const std::array<glm::vec3, kJointCount>& p, const Gait& gait) {
  const int intervals = static_cast<int>(std::lround(gait.period * kKeysPerSecond));
  std::vector<Keyframe> keys;
  for (int k = 0; k < intervals; ++k) keys.push_back(gait_key(p, gait, static_cast<float>(k) / static_cast<float>(intervals)));
  keys.push_back(keys.front());  // exact copy: the loop is seamless
  return keys;
}

}  // namespace

std::vector<Clip> build_clips(const std::array<glm::vec3, kJointCount>& p) {
  const Gait walk{1.0f, kWalkSpeed, 0.55f, 0.08f, 0.015f, 0.275f, 0.10f, 0.35f, 0.25f, 0.05f, 0.10f};
  const Gait run{0.7f, kRunSpeed, 0.38f, 0.13f, 0.03f, 0.44f, 0.22f, 0.60f, 1.40f, 0.15f, 0.18f};
  std::vector<Clip> clips;
  clips.push_back(make_clip("walk", cycle_keys(p, walk), walk.period, p));
  clips.push_back(make_clip("run", cycle_keys(p, run), run.period, p));

  constexpr float kWaveDuration = 2.4f;
  const int intervals = static_cast<int>(std::lround(kWaveDuration * kKeysPerSecond));
  std::vector<Keyframe> wave;
  for (int k = 0; k <= intervals; ++k) {
    wave.push_back(wave_key(p, kWaveDuration * static_cast<float>(k) / static_cast<float>(intervals)));
  }
  clips.push_back(make_clip("wave", wave, kWaveDuration, p));
  return clips;
}

}  // namespace proxygi::anim::mannequin
