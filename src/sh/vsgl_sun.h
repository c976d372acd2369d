#pragma once
// The sun variant of VSGL (notes/prt-vsgl.md §4, render.vsgl_sun): a reflective shadow map (RSM)
// of the characters seen from the sun turns every texel into a diffuse VPL, summed into the
// same VsglSums as the environment variant's vertex VPLs (sh/vsgl.h; the sums are additive).
//
// Not counting the sun twice. The environment variant lights a vertex VPL with the unshadowed
// SH irradiance E(n) = Σ L̃_i y_i(n), and the SH lighting L = L_sky + L_sun holds the sun disc
// (sh::project_sky = gradient + sh::project_sun_disc). With the RSM on, the vertex VPLs take
// E'(n) from L − L_sun (windowed and convolved like L: everything is linear), and the sun's share
// comes from the RSM instead: a sender texel the sun does not see (in the character's own sun
// shadow) is not in the map and sends no sun light. On a sender nothing shadows, the two differ
// only by the sun's share being exact (E_s max(n·s, 0)) instead of its order-3 SH smoothing.
//
// Texel flux. An orthographic texel of area a_t (m², perpendicular to the sun) hitting a surface
// of normal n covers a_t/(n·s) m² of it, which receives E_s (n·s): its reflected flux is
// Φ R = ρ E_s a_t, whatever the slope (0 when n·s ≤ 0: the sun does not light its back).
// E_s: the sun's irradiance onto a surface facing it (scene::AnalyticSky::sun_irradiance).
#include <array>
#include <span>

#include <glm/glm.hpp>

#include "sh/vsgl.h"

namespace proxygi::sh {

struct SunLight {
  glm::dvec3 direction{0.0, 1.0, 0.0};  // s: toward the sun, world, unit
  glm::dvec3 irradiance{0.0};           // E_s per channel onto a surface facing the sun
  // The sun variant is on only above the horizon (below, the ground plane hides it).
  bool above_horizon() const { return direction.y > 0.0 && (irradiance.x > 0.0 || irradiance.y > 0.0 || irradiance.z > 0.0); }
};

// One RSM texel: the surface point the texel's sun ray hits first.
struct RsmTexel {
  glm::dvec3 position{0.0};  // world meters
  glm::dvec3 normal{0.0, 1.0, 0.0};  // unit shading normal
  glm::dvec3 albedo{0.0};    // ρ, linear rgb
};

// The texel's VPL: at its position, normal n, flux ρ E_s a_t if n·s > 0, else 0.
VirtualPointLight rsm_texel_light(const RsmTexel& texel, const SunLight& sun, double texel_area);

// Adds the texels' VPLs to sums (origin as in add_light); nothing when the sun is not above the
// horizon. CPU twin of rsm_sums.comp.
void add_vsgl_sun(VsglSums& sums, std::span<const RsmTexel> texels, const SunLight& sun, double texel_area,
                  const glm::dvec3& origin);

// The orthographic sun view fitted to a world box: right/up (u, v) span the map, whose texel
// (x, y) of size × size has its centre ray through origin + (x + ½) texel_u u + (y + ½) texel_v v,
// travelling along −s; depth 0 at the box's highest point along s, 1 at its lowest.
struct RsmView {
  glm::dvec3 right{1.0, 0.0, 0.0}, up{0.0, 0.0, 1.0};  // u, v (unit, ⟂ s)
  glm::dvec3 toward_sun{0.0, 1.0, 0.0};                // s
  double u_min = 0.0, u_extent = 1.0;   // the map spans [u_min, u_min + u_extent] along u (m)
  double v_min = 0.0, v_extent = 1.0;
  double s_max = 0.0, s_extent = 1.0;   // depth = (s_max − p·s)/s_extent
  int size = 1;                          // texels per side
  double texel_area() const { return (u_extent / size) * (v_extent / size); }
  // World → Vulkan clip space (x, y in [−1, 1] across the map, z = depth in [0, 1]).
  glm::dmat4 view_projection() const;
};
// margin: added to every side of the box (m); box_min ≤ box_max; size ≥ 1.
RsmView fit_rsm_view(const glm::dvec3& toward_sun, const glm::dvec3& box_min, const glm::dvec3& box_max, int size,
                     double margin);
// The frame's margin around the characters' proxy box (the proxies stand for the characters;
// this covers what pokes out of them): 5 % of the box's diagonal plus 0.1 m.
double rsm_margin(const glm::dvec3& box_min, const glm::dvec3& box_max);

}  // namespace proxygi::sh
