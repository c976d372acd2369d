#pragma once
// Overlays drawn with Dear ImGui's background draw list, projected through the frame's camera:
// proxy spheres (their silhouette circles, coloured by bone; the selected bone's drawn white
// and thick; optionally their η·r shells, dimmer), the skeleton (a line from each
// node to its parent, for nodes that are skin joints), the characters' triangle edges (W: skinned
// on the CPU, x-ray: no depth test), and a 1 m ground grid. They are part of
// the UI: hidden with it (F10) and absent from screenshots taken without the UI.
#include "scene/camera.h"
#include "view/viewer_core.h"
#include "world/world.h"

namespace proxygi::view {

// `shadow_eta`: the η of the shells, the one in use (render::FrameTables::shadow_eta).
void draw_overlays(const scene::CameraState& camera, const world::World* world, const world::WorldState& state,
                   const Toggles& toggles, float shadow_eta);

}  // namespace proxygi::view
