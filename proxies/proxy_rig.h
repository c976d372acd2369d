#pragma once
// ProxyRig: a character's sphere proxies as fitted (proxies/fit.h) or loaded from a
// `*.proxies.json` file (proxies/rig_file.h), bound to its skeleton by node index
// (names are kept for people; glTF allows empty and repeated node names).
//
// Spaces and units: a sphere's center is in the bone space of its bone node (the node's local
// frame, where world = node_world[bone] * center), meters; its radius is in that same space.
// Albedo is linear RGB (the mean base color of the surface the sphere stands for).
//
// Binding (how tracking moves a sphere, proxies/tracking.h):
//  - rigid:   center_world = node_world[bone] * center.
//  - blended: center_world = sum_k w_k * node_world[n_k] * center_in(n_k), the sphere's bind
//             position carried by the mean skin weights {n_k, w_k} of the vertices it stands for
//             (linear blend skinning of the center).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace proxygi::proxies {

inline constexpr int kSphereWeights = 4;

enum class Binding { rigid, blended };
const char* binding_name(Binding binding);

struct ProxySphere {
  std::string bone;            // name of the bone node, for people (may be empty or repeated)
  int node = -1;               // node index of the bone (a joint, or the node of an unskinned mesh): the binding
  glm::vec3 center{0.0f};      // bone space, meters
  float radius = 0.0f;         // bone space, meters, > 0
  glm::vec3 albedo{1.0f};      // linear RGB in [0, 1]
  // Mean skin weights, largest first; unused slots have node -1. Empty (all -1) means the
  // sphere follows its bone only, whatever the rig's binding.
  std::array<int, kSphereWeights> weight_nodes{-1, -1, -1, -1};
  std::array<float, kSphereWeights> weights{0.0f, 0.0f, 0.0f, 0.0f};
  int source_line = 0;         // line in the rig file it came from (0 when fitted)
};

// Measured quality of a fit (proxies/quality.h); distances in meters (bind space).
struct FitQuality {
  float coverage = 0.0f;                   // fraction of surface samples within tolerance
  float outside_volume_ratio = 0.0f;       // sphere volume outside the mesh / union volume
  float hausdorff_surface_to_spheres = 0.0f;
  float hausdorff_spheres_to_surface = 0.0f;
  float mean_surface_to_spheres = 0.0f;
  int surface_samples = 0;
  int volume_samples = 0;
};

// Tracking error of one binding over animation (proxies/binding_eval.h), meters.
struct BindingError {
  float worst_poke_out = 0.0f;  // max over frames, spheres and represented points
  float mean_poke_out = 0.0f;   // mean over frames and spheres of each sphere's max poke-out
};

struct ProxyRig {
  static constexpr int kSchemaVersion = 2;
  std::string model;              // model file name the rig was fitted to
  std::string model_hash;         // "fnv1a64:<16 hex digits>" of the model file's bytes
  Binding binding = Binding::blended;
  float tolerance = 0.0f;         // relative to the bind-pose bounding-box diagonal
  int max_spheres = 0;
  int fit_version = 0;            // kFitVersion of the fit that made it (0: unknown)
  float diagonal = 0.0f;          // bind-pose bounding-box diagonal, meters
  std::vector<ProxySphere> spheres;
  // Informational, written by fit and shown by `info`; not used by tracking.
  bool has_quality = false;
  FitQuality quality;
  double fit_seconds = 0.0;
  int frames_evaluated = 0;
  BindingError rigid_error;
  BindingError blended_error;
  std::vector<std::string> warnings;
};

// A short human-readable description of a rig (for `proxygi info`): sphere count, spheres per
// bone, radius range, binding, quality when present.
struct RigSummary {
  int sphere_count = 0;
  int bone_count = 0;                 // bones with at least one sphere
  float min_radius = 0.0f, max_radius = 0.0f, total_volume = 0.0f;  // bone space, meters / m³
  // Label ("name", or "name#node" / "#node" when the name is empty or shared) and count, in
  // first-appearance order, one entry per bone node.
  std::vector<std::pair<std::string, int>> spheres_per_bone;
};
RigSummary summarize_rig(const ProxyRig& rig);
std::string format_rig_summary(const ProxyRig& rig);

}  // namespace proxygi::proxies
