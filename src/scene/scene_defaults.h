#pragma once
// The built-in scenes, used when no scene file is given and exported (by the scene tests' writer
// check and `save_scene`) as assets/scenes/default.json and assets/scenes/crowd.json.
//
// Both use "builtin:mannequin" with the clips named "walk" and "run", played in place and moved
// by a WalkPath; colors are chosen so bounce light shows (light gray ground, the mannequin's
// red shirt comes from its own material).
#include "scene/scene.h"

namespace proxygi::scene {

// One mannequin walking 4.8 m along +X (x = -2.4 .. 2.4, 1.2 m/s) across a 20 m light gray
// ground under a blue sky with a warm sun behind and to the right of it (shadow falls toward
// the camera); a fixed camera frames the whole walk. 512 x 512, 24 fps, 96 frames (4 s).
Scene default_scene();

// Twenty mannequins on a 5 x 4 grid for benchmarks: rows alternate walking (1.2 m/s) and
// running (3 m/s) and their direction, each row moving in step ping-pong over 6 m lanes with
// varied clip phases; an orbiting camera. 512 x 512, 24 fps, 120 frames (5 s).
Scene crowd_scene();

}  // namespace proxygi::scene
