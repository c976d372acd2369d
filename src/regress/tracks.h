#pragma once
// Animation tracks of a scenario, from the CPU world state (no GPU): per frame and instance the
// joints' world matrices (every skin joint; every node when the model has no skin), a seeded
// subset of CPU-skinned vertex positions and the proxy spheres. Stored at full precision
// (tracks.json, %.17g) and compared in millimetres; a rotation counts as the displacement it
// causes at rotation_distance_m (the largest column difference of the 3×3 part times that
// distance), added to the translation error. A change in the proxy count is reported as
// proxies appearing or disappearing.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "regress/results.h"
#include "regress/scenario.h"
#include "regress/scenario_run.h"

namespace proxygi::regress {

struct InstanceTrack {
  std::vector<std::string> joint_names;
  std::vector<glm::dmat4> joints;
  std::vector<glm::dvec3> vertices;
  std::vector<glm::dvec4> proxies;  // center, radius
};
struct FrameTrack {
  int frame = 0;
  std::vector<InstanceTrack> instances;
};
using Tracks = std::vector<FrameTrack>;

Result<Tracks> compute_tracks(const ScenarioRun& run, const Check& check);
std::string tracks_to_json(const Tracks& tracks);
Result<Tracks> tracks_from_json(const std::string& text, const std::string& where);

// Fills series (worst error / tolerance per frame, threshold 1), first_failing_frame, message and
// details ("instance 0 joint LeftFoot diverges from frame 37 by 2.3 mm (tolerance 0.1 mm)").
void compare_tracks(const Tracks& actual, const Tracks& golden, const Check& check, double scale, CheckResult& result);

}  // namespace proxygi::regress
