#pragma once
// The scenes of the speed–accuracy chart: the built-in default scene and one scene per shared
// sample character (CesiumMan, Fox, RiggedSimple from ../shared/assets/gltf); only when `only`
// names them: "pair" (two mannequins 1.5 m apart) and the bounce study's scenes (below).
//
// A character scene is the default scene's stage (ground, sky and sun) with that character
// walking in place at the origin, uniformly scaled so its largest bind-pose extent is 1.7 m,
// feet on the ground (the lowest point of its first frame at y = 0), and a fixed camera at
// (1.6, 1.5, 3.4) m looking at (0, 0.6, 0) so the character and its shadow fill the frame. Its
// proxy rig is cached under `rig_cache_dir` (never next to the shared model).
//
// All chart scenes render SH order `reference_order` lighting in the reference (the highest
// order the proxy method offers); each proxy setting overrides render.sh_order itself.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::study {

struct ChartScene {
  std::string name;              // "default", "CesiumMan", "Fox", "RiggedSimple"
  scene::Scene scene;            // output size set to the chart's
  std::vector<int> frames;       // the frames of motion the chart averages over
};

struct ChartSceneOptions {
  int size = 192;                     // square output, pixels
  int frame_count = 2;                // frames of motion per scene, spread over its clip
  std::filesystem::path shared_dir;   // folder holding assets/gltf; empty: characters skipped
  std::filesystem::path assets_dir;   // the project's assets/ (the mannequin)
  std::filesystem::path rig_cache_dir;
  std::filesystem::path prop_dir;     // generated static meshes (the wall's box); empty: rig_cache_dir
  std::vector<std::string> only;      // when not empty: keep only these scene names (or groups)
};

// `frame_count` frames spread evenly inside [first, first + count): first + (i + 1) count / (n + 1).
std::vector<int> spread_frames(int first, int count, int frame_count);

// The chart's scenes; fails when a shared character cannot be imported. Characters whose file
// is missing are skipped with a warning (so the chart runs without ../shared).
Result<std::vector<ChartScene>> chart_scenes(const ChartSceneOptions& options);

// The bounce study's scenes (chart_study_scenes.cpp), each the default stage with mannequins
// walking in place and a fixed camera, chosen where one bounce method should beat the other:
//   "contact"         one mannequin, the camera low on its feet (proxies should win);
//   "wall-<d>"        one mannequin d m (wall_distances_m) from a 0.2 m x 2.5 m x 8 m box wall on
//                     its left, the face at x = -d; the box is written as OUT prop_dir/chart-wall-box.glb;
//   "pair-<d>"        two mannequins side by side, d m (pair_distances_m) between their axes;
//   "crowd"           the built-in crowd (scene_defaults.h) with its orbiting camera;
//   "wall-corner"     assets/scenes/wall_corner.json (assets_dir): the mannequin walking into a
//                     wall corner with steps, the static meshes the PRT rows (static-ratio,
//                     static-l1) act on.
// Groups in `only`: "wall" = every wall-<d>, "pair-distance" = every pair-<d>.
const std::vector<float>& wall_distances_m();  // 0.5, 1, 2, 4
const std::vector<float>& pair_distances_m();  // 0.5, 1, 2, 5
Result<std::vector<ChartScene>> bounce_study_scenes(const ChartSceneOptions& options,
                                                    const std::function<bool(const std::string&)>& named);
// `names` with the groups replaced by their scenes.
std::vector<std::string> expand_scene_groups(const std::vector<std::string>& names);
// Every name and group `only` (and bench chart --scenes) accepts.
std::vector<std::string> chart_scene_names();

}  // namespace proxygi::study
