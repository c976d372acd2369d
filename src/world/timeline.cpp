#include "world/timeline.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "anim/blending.h"
#include "anim/sampling.h"

namespace proxygi::world {
namespace {

std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string segment_path(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

Result<int> resolve_segment_clip(const anim::Character& character, const scene::ClipRef& clip) {
  if (character.clips.empty()) return -1;
  if (const auto* index = std::get_if<int>(&clip)) {
    if (*index < 0 || std::size_t(*index) >= character.clips.size())
      return make_error("clip index " + std::to_string(*index) + " out of range (" + std::to_string(character.clips.size()) +
                        " clips)");
    return *index;
  }
  return anim::find_clip(character, std::get<std::string>(clip));
}

Status sample_clip(const anim::Character& character, int clip, float time, std::span<anim::Transform> locals,
                   std::span<float> morph_weights) {
  if (clip < 0) {
    anim::rest_pose(character, locals);
    anim::default_morph_weights(character, morph_weights);
    return {};
  }
  anim::SampleClipJob job;
  job.character = &character;
  job.clip = &character.clips[std::size_t(clip)];
  job.time = time;
  job.wrap = anim::WrapMode::clamp;
  job.locals = locals;
  job.morph_weights = morph_weights;
  return job.run();
}

}  // namespace

Result<ResolvedTimeline> resolve_timeline(const anim::Character& character, const std::vector<scene::ClipSegment>& segments,
                                          const std::string& path) {
  ResolvedTimeline timeline;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const scene::ClipSegment& in = segments[i];
    const std::string where = segment_path(path, i);
    auto clip = resolve_segment_clip(character, in.clip);
    if (!clip) return make_error(where + ".clip: " + clip.message());
    ResolvedSegment out;
    out.clip = *clip;
    out.start_s = in.start_s;
    out.speed = in.speed;
    out.clip_offset_s = in.clip_offset_s;
    out.clip_duration_s = *clip >= 0 ? double(character.clips[std::size_t(*clip)].duration) : 0.0;
    out.mode = in.mode;
    out.crossfade_s = in.crossfade_s;
    if (in.duration_s) {
      out.end_s = in.start_s + *in.duration_s;
    } else {
      if (!(out.clip_duration_s > 0.0))
        return make_error(where + ".repeat: clip has no duration (give duration instead)");
      const double pass = out.clip_duration_s / out.speed * (in.mode == scene::ClipSegment::Mode::ping_pong ? 2.0 : 1.0);
      out.end_s = in.start_s + double(*in.repeat) * pass;
    }
    if (i > 0) {
      const ResolvedSegment& previous = timeline.segments.back();
      if (previous.end_s > out.start_s + 1e-9)
        return make_error(where + ".start: overlaps " + segment_path(path, i - 1) + " (which ends at " + show(previous.end_s) +
                          " s, this starts at " + show(out.start_s) + " s)");
      if (previous.crossfade_s > out.end_s - out.start_s + 1e-9)
        return make_error(segment_path(path, i - 1) + ".crossfade: " + show(previous.crossfade_s) +
                          " s is longer than the next segment (" + show(out.end_s - out.start_s) + " s)");
    }
    timeline.segments.push_back(out);
  }
  return timeline;
}

double segment_clip_time(const ResolvedSegment& segment, double scene_time_s) {
  const double d = segment.clip_duration_s;
  const double u = segment.clip_offset_s + segment.speed * (scene_time_s - segment.start_s);
  if (!(d > 0.0)) return 0.0;
  switch (segment.mode) {
    case scene::ClipSegment::Mode::once:
      return std::clamp(u, 0.0, d);
    case scene::ClipSegment::Mode::ping_pong: {
      const double phase = std::fmod(std::max(u, 0.0), 2.0 * d);
      return phase > d ? 2.0 * d - phase : phase;
    }
    case scene::ClipSegment::Mode::loop:
    default: {
      const double wrapped = std::fmod(std::max(u, 0.0), d);
      return (wrapped == 0.0 && u > 0.0 && scene_time_s >= segment.end_s) ? d : wrapped;
    }
  }
}

TimelineSample sample_timeline(const ResolvedTimeline& timeline, double t) {
  TimelineSample sample;
  const auto& segments = timeline.segments;
  if (segments.empty()) return sample;
  // The last segment starting at or before t (the first one when t precedes them all).
  std::size_t k = 0;
  while (k + 1 < segments.size() && segments[k + 1].start_s <= t) ++k;
  const ResolvedSegment& segment = segments[k];
  sample.segment = int(k);
  sample.clip_a = segment.clip;
  const double clamped = std::clamp(t, segment.start_s, segment.end_s);
  sample.time_a = float(segment_clip_time(segment, clamped));
  if (k > 0 && t >= segment.start_s) {
    const ResolvedSegment& previous = segments[k - 1];
    if (previous.crossfade_s > 0.0 && t < segment.start_s + previous.crossfade_s) {
      sample.clip_b = sample.clip_a;
      sample.time_b = sample.time_a;
      sample.clip_a = previous.clip;
      sample.time_a = float(segment_clip_time(previous, previous.end_s + (t - segment.start_s)));
      sample.weight = float((t - segment.start_s) / previous.crossfade_s);
    }
  }
  return sample;
}

Status evaluate_timeline_pose(const anim::Character& character, const TimelineSample& sample, anim::PoseBuffers& pose,
                              const glm::mat4& root_transform) {
  pose.locals.resize(character.nodes.size());
  pose.morph_weights.resize(std::size_t(anim::morph_weight_count(character)));
  if (Status s = sample_clip(character, sample.clip_a, sample.time_a, pose.locals, pose.morph_weights); !s)
    return make_error(character.source + ": " + s.message());
  if (sample.weight > 0.0f) {
    std::vector<anim::Transform> locals_b(pose.locals.size());
    std::vector<float> morph_b(pose.morph_weights.size());
    if (Status s = sample_clip(character, sample.clip_b, sample.time_b, locals_b, morph_b); !s)
      return make_error(character.source + ": " + s.message());
    anim::BlendJob blend;
    blend.a = pose.locals;
    blend.b = locals_b;
    blend.morph_a = pose.morph_weights;
    blend.morph_b = morph_b;
    blend.weight = sample.weight;
    blend.output = pose.locals;
    blend.morph_output = pose.morph_weights;
    if (Status s = blend.run(); !s) return make_error(character.source + ": blend: " + s.message());
  }
  return anim::pose_from_locals(character, pose, root_transform);
}

}  // namespace proxygi::world
