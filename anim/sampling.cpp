#include "anim/sampling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "anim/blending.h"

namespace proxygi::anim {
namespace {

std::string channel_name(const Clip& clip, std::size_t index) {
  return "clip '" + clip.name + "' channel " + std::to_string(index);
}

int expected_components(const Character& character, const Channel& channel) {
  switch (channel.path) {
    case ChannelPath::translation:
    case ChannelPath::scale: return 3;
    case ChannelPath::rotation: return 4;
    case ChannelPath::weights: return morph_target_count(character, channel.node);
  }
  return -1;
}

// Hermite basis with tangents scaled by the key interval t_d (glTF Appendix C).
float hermite(float v0, float b0, float v1, float a1, float u, float t_d) {
  const float u2 = u * u;
  const float u3 = u2 * u;
  return (2.0f * u3 - 3.0f * u2 + 1.0f) * v0 + t_d * (u3 - 2.0f * u2 + u) * b0 +
         (-2.0f * u3 + 3.0f * u2) * v1 + t_d * (u3 - u2) * a1;
}

// Copies the value of key k: for CUBICSPLINE the value sits between the two tangents.
void copy_key(const Channel& channel, std::size_t k, std::span<float> out) {
  const std::size_t n = static_cast<std::size_t>(channel.components);
  const std::size_t stride = channel.interpolation == Interpolation::cubic_spline ? 3 * n : n;
  const std::size_t offset = channel.interpolation == Interpolation::cubic_spline ? n : 0;
  const float* key = channel.values.data() + k * stride + offset;
  std::copy(key, key + n, out.begin());
}

}  // namespace

float wrap_time(float time, float duration, WrapMode wrap) {
  if (!(duration > 0.0f) || !std::isfinite(time)) return 0.0f;
  if (wrap == WrapMode::clamp) return std::clamp(time, 0.0f, duration);
  float wrapped = std::fmod(time, duration);
  if (wrapped < 0.0f) wrapped += duration;
  return wrapped >= duration ? 0.0f : wrapped;  // fmod of a value just below 0 can round up
}

int morph_target_count(const Character& character, int node) {
  if (node < 0 || node >= static_cast<int>(character.nodes.size())) return 0;
  const int mesh = character.nodes[static_cast<std::size_t>(node)].mesh;
  if (mesh < 0 || mesh >= static_cast<int>(character.meshes.size())) return 0;
  const Mesh& m = character.meshes[static_cast<std::size_t>(mesh)];
  std::size_t count = m.default_morph_weights.size();
  for (const Primitive& primitive : m.primitives) count = std::max(count, primitive.morph_targets.size());
  return static_cast<int>(count);
}

int morph_weight_offset(const Character& character, int node) {
  int offset = 0;
  for (int i = 0; i < node; ++i) offset += morph_target_count(character, i);
  return offset;
}

int morph_weight_count(const Character& character) {
  return morph_weight_offset(character, static_cast<int>(character.nodes.size()));
}

void default_morph_weights(const Character& character, std::span<float> weights) {
  std::size_t offset = 0;
  for (std::size_t i = 0; i < character.nodes.size(); ++i) {
    const std::size_t count = static_cast<std::size_t>(morph_target_count(character, static_cast<int>(i)));
    if (count == 0) continue;
    const Node& node = character.nodes[i];
    const std::vector<float>& source = !node.morph_weights.empty()
                                           ? node.morph_weights
                                           : character.meshes[static_cast<std::size_t>(node.mesh)].default_morph_weights;
    for (std::size_t k = 0; k < count; ++k) weights[offset + k] = k < source.size() ? source[k] : 0.0f;
    offset += count;
  }
}

void rest_pose(const Character& character, std::span<Transform> locals) {
  for (std::size_t i = 0; i < character.nodes.size(); ++i) locals[i] = character.nodes[i].rest;
}

void sample_channel(const Channel& channel, float time, std::span<float> out) {
  const std::vector<float>& times = channel.times;
  const std::size_t n = static_cast<std::size_t>(channel.components);
  // Clamp outside the key range; this also covers one-key channels.
  if (times.size() == 1 || time <= times.front()) return copy_key(channel, 0, out);
  if (time >= times.back()) return copy_key(channel, times.size() - 1, out);

  // k: last key with times[k] <= time (exists because time > times.front()).
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
  if (times[k] == time || channel.interpolation == Interpolation::step) return copy_key(channel, k, out);

  const float t_d = times[k + 1] - times[k];
  const float u = (time - times[k]) / t_d;
  if (channel.interpolation == Interpolation::linear) {
    const float* a = channel.values.data() + k * n;
    const float* b = a + n;
    if (channel.path == ChannelPath::rotation) {
      const glm::quat q = slerp_shortest(glm::quat(a[3], a[0], a[1], a[2]), glm::quat(b[3], b[0], b[1], b[2]), u);
      out[0] = q.x; out[1] = q.y; out[2] = q.z; out[3] = q.w;
      return;
    }
    for (std::size_t c = 0; c < n; ++c) out[c] = a[c] * (1.0f - u) + b[c] * u;
    return;
  }

  // CUBICSPLINE: key layout is in-tangent a, value v, out-tangent b (n floats each).
  const float* key0 = channel.values.data() + k * 3 * n;
  const float* key1 = key0 + 3 * n;
  for (std::size_t c = 0; c < n; ++c) out[c] = hermite(key0[n + c], key0[2 * n + c], key1[n + c], key1[c], u, t_d);
  if (channel.path == ChannelPath::rotation) {
    const float length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
    if (length > 0.0f) {
      for (std::size_t c = 0; c < 4; ++c) out[c] /= length;
    } else {  // degenerate spline: hold the previous key
      copy_key(channel, k, out);
    }
  }
}

Status SampleClipJob::validate() const {
  if (character == nullptr || clip == nullptr) return make_error("sample: character and clip are required");
  if (locals.size() != character->nodes.size()) {
    return make_error("sample: locals holds " + std::to_string(locals.size()) + " transforms, character has " +
                      std::to_string(character->nodes.size()) + " nodes");
  }
  if (!morph_weights.empty() && morph_weights.size() != static_cast<std::size_t>(morph_weight_count(*character))) {
    return make_error("sample: morph_weights holds " + std::to_string(morph_weights.size()) + " floats, expected " +
                      std::to_string(morph_weight_count(*character)));
  }
  for (std::size_t i = 0; i < clip->channels.size(); ++i) {
    const Channel& channel = clip->channels[i];
    if (channel.node < 0 || channel.node >= static_cast<int>(character->nodes.size())) {
      return make_error(channel_name(*clip, i) + ": node " + std::to_string(channel.node) + " out of range (" +
                        std::to_string(character->nodes.size()) + " nodes)");
    }
    const int components = expected_components(*character, channel);
    if (channel.components != components || components <= 0) {
      return make_error(channel_name(*clip, i) + ": " + std::to_string(channel.components) +
                        " components, expected " + std::to_string(components));
    }
    if (channel.times.empty()) return make_error(channel_name(*clip, i) + ": no keys");
    const std::size_t per_key = static_cast<std::size_t>(components) *
                                (channel.interpolation == Interpolation::cubic_spline ? 3u : 1u);
    if (channel.values.size() != channel.times.size() * per_key) {
      return make_error(channel_name(*clip, i) + ": " + std::to_string(channel.values.size()) + " values for " +
                        std::to_string(channel.times.size()) + " keys, expected " +
                        std::to_string(channel.times.size() * per_key));
    }
  }
  return {};
}

Status SampleClipJob::run() const {
  if (Status status = validate(); !status) return status;
  rest_pose(*character, locals);
  if (!morph_weights.empty()) default_morph_weights(*character, morph_weights);
  const float t = wrap_time(time, clip->duration, wrap);
  float value[4];
  for (const Channel& channel : clip->channels) {
    Transform& local = locals[static_cast<std::size_t>(channel.node)];
    switch (channel.path) {
      case ChannelPath::translation:
        sample_channel(channel, t, value);
        local.translation = glm::vec3(value[0], value[1], value[2]);
        break;
      case ChannelPath::scale:
        sample_channel(channel, t, value);
        local.scale = glm::vec3(value[0], value[1], value[2]);
        break;
      case ChannelPath::rotation:
        sample_channel(channel, t, value);
        local.rotation = glm::quat(value[3], value[0], value[1], value[2]);
        break;
      case ChannelPath::weights:
        if (morph_weights.empty()) break;
        sample_channel(channel, t,
                       morph_weights.subspan(static_cast<std::size_t>(morph_weight_offset(*character, channel.node)),
                                             static_cast<std::size_t>(channel.components)));
        break;
    }
  }
  return {};
}

}  // namespace proxygi::anim
