#include "sh/environment.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/occlusion_tables.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"

namespace proxygi::sh {

glm::dvec3 equirect_direction(double u, double v) {
  const double phi = 2.0 * kPi * u - kPi, theta = kPi * v;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

RgbSh project_equirect(int order, const image::ImageF& image) {
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder, "SH order must be 1..8");
  const std::size_t count = std::size_t(order * order);
  RgbSh result{order, {std::vector<double>(count, 0.0), std::vector<double>(count, 0.0), std::vector<double>(count, 0.0)}};
  std::vector<double> basis(count);
  for (int y = 0; y < image.height; ++y) {
    const double theta_top = kPi * y / image.height, theta_bottom = kPi * (y + 1) / image.height;
    const double solid_angle = (std::cos(theta_top) - std::cos(theta_bottom)) * 2.0 * kPi / image.width;
    for (int x = 0; x < image.width; ++x) {
      evaluate_basis(order, equirect_direction((x + 0.5) / image.width, (y + 0.5) / image.height), basis);
      const glm::vec4& pixel = image.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const double weight = solid_angle * double(pixel[c]);
        for (std::size_t i = 0; i < count; ++i) result.channels[std::size_t(c)][i] += weight * basis[i];
      }
    }
  }
  return result;
}

Result<RgbSh> project_equirect_file(int order, const std::filesystem::path& path) {
  Result<image::ImageF> image = image::read_image(path);
  if (!image) return image.error();
  if (image->width < 2 || image->height < 1) return make_error(path.string() + ": environment image is too small");
  return project_equirect(order, *image);
}

glm::dvec3 AnalyticSky::radiance_without_sun(const glm::dvec3& dir) const {
  if (dir.y < 0.0) return ground;
  const double t = std::sqrt(dir.y);  // quick rise away from the horizon
  return horizon + (zenith - horizon) * t;
}

glm::dvec3 AnalyticSky::radiance(const glm::dvec3& dir) const {
  const bool in_sun = glm::dot(dir, sun_direction) >= std::cos(sun_radius_radians);
  return radiance_without_sun(dir) + (in_sun ? sun_radiance : glm::dvec3(0.0));
}

RgbSh project_sun_disc(int order, const AnalyticSky& sky) {
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder, "SH order must be 1..8");
  const std::size_t count = std::size_t(order * order);
  RgbSh result{order, {std::vector<double>(count, 0.0), std::vector<double>(count, 0.0), std::vector<double>(count, 0.0)}};
  std::vector<double> disc(count);
  rotate_zonal(order, proxy_visibility_zonal(order, std::sin(sky.sun_radius_radians)), sky.sun_direction, disc);
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < count; ++i) result.channels[std::size_t(c)][i] = sky.sun_radiance[c] * disc[i];
  return result;
}

RgbSh project_sky(int order, const AnalyticSky& sky) {
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder, "SH order must be 1..8");
  const std::size_t count = std::size_t(order * order);
  RgbSh result{order, {std::vector<double>(count, 0.0), std::vector<double>(count, 0.0), std::vector<double>(count, 0.0)}};
  // Quadrature about +Y split at the horizon: upper half (gradient, smooth in y once
  // substituted) and lower half (constant), both exact or nearly so with Gauss nodes.
  const SphereQuadrature upper = make_cap_quadrature(0.0, 48, 4 * order + 4);
  std::vector<double> basis(count);
  for (int half = 0; half < 2; ++half) {
    for (std::size_t q = 0; q < upper.size(); ++q) {
      // The cap rule is about +z; map z -> +Y (upper) or -Y (lower).
      const glm::dvec3 d = upper.directions[q];
      const glm::dvec3 dir = half == 0 ? glm::dvec3(d.x, d.z, -d.y) : glm::dvec3(d.x, -d.z, d.y);
      const glm::dvec3 value = sky.radiance_without_sun(dir);
      evaluate_basis(order, dir, basis);
      for (int c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < count; ++i) result.channels[std::size_t(c)][i] += upper.weights[q] * value[c] * basis[i];
    }
  }
  // The sun disc adds to the sky under it (scene/environment.h), in closed form.
  const RgbSh sun = project_sun_disc(order, sky);
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < count; ++i) result.channels[std::size_t(c)][i] += sun.channels[std::size_t(c)][i];
  return result;
}

