#pragma once
// The reference integrator: a unidirectional path tracer over an EmbreeScene lit only by a
// distant environment (EnvironmentLight). Every surface is Lambertian with
// f = albedo / pi, so the radiance leaving a point is albedo/pi · E, E the irradiance there.
//
// Estimator (one call = one path = one "sample"; spp = paths per pixel):
//  - At each surface vertex with shading normal n:
//    * sun (only when the light has one): one direction uniform in the sun cone, pdf p_l =
//      1/(2 pi (1 - cos r)); if unoccluded it adds f L_sun cos / p_l · w_l,
//    * BSDF: one cosine-weighted direction, pdf p_b = cos/pi (throughput × albedo). If it
//      escapes, it adds albedo · (L_without_sun(d) + w_b L_sun(d)).
//    * environment (sh and map lighting): one direction from the light's EquirectSampler, MIS-
//      weighted against the BSDF sample the same way (the sky kind has a sun instead).
//    w_l, w_b: power heuristic between p_l and p_b (Veach 1997), so light is counted once.
//    Directions below the geometric surface carry nothing (the surface itself blocks them).
//  - Light transport depth (LightTransport):
//    direct       only the primary vertex's environment light, with visibility (0 bounces);
//    one_bounce   plus environment light reflected by one more surface (1 diffuse bounce);
//    multi_bounce paths continue, Russian roulette from vertex `russian_roulette_depth` on with
//                 continuation probability min(1, max throughput component), and at most
//                 `max_bounces` bounces (truncation bias below albedo^max_bounces).
//  - "indirect" is the part of the estimate that arrived over at least one bounce (vertex >= 1):
//    radiance = direct + indirect.
// Random numbers come from the caller's SampleStream in a fixed order, so a (seed, pixel,
// sample) triple always traces the same path.
#include <cstdint>

#include <glm/glm.hpp>

#include "ref/embree_scene.h"
#include "ref/path_tracer_lighting.h"
#include "ref/sampling.h"
#include "scene/camera.h"

namespace proxygi::ref {

enum class LightTransport { direct, one_bounce, multi_bounce };

struct PathTracerSettings {
  LightTransport transport = LightTransport::one_bounce;
  int russian_roulette_depth = 3;  // multi_bounce: first vertex where roulette may end a path
  int max_bounces = 64;            // multi_bounce: hard cap
  // false: a character reached at a vertex after the first reflects nothing (its albedo taken as
  // 0 there; primary hits keep theirs). The random stream is consumed the same, so with the same
  // seed the difference to a `true` render is exactly the light the characters bounce.
  bool character_senders = true;
  // true: a character reached after the first vertex is lit without shadows (its light samples
  // and BSDF ray count as unoccluded), as the bounce methods light their senders (the VPLs' and
  // proxies' unshadowed irradiance): a reference for their assumption, not a physical one.
  bool unshadowed_character_senders = false;
};

struct PathSample {
  glm::vec3 radiance{0.0f};  // linear RGB arriving along the ray (direct + indirect)
  glm::vec3 indirect{0.0f};  // the part that bounced at least once
  bool hit = false;          // the primary ray hit geometry (else radiance = background)
  std::uint32_t rays = 0;    // rays traced for this sample (intersect + occluded)
};

class PathTracer {
 public:
  // `lighting` lights the surfaces; `background` is what camera rays that miss see (the full
  // environment in both lighting modes, as the rasterizer's background). All referenced objects
  // must outlive the tracer.
  PathTracer(const EmbreeScene& scene, const EnvironmentLight& lighting, const EnvironmentLight& background,
             const PathTracerSettings& settings);

  // One path through a camera ray.
  PathSample trace(const scene::Ray& ray, SampleStream& random) const;
  // One estimate of the radiance leaving the surface point `hit` (view-independent: Lambertian).
  PathSample shade(const SurfaceHit& hit, SampleStream& random) const;

  const PathTracerSettings& settings() const { return settings_; }

 private:
  const EmbreeScene& scene_;
  const EnvironmentLight& lighting_;
  const EnvironmentLight& background_;
  PathTracerSettings settings_;
};

}  // namespace proxygi::ref
