#pragma once
// Range and consistency checks on a Scene, shared by the parser and by code that builds scenes.
// Messages name the field as the file spells it: "render.sh_order: must be in 3..6 (got 7)".
// Rules (besides the per-field ranges documented in scene.h):
//  - every number finite; colors >= 0; albedos in [0, 1]; sizes, radii, distances > 0
//  - transform scales > 0; quaternions of unit length within 1e-3
//  - camera near > 0, far > near; fov in [1, 179]; eye != target; up not parallel to the view
//  - follow camera: character index in range; keyframes: at least one, times strictly increasing
//  - walk path: start != end, speed > 0
//  - environment map path ends in .hdr or .exr; model paths non-empty
//  - output: width and height and frame count within settings/limits.h, fps in (0, 1000], first frame >= 0,
//    formats non-empty without repeats
#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::scene {

Status validate_scene(const Scene& scene);

}  // namespace proxygi::scene
