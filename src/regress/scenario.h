#pragma once
// Scenario files for `proxygi regress` (README "Regression scenarios"): a scene (a file, a
// built-in, or inline) with overrides, checkpoints (frames) and checks. Parsed with the scene
// library's field-path reader: unknown keys are refused, every error names the file and field
// ("walk.json: checks[2].pixel_threshold: must be >= 0 (got -1)").
//
//   {"scenario_version": 1, "scene": "builtin:default" | "shot.json" | {...scene...},
//    "overrides": {"render.sh_order": 3, "output.width": 96},
//    "checkpoints": [0, 12, 24],
//    "checks": [{"name": "frame", "type": "image", ...}, ...]}
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "scene/scene.h"

namespace proxygi::regress {

inline constexpr int kScenarioVersion = 1;

enum class CheckType { image, tracks, temporal, differential, budget };
enum class Region { all, ground, character };           // from the G-buffer: ground y = 0, character the rest
enum class Aov { final_frame, irradiance, albedo };     // what an image check compares
enum class DifferentialKind { settings, repeat, shard };

// Overrides: "render.<field>" (settings::fields()), "output.width|height|fps|frames.first|frames.count".
using Overrides = std::map<std::string, double>;  // choice fields store their enumerator value

struct ImageTolerance {
  int pixel_threshold = 5;              // 8-bit codes, any channel
  double max_failing_fraction = 0.001;  // of the region's pixels
  std::optional<double> flip_mean;      // LDR-FLIP mean over the region, at most
  std::optional<double> flip_percentile;       // which percentile (0..1] ...
  std::optional<double> flip_percentile_max;   // ... must be at most this
  int shift_radius = 0;                 // a pixel passes when a golden pixel within this radius matches
};

struct TrackTolerance {
  double joint_mm = 0.1;            // joint position, millimetres
  double rotation_distance_m = 0.1; // rotations judged by the displacement they cause this far away
  double vertex_mm = 0.1;
  double proxy_mm = 0.1;            // centers and radii
};

struct Check {
  std::string name;                 // [A-Za-z0-9_-]+, unique in the scenario
  CheckType type = CheckType::image;
  std::vector<int> frames;          // the scenario's checkpoints unless given
  // image, temporal, differential
  Aov aov = Aov::final_frame;
  Region region = Region::all;
  ImageTolerance image;
  double fallback_scale = 2.0;      // a golden from the fallback tier ("any") loosens thresholds by this
  // tracks
  bool joints = true;
  int vertices = 32;                // seeded subset of skinned vertices per instance
  std::uint32_t seed = 1;
  bool proxies = true;
  TrackTolerance tracks;
  // temporal: mean |frame-to-frame change| (codes) of the region vs the golden's, per frame pair
  double temporal_tolerance = 0.25;
  // differential
  DifferentialKind kind = DifferentialKind::repeat;
  Overrides a, b;                   // settings: the two sides
  // budget: milliseconds per frame for a device pattern (substring of the device name or family)
  std::vector<std::pair<std::string, double>> budgets;
  int runs = 3;                     // median of this many timed runs
  int timed_frames = 4;
};

struct Scenario {
  std::string name;                 // file stem
  std::filesystem::path file;
  scene::Scene scene;               // overrides applied
  std::vector<int> checkpoints;
  std::vector<Check> checks;
  // "requires": files or folders (relative to the scenario) without which every check is
  // skipped, e.g. the shared sample characters in ../shared/assets.
  std::vector<std::filesystem::path> requires_paths;
  bool requirements_met() const;
};

Result<Scenario> parse_scenario(std::string_view json_text, const std::filesystem::path& file,
                                const std::filesystem::path& assets_dir);
Result<Scenario> load_scenario(const std::filesystem::path& file, const std::filesystem::path& assets_dir);
// SCENARIO files and folders (every *.json directly inside a folder that holds "scenario_version"),
// sorted by name; names must be unique.
Result<std::vector<Scenario>> load_scenarios(const std::vector<std::filesystem::path>& inputs,
                                             const std::filesystem::path& assets_dir);

// Applies overrides (keys above) to a scene; errors name the key.
Status apply_overrides(scene::Scene& scene, const Overrides& overrides);

std::string_view check_type_name(CheckType type);

}  // namespace proxygi::regress
