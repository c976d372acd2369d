// Animations: one Clip per glTF animation, one Channel per glTF channel with its sampler's
// times and outputs decoded (quantized rotations and weights included) and checked.
#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "anim/import_accessor.h"
#include "anim/import_context.h"

namespace proxygi::anim::detail {
namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

Result<Interpolation> parse_interpolation(const std::string& name, const std::string& what) {
  if (name.empty() || name == "LINEAR") return Interpolation::linear;
  if (name == "STEP") return Interpolation::step;
  if (name == "CUBICSPLINE") return Interpolation::cubic_spline;
  return error_at(what, "unknown interpolation \"" + name + "\"");
}

Result<ChannelPath> parse_path(const std::string& name, const std::string& what) {
  if (name == "translation") return ChannelPath::translation;
  if (name == "rotation") return ChannelPath::rotation;
  if (name == "scale") return ChannelPath::scale;
  if (name == "weights") return ChannelPath::weights;
  return error_at(what, "unsupported target path \"" + name + "\"");
}

Result<std::vector<float>> read_times(ImportContext& ctx, int accessor, const std::string& what) {
  auto input = read_float_accessor(ctx, accessor, what, {TINYGLTF_TYPE_SCALAR}, {kFloat});
  if (!input) return input.error();
  std::vector<float>& times = input->values;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (times[k] < 0.0f) {
      return error_at(what, "key " + std::to_string(k) + " time " + std::to_string(times[k]) +
                                " is negative");
    }
    if (k > 0 && !(times[k] > times[k - 1])) {
      return error_at(what, "key " + std::to_string(k) + " time " + std::to_string(times[k]) +
                                " is not greater than key " + std::to_string(k - 1) + " time " +
                                std::to_string(times[k - 1]));
    }
  }
  return std::move(input->values);
}

// Morph target count of the mesh on `node`, or an error when it has none.
Result<int> morph_target_count(const Character& character, int node, const std::string& what) {
  const int mesh = character.nodes[static_cast<std::size_t>(node)].mesh;
  if (mesh < 0) return error_at(what, "animates weights of node " + std::to_string(node) + " which has no mesh");
  const auto& primitives = character.meshes[static_cast<std::size_t>(mesh)].primitives;
  const std::size_t targets = primitives.empty() ? 0 : primitives[0].morph_targets.size();
  if (targets == 0) {
    return error_at(what, "animates weights of node " + std::to_string(node) + " but mesh " +
                              std::to_string(mesh) + " has no morph targets");
  }
  return static_cast<int>(targets);
}

Result<Channel> convert_channel(ImportContext& ctx, const Character& character,
                                const tinygltf::Animation& animation, std::size_t index,
                                const std::string& what) {
  const tinygltf::AnimationChannel& source = animation.channels[index];
  Channel channel;
  if (source.sampler < 0 || static_cast<std::size_t>(source.sampler) >= animation.samplers.size()) {
    return error_at(what, "sampler " + std::to_string(source.sampler) + " out of range (" +
                              std::to_string(animation.samplers.size()) + " samplers)");
  }
  if (source.target_node < 0 || static_cast<std::size_t>(source.target_node) >= character.nodes.size()) {
    return error_at(what, "target node " + std::to_string(source.target_node) + " out of range (" +
                              std::to_string(character.nodes.size()) + " nodes)");
  }
  channel.node = source.target_node;
  if (character.nodes[static_cast<std::size_t>(channel.node)].matrix) {
    return error_at(what, "animates node " + std::to_string(channel.node) +
                              " which has a matrix (only TRS nodes may be animated)");
  }
  auto path = parse_path(source.target_path, what);
  if (!path) return path.error();
  channel.path = *path;

  const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(source.sampler)];
  const std::string sampler_what = what + " sampler " + std::to_string(source.sampler);
  auto interpolation = parse_interpolation(sampler.interpolation, sampler_what);
  if (!interpolation) return interpolation.error();
  channel.interpolation = *interpolation;
  auto times = read_times(ctx, sampler.input, sampler_what + " input");
  if (!times) return times.error();
  channel.times = std::move(*times);
  const bool cubic = channel.interpolation == Interpolation::cubic_spline;
  if (cubic && channel.times.size() < 2) {
    return error_at(sampler_what, "CUBICSPLINE needs at least 2 keys, has " +
                                      std::to_string(channel.times.size()));
  }

  std::vector<int> component_types = {kFloat};
  int type = TINYGLTF_TYPE_VEC3;
  channel.components = 3;
  if (channel.path == ChannelPath::rotation) {
    type = TINYGLTF_TYPE_VEC4;
    channel.components = 4;
    component_types = {kFloat, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                       TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  } else if (channel.path == ChannelPath::weights) {
    auto targets = morph_target_count(character, channel.node, what);
    if (!targets) return targets.error();
    type = TINYGLTF_TYPE_SCALAR;
    channel.components = *targets;
    component_types = {kFloat, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                       TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  }
  auto output = read_float_accessor(ctx, sampler.output, sampler_what + " output", {type}, component_types);
  if (!output) return output.error();
  const std::uint64_t per_key = (cubic ? 3u : 1u) * static_cast<std::uint64_t>(channel.components);
  const std::uint64_t expected = per_key * channel.times.size();
  if (output->values.size() != expected) {
    return error_at(sampler_what + " output",
                    std::to_string(output->values.size() / static_cast<std::size_t>(output->components)) +
                        " elements for " + std::to_string(channel.times.size()) + " keys (expected " +
                        std::to_string(expected / static_cast<std::uint64_t>(output->components)) + ")");
  }
  channel.values = std::move(output->values);
  if (channel.path == ChannelPath::rotation && !cubic) {
    // Decoded (possibly quantized) keys are renormalized so samplers start from unit quaternions.
    for (std::size_t k = 0; k < channel.times.size(); ++k) {
      float* q = channel.values.data() + 4 * k;
      const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(length > 1e-6f)) {
        return error_at(sampler_what + " output", "rotation key " + std::to_string(k) + " has zero length");
      }
      for (int c = 0; c < 4; ++c) q[c] /= length;
    }
  }
  return channel;
}

}  // namespace

Status import_animations(ImportContext& ctx, Character& character) {
  character.clips.clear();
  for (std::size_t a = 0; a < ctx.model.animations.size(); ++a) {
    const tinygltf::Animation& animation = ctx.model.animations[a];
    const std::string what = "animation " + std::to_string(a);
    if (animation.channels.size() > ctx.limits.max_objects) {
      return error_at(what, std::to_string(animation.channels.size()) + " channels exceed the limit of " +
                                std::to_string(ctx.limits.max_objects));
    }
    Clip clip;
    clip.name = animation.name;
    std::set<std::pair<int, int>> targets;
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const std::string channel_what = what + " channel " + std::to_string(c);
      auto channel = convert_channel(ctx, character, animation, c, channel_what);
      if (!channel) return channel.error();
      if (!targets.emplace(channel->node, static_cast<int>(channel->path)).second) {
        return error_at(channel_what, "targets node " + std::to_string(channel->node) + " " +
                                          animation.channels[c].target_path + " a second time");
      }
      clip.duration = std::max(clip.duration, channel->times.back());
      clip.channels.push_back(std::move(*channel));
    }
    character.clips.push_back(std::move(clip));
  }
  return {};
}

}  // namespace proxygi::anim::detail
