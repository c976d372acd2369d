#include "sh/vsgl_sun.h"

#include <algorithm>
#include <cmath>

namespace proxygi::sh {

VirtualPointLight rsm_texel_light(const RsmTexel& texel, const SunLight& sun, double texel_area) {
  VirtualPointLight light;
  light.position = texel.position;
  light.normal = texel.normal;
  light.flux = glm::dot(texel.normal, sun.direction) > 0.0 ? texel.albedo * sun.irradiance * texel_area : glm::dvec3(0.0);
  return light;
}

void add_vsgl_sun(VsglSums& sums, std::span<const RsmTexel> texels, const SunLight& sun, double texel_area,
                  const glm::dvec3& origin) {
  if (!sun.above_horizon()) return;
  for (const RsmTexel& texel : texels) add_light(sums, rsm_texel_light(texel, sun, texel_area), origin);
}

glm::dmat4 RsmView::view_projection() const {
  // Rows: x = 2 (p·u − u_min)/u_extent − 1, y likewise with v, z = (s_max − p·s)/s_extent.
  glm::dmat4 m(0.0);  // column-major: m[column][row]
  const glm::dvec3 rows[3] = {2.0 * right / u_extent, 2.0 * up / v_extent, -toward_sun / s_extent};
  const double offsets[3] = {-2.0 * u_min / u_extent - 1.0, -2.0 * v_min / v_extent - 1.0, s_max / s_extent};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[c][r] = rows[r][c];
    m[3][r] = offsets[r];
  }
  m[3][3] = 1.0;
  return m;
}

RsmView fit_rsm_view(const glm::dvec3& toward_sun, const glm::dvec3& box_min, const glm::dvec3& box_max, int size,
                     double margin) {
  RsmView view;
  view.toward_sun = glm::normalize(toward_sun);
  // u ⟂ s and horizontal unless the sun is at the zenith.
  const glm::dvec3 helper = std::abs(view.toward_sun.y) < 0.999 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
  view.right = glm::normalize(glm::cross(helper, view.toward_sun));
  view.up = glm::cross(view.toward_sun, view.right);
  glm::dvec3 low(1e300), high(-1e300);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? box_max.x : box_min.x, (corner & 2) ? box_max.y : box_min.y,
                       (corner & 4) ? box_max.z : box_min.z);
    const glm::dvec3 q(glm::dot(p, view.right), glm::dot(p, view.up), glm::dot(p, view.toward_sun));
    low = glm::min(low, q), high = glm::max(high, q);
  }
  low -= margin, high += margin;
  view.u_min = low.x, view.u_extent = high.x - low.x;
  view.v_min = low.y, view.v_extent = high.y - low.y;
  view.s_max = high.z, view.s_extent = high.z - low.z;
  view.size = std::max(size, 1);
  return view;
}

double rsm_margin(const glm::dvec3& box_min, const glm::dvec3& box_max) {
  return 0.05 * glm::length(box_max - box_min) + 0.1;
}

}  // namespace proxygi::sh
