#pragma once
// Levels of detail of a character's proxies without pops (issue 18 item 2; render.proxy_lod).
//
// Levels are nested sphere sets built from the fitted rig, not by the fit: level 0 is the rig
// itself (one sphere per rig sphere); each coarser level merges pairs of the finer level's
// spheres bottom-up (within one bone chain while a chain has two, then across chains), about
// halving the count down to a minimum (rig 32 → 16 → 8). A level sphere stands for a set of rig
// spheres (its members) and holds spheres of the next finer level (its children); every frame it
// is the bounding sphere (culling.h bounding_sphere: volume-weighted centroid, radius reaching
// every child) of its children as tracked, so it covers the finer level in every pose and
// follows the bones its members follow.
//
//   LodLevels levels;
//   BuildLodLevelsJob build{rest_spheres, chain_groups(rig, character), nodes, 8, &levels};
//   build.run();                                     // once per model
//   LodChoice choice = chooser.step(choice, radius_px);  // once per frame and character
//   append_lod_spheres(levels, choice, chooser.fade(choice), tracked, scratch, out);
//
// Cross-fade: the shaders accumulate weight × log-visibility (render::Sphere::weight), and the
// log sum is linear, so streaming level A with weight 1 − t and level B with weight t gives
// exactly f = (1 − t) Σ_A + t Σ_B; t steps by 1/fade_frames per frame. A level sphere present
// in both levels (the same members) is streamed once with weight 1, which is the same sum.
#include <span>
#include <vector>

#include "base/result.h"
#include "proxies/tracking.h"

namespace proxygi::proxies {

struct LodSphere {
  std::vector<int> members;   // rig sphere indices it stands for, ascending, not empty
  std::vector<int> children;  // indices into the next finer level, ascending (level 0: empty)
  int node = -1;              // bone node of its largest member (its binding, for people)
  int coarser = -1;           // index of the sphere of the next coarser level holding it (-1: coarsest)
};

struct LodLevel {
  std::vector<LodSphere> spheres;
};

struct LodLevels {
  std::vector<LodLevel> levels;  // [0]: the rig, sphere i = rig sphere i; counts strictly decreasing
  std::vector<int> counts() const;  // spheres per level, finest first
};

struct BuildLodLevelsJob {
  // Inputs: the rig's spheres tracked in one reference pose (the rest pose), world space, with
  // their chain (chain_groups) and bone node; merges are chosen by bounding volumes there.
  std::span<const WorldSphere> spheres;
  std::span<const int> groups;  // one per sphere
  std::span<const int> nodes;   // one per sphere
  int min_spheres = 8;          // the coarsest level's count (>= 1); a rig no larger has one level
  // Output.
  LodLevels* levels = nullptr;

  Status validate() const;  // sizes, min_spheres >= 1, finite spheres with radius > 0
  Status run() const;       // validate(), then build
};

// The levels' invariants against `spheres` (the same reference spheres, or any pose's): level 0
// is the rig; counts strictly decrease; every level partitions the rig spheres; a sphere's
// children are exactly the finer spheres naming it as `coarser` and its members the union of
// theirs (nesting); and each level sphere, evaluated as below, covers every child within
// `tolerance` meters (coverage). Errors name the level and sphere ("level 2 sphere 3: ...").
Status validate_lod_levels(const LodLevels& levels, std::span<const WorldSphere> spheres, float tolerance = 1e-5f);

// Levels 0..last from the tracked rig spheres: out[k][i] is level k's sphere i, the bounding
// sphere of its children (one child: the child as it is). out is resized; no other allocation
// once it has the size.
void evaluate_lod_levels(const LodLevels& levels, int last, std::span<const WorldSphere> tracked,
                         std::vector<std::vector<WorldSphere>>& out);

// What a character streams: level `to` with share t = fade(choice), level `from` with 1 − t.
// Settled when from == to (frames_into_fade 0).
struct LodChoice {
  int from = 0;
  int to = 0;
  int frames_into_fade = 0;  // 1..fade_frames - 1 while fading
  bool operator==(const LodChoice&) const = default;
};

struct LodChooser {
  std::vector<int> counts;          // spheres per level, finest first (LodLevels::counts)
  float pixels_per_sphere = 4.0f;   // a level is enough while count >= radius_px / this
  float hysteresis = 0.15f;         // switch only past the switch point × (1 ± this), in [0, 1)
  int fade_frames = 16;             // frames a change of level takes (1: a hard switch)

  // Memoryless: the coarsest level with count >= radius_px / pixels_per_sphere (the finest when
  // none has). radius_px: the character's bounding sphere's projected radius, pixels.
  int level_for(float radius_px) const;
  // One frame: a fade in progress advances (and ends after fade_frames frames); a settled choice
  // starts a fade to level_for(radius_px) only when level_for(radius_px × (1 ∓ hysteresis)) also
  // leaves the current level (finer: radius × (1 − h); coarser: radius × (1 + h)).
  LodChoice step(const LodChoice& choice, float radius_px) const;
  // The share of `to`: frames_into_fade / fade_frames, 1 when settled.
  float fade(const LodChoice& choice) const;
};

// Appends the spheres of `choice` (render order: `from`'s spheres, then `to`'s not shared with
// it) as (sphere, weight) pairs; weight-0 spheres are left out.
struct WeightedSphere {
  WorldSphere sphere;
  float weight = 1.0f;
};
// `scratch` holds the evaluated levels (evaluate_lod_levels) between calls.
void append_lod_spheres(const LodLevels& levels, const LodChoice& choice, float fade,
                        std::span<const WorldSphere> tracked, std::vector<std::vector<WorldSphere>>& scratch,
                        std::vector<WeightedSphere>& out);

// Projected radius (pixels) of a world-space sphere seen from `eye` with focal length
// `focal_pixels` (viewport height / (2 tan(fov_y / 2))): radius × focal / distance, the
// distance at least the radius (a camera inside counts as the whole screen).
float projected_radius_pixels(const glm::vec3& center, float radius, const glm::vec3& eye, float focal_pixels);

}  // namespace proxygi::proxies
