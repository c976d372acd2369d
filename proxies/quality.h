#pragma once
// Quality of a sphere set against the surface it stands for, all in bind space (meters).
// Every measure uses its own samples (a different seed from fitting), so a fit cannot look
// good merely by covering the very points it was fitted to.
//
//  coverage                      fraction of area-uniform surface samples p with
//                                d(p) <= tolerance, where d(p) = max(0, min_i |p − c_i| − r_i)
//                                is the distance from p to the union of spheres.
//  hausdorff_surface_to_spheres  max d(p) over those samples (mean_surface_to_spheres: mean).
//  hausdorff_spheres_to_surface  max, over points q of the union's boundary, of the exact
//                                distance from q to the mesh surface. Boundary points: Fibonacci
//                                points on each sphere, kept when no other sphere contains them.
//  outside_volume_ratio          volume of the union outside the mesh / volume of the union, by
//                                Monte Carlo: pick a sphere with probability ∝ its volume, a
//                                uniform point in it, keep the point with probability 1/(number
//                                of spheres containing it) (so kept points are uniform in the
//                                union), and classify it with the winding-number inside test of
//                                proxies/mesh_index.h (majority of three signed-crossing rays).
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "proxies/bind_surface.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

struct QualityOptions {
  int surface_samples = 20000;
  int volume_samples = 20000;
  int boundary_points_per_sphere = 256;
  std::uint64_t seed = 0x5eed;
};

// `spheres`: xyz = center, w = radius, bind space. `tolerance_m` in meters.
FitQuality measure_quality(const anim::Character& character, const BindSurface& surface,
                           std::span<const glm::vec4> spheres, float tolerance_m,
                           const QualityOptions& options = {});

}  // namespace proxygi::proxies