std::vector<double> project_over_hemisphere(int order, std::span<const double> lighting, const glm::dvec3& normal, int out_order,
                                            bool cosine_weighted, int z_count, int phi_count) {
  const std::size_t count = std::size_t(order * order), out_count = std::size_t(out_order * out_order);
  PROXYGI_CHECK(lighting.size() >= count, "lighting span too small");
  static thread_local SphereQuadrature hemisphere;
  static thread_local std::pair<int, int> hemisphere_nodes{-1, -1};
  if (hemisphere_nodes != std::pair{z_count, phi_count}) {
    hemisphere = make_cap_quadrature(0.0, z_count, phi_count);
    hemisphere_nodes = {z_count, phi_count};
  }
  const glm::dmat3 to_normal = rotation_between({0.0, 0.0, 1.0}, normal);
  const int basis_order = std::max(order, out_order);
  std::vector<double> result(out_count, 0.0), basis(std::size_t(basis_order * basis_order));
  for (std::size_t q = 0; q < hemisphere.size(); ++q) {
    evaluate_basis(basis_order, to_normal * hemisphere.directions[q], basis);
    double radiance = 0.0;
    for (std::size_t i = 0; i < count; ++i) radiance += lighting[i] * basis[i];
    const double weight = hemisphere.weights[q] * (cosine_weighted ? hemisphere.directions[q].z : 1.0) * radiance;
    for (std::size_t i = 0; i < out_count; ++i) result[i] += weight * basis[i];
  }
  return result;
}

std::vector<double> lighting_times_clamped_cosine(int order, std::span<const double> lighting, const glm::dvec3& normal) {
  // Over the hemisphere about N the integrand L(s) y_i(s) (N.s) is a polynomial of degree
  // 2(n-1)+1 in s whose odd powers of sin(theta') cancel over phi': Gauss nodes in cos(theta')
  // on [0, 1] and 2n+2 phi samples are exact.
  return project_over_hemisphere(order, lighting, normal, order, true, order + 1, 2 * order + 2);
}

glm::dvec3 cube_map_direction(int face, int x, int y, int face_size) {
  const double sc = 2.0 * (x + 0.5) / face_size - 1.0, tc = 2.0 * (y + 0.5) / face_size - 1.0;
  glm::dvec3 dir;
  switch (face) {  // Vulkan spec, "Cube Map Face Selection": (sc, tc) = f(rx, ry, rz)
    case 0: dir = {1.0, -tc, -sc}; break;   // +X
    case 1: dir = {-1.0, -tc, sc}; break;   // -X
    case 2: dir = {sc, 1.0, tc}; break;     // +Y
    case 3: dir = {sc, -1.0, -tc}; break;   // -Y
    case 4: dir = {sc, -tc, 1.0}; break;    // +Z
    default: dir = {-sc, -tc, -1.0}; break; // -Z
  }
  return glm::normalize(dir);
}

LightingCubeMap make_lighting_cube_map(int order, std::span<const double> lighting, int face_size) {
  PROXYGI_CHECK(face_size >= 1, "cube map faces need at least one texel");
  const std::size_t count = std::size_t(order * order);
  LightingCubeMap map{order, face_size, {}};
  map.values.reserve(6 * std::size_t(face_size) * std::size_t(face_size) * count);
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < face_size; ++y)
      for (int x = 0; x < face_size; ++x)
        for (double value : lighting_times_clamped_cosine(order, lighting, cube_map_direction(face, x, y, face_size)))
          map.values.push_back(float(value));
  return map;
}

}  // namespace proxygi::sh
