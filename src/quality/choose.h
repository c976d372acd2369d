#pragma once
// render.quality: the settings chosen for one shot from an error target (issue 18 item 3).
//
//   quality::ShotInputs shot = ...;                 // or quality::shot_inputs(world, state, height)
//   quality::QualityChoice choice;
//   quality::ChooseSettingsJob job{.requested = &settings, .shot = &shot, .out = &choice};
//   if (job.validate()) job.run();                  // choice.settings, choice.reasons
//
// With settings.quality == kQualityManual the choice is the requested settings unchanged. With a
// target T it changes only these, every other field as requested:
//   sh_order, receiver_scale, upsampling  the cheapest (by the chart's frame time) of the order ×
//        k × upsampler grid whose predicted error (quality/predictors.h) is <= T; when none is, the
//        one with the lowest predicted error (met = false). A tighter target's feasible set is a
//        subset of a looser one's, so it never costs less;
//   shadow_eta  "auto" (η = √(c_L/ε) from the lighting, sh/influence_eta.h), resolved by the frame;
//   proxy_lod   as requested: the error model has no LOD term and on the chart the LOD raised the
//        chosen setting's error 1.3-1.6x without saving time on lavapipe (choose.cpp); the reasons
//        say whether a coarser level would have been asked for.
// Only image_space frames have these knobs: another method keeps the requested settings (the
// reasons say so). The error model knows nothing of η, LOD, the indirect operator or
// antialiasing: the frames they change are not predicted (README "render.quality").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "scene/camera.h"
#include "settings/render_settings.h"

namespace proxygi::world {
class World;
struct WorldState;
}  // namespace proxygi::world

namespace proxygi::quality {

// One character as the camera sees it.
struct CharacterView {
  float radius_px = 0.0f;   // projected radius of its proxies' bounding sphere, pixels, > 0
  int spheres = 0;          // spheres of its full rig
  std::optional<float> outside_volume_ratio;  // its rig's fit quality, when the rig file has it
};

struct ShotInputs {
  // The environment's unwindowed SH radiance as luminance (Rec. 709), at least order 6 (36),
  // sun included.
  std::vector<double> lighting;
  std::vector<CharacterView> characters;  // may be empty (then k is chosen as for the chart's size)
};

struct QualityChoice {
  settings::RenderSettings settings;  // the settings to render (quality kept as requested)
  bool automatic = false;             // false: manual, settings == requested
  double target = 0.0;                // relative MSE asked for
  double predicted = 0.0;             // predicted relative MSE of the choice
  bool met = false;                   // predicted <= target
  double floor = 0.0;                 // F, the characters' area-weighted floor
  double radius_px = 0.0;             // the characters' area-weighted projected radius
  std::array<double, 4> energy{};     // e(n), n = 3..6
  std::vector<std::string> reasons;   // one line per chosen setting, for summaries and the HUD
};

// One line: "quality balanced (target 0.015): n4 k4 bilinear, eta auto, lod off; predicted 0.0123".
std::string describe(const QualityChoice& choice);

struct ChooseSettingsJob {
  const settings::RenderSettings* requested = nullptr;  // in
  const ShotInputs* shot = nullptr;                      // in
  QualityChoice* out = nullptr;                          // out
  // Inputs present, lighting of order >= 6, every radius > 0 and finite, sphere counts >= 0.
  bool validate() const;
  bool run() const;  // false when validate() fails
};

// The shot's inputs from a world state (world::World::evaluate) seen on `height` pixels: the
// environment at order 6, each character's tracked spheres' bounding sphere projected with the
// state's camera, its rig's sphere count and fit quality.
Result<ShotInputs> shot_inputs(const world::World& world, const world::WorldState& state, std::uint32_t height);

// The choice for `requested` in one shot of `world`: the world evaluated at scene time `time_s`
// with `camera` (the scene's when empty), seen on `height` display pixels × the supersampling
// factor of requested.antialiasing. Manual: `requested` unchanged and nothing evaluated.
Result<QualityChoice> choose_for_shot(const world::World& world, const settings::RenderSettings& requested, double time_s,
                                      const std::optional<scene::CameraState>& camera, std::uint32_t height);

}  // namespace proxygi::quality
