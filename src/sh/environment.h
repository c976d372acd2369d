#pragma once
// Environment lighting in SH (conventions in sh/basis.h): projection of equirectangular maps and
// of an analytic sky with a sun disc, and the LH(N) cube map used for shadowed direct light.
//
// Equirectangular convention (glTF world space, +Y up): pixel (x, y) of a W x H image covers
//   u = (x + 0.5) / W, v = (y + 0.5) / H,  phi = 2 pi u - pi,  theta = pi v  (v = 0 is the zenith)
//   direction = (sin theta sin phi, cos theta, -sin theta cos phi)
// so the image center (u = 0.5) looks along -Z, u = 0.75 along +X, and the top row is +Y.
// Each pixel is weighted by its exact solid angle (cos theta_top - cos theta_bottom) 2 pi / W.
// RGB projections are three SH vectors (red, green, blue), each order*order values.
#include <array>
#include <filesystem>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "image/image.h"

namespace proxygi::sh {

struct RgbSh {
  int order = 0;
  std::array<std::vector<double>, 3> channels;  // each order*order coefficients
};

glm::dvec3 equirect_direction(double u, double v);

// Projects a linear RGB equirectangular image (alpha ignored) to SH of the given order (1..8).
RgbSh project_equirect(int order, const image::ImageF& image);
// Reads an equirectangular .hdr or .exr (through image::read_image) and projects it.
Result<RgbSh> project_equirect_file(int order, const std::filesystem::path& path);

// Analytic sky: a vertical gradient from horizon to zenith colour above the horizon (+Y up),
// a uniform ground colour below, and a sun disc of angular radius sun_radius_radians around
// sun_direction (unit) adding the constant radiance sun_radiance on top of the sky under it (as
// scene/environment.h and the path tracer do). Radiances are linear RGB.
struct AnalyticSky {
  glm::dvec3 zenith{0.25, 0.45, 0.9};
  glm::dvec3 horizon{0.8, 0.85, 0.95};
  glm::dvec3 ground{0.3, 0.28, 0.25};
  glm::dvec3 sun_direction = glm::normalize(glm::dvec3(0.3, 0.8, 0.4));
  double sun_radius_radians = 0.0465;  // about 2.7 deg: wide enough to matter at low orders
  glm::dvec3 sun_radiance{60.0, 55.0, 45.0};
  // Radiance in direction dir (unit), sun included.
  glm::dvec3 radiance(const glm::dvec3& dir) const;
  // The gradient and ground alone.
  glm::dvec3 radiance_without_sun(const glm::dvec3& dir) const;
};
// Sky by quadrature (split at the horizon, so exact up to the smooth gradient) plus the sun disc
// in closed form (a rotated cap): project_sky = projection of the gradient + project_sun_disc.
RgbSh project_sky(int order, const AnalyticSky& sky);
// The sun disc's share of project_sky alone: sun_radiance × the SH of the cap's indicator.
RgbSh project_sun_disc(int order, const AnalyticSky& sky);

// The order-`out_order` projection of L(s) w(s) over the hemisphere s . N > 0 (zero below it),
// w = N . s when `cosine_weighted`, else 1, for the order-n lighting L (one channel; N unit): the
// cap rule of sh/quadrature.h with z_count x phi_count nodes turned onto N, exact when they cover
// the integrand's degree. Shared by LH(N) below and the proxies' sender light (sh/sender_light.h).
std::vector<double> project_over_hemisphere(int order, std::span<const double> lighting, const glm::dvec3& normal, int out_order,
                                            bool cosine_weighted, int z_count, int phi_count);

// LH(N) = SH projection (order n) of L(s) max(N . s, 0) for the lighting L given by its order-n
// SH vector: the shadowed irradiance at a receiver is E = O_p . LH(N) (not divided by pi).
// Computed by exact hemisphere quadrature about N (no truncation of the clamped cosine).
std::vector<double> lighting_times_clamped_cosine(int order, std::span<const double> lighting, const glm::dvec3& normal);

// LH over a cube map: face_size x face_size texels per face, 6 faces in Vulkan order
// (+X, -X, +Y, -Y, +Z, -Z), texel (x, y) at the texel centre with the Vulkan cube-map face
// orientation (sc, tc, ma table of the Vulkan spec). Layout: values[((face * face_size + y) *
// face_size + x) * n*n + i], floats. One channel: call per colour channel.
struct LightingCubeMap {
  int order = 0;
  int face_size = 0;
  std::vector<float> values;
};
glm::dvec3 cube_map_direction(int face, int x, int y, int face_size);
LightingCubeMap make_lighting_cube_map(int order, std::span<const double> lighting, int face_size);

}  // namespace proxygi::sh
