#pragma once
// Fitting sphere proxies to a character's bones, in the bind pose (offline; results are cached
// as `*.proxies.json`, proxies/rig_file.h).
//
//   FitResult fit;
//   FitProxiesJob job;
//   job.character = &character;
//   job.options.tolerance = 0.05f;   // 5 % of the bind-pose bounding-box diagonal
//   job.result = &fit;
//   if (Status s = job.run(); !s) return s;   // fit.rig.spheres: bone space, meters
//
// Algorithm (variational sphere-set approximation per bone; proxies/sphere_set_fit.h):
//  1. Bind surface: every mesh instance in bind space (proxies/bind_surface.h), welded with
//     OpenMesh for areas and open-edge counts; each vertex's dominant bone.
//  2. Signed distance grid (cell = diagonal / grid_resolution) from exact point–triangle
//     distances and winding-number inside tests (proxies/mesh_index.h).
//  3. Points: area-stratified surface samples, the mesh vertices, and one jittered point per
//     inside grid node. Each point belongs to the dominant bone of its influences (interior
//     points: of the nearest surface sample).
//  4. Every bone with points starts with one sphere. Then, over the whole character, the sphere
//     with the largest protrusion is split and its bone re-clustered, until every sphere's
//     protrusion is at most tolerance × diagonal or max_spheres is reached. A bone with no
//     points gets no sphere. Spheres come within surface_slack × tolerance × diagonal of their
//     points rather than bounding them, so a limb becomes a chain of spheres thinner than it
//     (coverage, measured at the tolerance, stays whole). Once no protrusion exceeds the
//     tolerance, the sphere with the largest outside volume is split while the spheres' outside
//     volume exceeds outside_target of their volume (bones warned flat or open excepted).
//  5. Teleport (VSSA; proxies/teleport.h): a sphere is split where the spheres bulge most out of
//     the mesh and, to keep the count, the sphere whose removal costs least (keeping every
//     protrusion within max(tolerance, the worst before)) is dropped, each bone re-clustered,
//     while that lowers the summed outside volume (teleport_candidates splits tried per move,
//     up to teleport_worsening non-improving moves in a row explored, the best state kept).
//  6. Per sphere: albedo = mean linear base color of its surface samples; mean skin weights of
//     its surface samples and vertices (largest four, renormalized); center and radius mapped
//     to bone space with the bone's bind_to_bone matrix (radius scaled by its largest axis).
// Warnings (never errors) name bones whose region is flat (smallest principal extent below a
// quarter of the middle one, and wider than the tolerance) or has no interior points: a sphere
// set can only over-cover such parts.
#include <cstdint>
#include <string>
#include <vector>

#include "anim/character.h"
#include "proxies/quality.h"
#include "base/result.h"
#include "proxies/bind_surface.h"
#include "proxies/point_sampling.h"
#include "proxies/proxy_rig.h"
#include "proxies/teleport.h"

namespace proxygi::proxies {

// The fit algorithm's version, stored in rigs; a cached rig of another version is refitted.
inline constexpr int kFitVersion = 2;

struct FitOptions {
  float tolerance = 0.05f;    // allowed protrusion, relative to the bounding-box diagonal (> 0)
  int max_spheres = 96;       // cap over the whole character (>= 1)
  int surface_samples = 8000; // fitting samples on the surface
  int interior_samples = 8000;// cap on interior points
  int grid_resolution = 100;  // distance-grid cells along the diagonal
  int lloyd_iterations = 6;   // re-clustering passes after each split
  float surface_slack = 0.5f; // how far a point may lie outside its sphere, × tolerance, [0, 1)
  float outside_target = 0.2f;  // split further while the spheres' outside volume share exceeds it
  int teleport_rounds = 64;   // cap on teleport moves (0: none; proxies/teleport.h)
  int teleport_candidates = 1;  // splits tried per teleport move (>= 1)
  int teleport_worsening = 0;   // worsening teleport moves allowed in a row (>= 0)
  std::uint64_t seed = 1;
};

// A fitted sphere in bind space with the points it stands for (for quality and tracking).
struct FittedSphere {
  int bone = -1;
  glm::vec3 center{0.0f};  // bind space
  float radius = 0.0f;     // bind space
  float protrusion = 0.0f; // meters, measured on the distance grid
  std::vector<std::uint32_t> samples;  // indices into FitResult::samples it stands for
};

struct FitResult {
  ProxyRig rig;                        // spheres in bone space; quality fields left empty
  std::vector<FittedSphere> fitted;    // same order as rig.spheres
  BindSurface surface;                 // the bind surface it was fitted to
  std::vector<SurfaceSample> samples;  // fitting surface samples
  float diagonal = 0.0f;               // meters
  float tolerance_m = 0.0f;            // tolerance × diagonal
  TeleportStats teleport;              // what the teleport step did
  double seconds = 0.0;                // wall time of run()
};

// The quality figures of a fit: its spheres (bind space) measured against its own bind surface
// at its own tolerance (measure_quality).
FitQuality measure_fit_quality(const anim::Character& character, const FitResult& fit);

struct FitProxiesJob {
  // Inputs.
  const anim::Character* character = nullptr;
  FitOptions options;
  // Output (caller-owned).
  FitResult* result = nullptr;

  // Checks pointers and option ranges.
  Status validate() const;
  // validate(), then fit. Fails only when the character has no triangles or bad mesh data.
  Status run() const;
};

}  // namespace proxygi::proxies
