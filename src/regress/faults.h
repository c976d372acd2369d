#pragma once
// Known small faults for `regress --sensitivity` (notes/viewer-regression.md §3.6): each is
// applied to a whole run and a tolerance that means something must make some check fail.
//  - joint_0.5deg: the middle joint of instance 0's first skin turned 0.5° about its local X
//    (pose recomputed, proxies re-tracked);
//  - proxy_radius_5pct: the first proxy sphere of instance 0 5 % larger;
//  - clip_time_1frame: characters evaluated one frame late (the camera stays on time);
//  - sh_band_less: SH order one less (4 → 3; 3 → 4 since 2 does not exist);
//  - receivers_2k: receiver scale doubled (k = 4 → 8; 8 → 4).
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "settings/render_settings.h"
#include "world/world.h"

namespace proxygi::regress {

enum class FaultKind { none, joint_rotation, proxy_radius, clip_time, sh_band, receivers };

struct Fault {
  FaultKind kind = FaultKind::none;
  std::string_view name() const;
};

std::vector<Fault> sensitivity_faults();  // every kind but none

// Settings faults (SH band, receivers) change the settings; the others leave them.
void apply_fault(const Fault& fault, settings::RenderSettings& settings);
// The scene time characters are evaluated at for frame time t.
double fault_character_time(const Fault& fault, double t, double fps);
// State faults (joint, proxy radius) change an evaluated state in place.
Status apply_fault(const Fault& fault, const world::World& world, double t, world::WorldState& state);

}  // namespace proxygi::regress
