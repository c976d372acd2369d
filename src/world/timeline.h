#pragma once
// Clip timelines (scene schema version 2, scene::ClipSegment): which clips a character plays at a
// scene time and how they blend. Resolved once per character at World::load (clip names to
// indices, repeat counts to lengths, overlaps refused naming the field), sampled per frame.
//
// Rules (scene.h documents them for the file):
//  - segment k covers [start_k, end_k), end_k = start_k + duration, or start_k + repeat * pass,
//    pass = clip duration / speed (ping_pong: twice that, there and back);
//  - clip time u(t) = clip_offset + speed * (t - start), wrapped by the mode: loop u mod D (the
//    segment's end shows D, not 0), once clamp(u, 0, D), ping_pong a triangle wave of period 2D;
//  - before the first segment: its pose at its start; in a gap and after the last: the previous
//    segment's pose at its end;
//  - segment k with crossfade f > 0 blends into k+1 over [start_{k+1}, start_{k+1} + f): a =
//    segment k continued by its mode from its end (clip time u(end_k + t - start_{k+1})),
//    b = segment k+1, weight (t - start_{k+1}) / f through anim::BlendJob.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "anim/posed_character.h"
#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::world {

struct ResolvedSegment {
  int clip = -1;               // clip index; -1: rest pose (the model has no clips)
  double start_s = 0.0;
  double end_s = 0.0;
  double speed = 1.0;
  double clip_offset_s = 0.0;
  double clip_duration_s = 0.0;
  scene::ClipSegment::Mode mode = scene::ClipSegment::Mode::loop;
  double crossfade_s = 0.0;    // into the next segment
};

struct ResolvedTimeline {
  std::vector<ResolvedSegment> segments;  // empty: the character plays its one clip (version 1)
  bool empty() const { return segments.empty(); }
};

// `path` names the timeline in errors ("characters[0].timeline"); errors name the segment field
// ("characters[0].timeline[2].start: overlaps characters[0].timeline[1] (which ends at 3.2 ...)").
Result<ResolvedTimeline> resolve_timeline(const anim::Character& character, const std::vector<scene::ClipSegment>& segments,
                                          const std::string& path);

// One pose of the timeline: clip a at time_a, blended with clip b at time_b by weight (0: a alone).
struct TimelineSample {
  int clip_a = -1;
  float time_a = 0.0f;
  int clip_b = -1;
  float time_b = 0.0f;
  float weight = 0.0f;
  int segment = 0;  // the segment showing (b's while fading)
};

// Clip time of segment s at scene time t (not clamped to the segment's range), wrapped by its mode.
double segment_clip_time(const ResolvedSegment& segment, double scene_time_s);
TimelineSample sample_timeline(const ResolvedTimeline& timeline, double scene_time_s);

// Samples both clips (anim::SampleClipJob, clamped: the times are already wrapped), blends them
// (anim::BlendJob) and finishes the pose (anim::pose_from_locals) under root_transform.
Status evaluate_timeline_pose(const anim::Character& character, const TimelineSample& sample, anim::PoseBuffers& pose,
                              const glm::mat4& root_transform);

}  // namespace proxygi::world
