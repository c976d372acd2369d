#include "study/stability_shading.h"

#include <algorithm>
#include <cmath>

#include "base/check.h"
#include "image/image.h"
#include "render/baselines.h"
#include "render/ground_grid.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/exponential.h"
#include "sh/occlusion_tables.h"
#include "sh/product.h"
#include "sh/rotation.h"
#include "sh/tangent_plane.h"

namespace proxygi::study {
namespace {

constexpr double kSqrtFourPi = 3.5449077018110318;

bool ray_hits(const glm::dvec3& p, const glm::dvec3& direction, const render::Sphere& sphere) {
  const glm::dvec3 offset = glm::dvec3(sphere.center) - p;
  const double r = sphere.radius;
  const double c = glm::dot(offset, offset) - r * r;
  if (c < 0.0) return true;  // inside
  const double b = glm::dot(offset, direction);
  return b > 0.0 && b * b > c;
}

}  // namespace

double luminance(const glm::vec3& rgb) { return image::rec709_luminance(rgb); }

double relative_l2(std::span<const double> a, std::span<const double> b) {
  double difference = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) difference += (a[i] - b[i]) * (a[i] - b[i]), norm += b[i] * b[i];
  return norm > 0.0 ? std::sqrt(difference / norm) : std::sqrt(difference);
}

sh::RgbSh sweep_lighting(SweepLight light) {
  const sh::AnalyticSky sky;
  if (light == SweepLight::sky) return sh::project_sky(sh::kMaxOrder >= 6 ? 6 : sh::kMaxOrder, sky);
  // A delta light carrying the sun's power (radiance × solid angle of its disc).
  const int order = 6;
  sh::RgbSh out;
  out.order = order;
  std::vector<double> basis(std::size_t(order * order));
  sh::evaluate_basis(order, sky.sun_direction, basis);
  const double solid_angle = 2.0 * sh::kPi * (1.0 - std::cos(sky.sun_radius_radians));
  for (int c = 0; c < 3; ++c) {
    out.channels[std::size_t(c)].resize(basis.size());
    for (std::size_t i = 0; i < basis.size(); ++i) out.channels[std::size_t(c)][i] = sky.sun_radiance[c] * solid_angle * basis[i];
  }
  return out;
}

render::FrameTables sweep_tables(const sh::RgbSh& lighting, int order, double window, float shadow_eta) {
  sh::RgbSh windowed = lighting;
  if (window > 0.0)
    for (auto& channel : windowed.channels) sh::apply_ringing_window(lighting.order, channel, window);
  settings::RenderSettings settings;
  settings.sh_order = order;
  settings.sh_window = false;  // applied above with the sweep's window size
  settings.shadow_eta = shadow_eta;
  settings.ground_bounce = false;
  return render::make_frame_tables(windowed, settings);
}

MethodShade shade_visibility(const render::FrameTables& tables, std::span<const float> visibility, const glm::vec3& p,
                             const glm::vec3& normal) {
  const int order = tables.settings.sh_order;
  const std::size_t count = std::size_t(order * order);
  MethodShade shade;
  shade.visibility.assign(visibility.begin(), visibility.begin() + std::ptrdiff_t(count));
  std::vector<float> lh(count);
  const int set = render::lighting_cube_set(p);
  glm::vec3 clamped(0.0f), unclamped(0.0f), open(0.0f);
  for (int channel = 0; channel < 3; ++channel) {
    render::lookup_lighting_cube(tables.lighting_cube[std::size_t(set + channel)], normal, lh);
    float e = 0.0f;
    for (std::size_t i = 0; i < count; ++i) e += visibility[i] * lh[i];
    const float unshadowed = std::max(float(kSqrtFourPi) * lh[0], 0.0f);
    unclamped[channel] = e;
    clamped[channel] = std::clamp(e, 0.0f, unshadowed);  // exponentiate.comp's F4 clamp
    open[channel] = unshadowed;
  }
  shade.value = luminance(clamped);
  shade.unclamped = luminance(unclamped);
  shade.unshadowed = luminance(open);
  return shade;
}

MethodShade shade_log_sum(const render::FrameTables& tables, float tau, std::span<const float> f, const glm::vec3& p,
                          const glm::vec3& normal) {
  const int order = tables.settings.sh_order;
  std::vector<float> visibility(std::size_t(order * order));
  const int squarings = sh::exp_hybrid(order, f, tables.optimal_linear, tau, visibility);
  MethodShade shade = shade_visibility(tables, visibility, p, normal);
  shade.squarings = squarings;
  // The twin itself must agree with this decomposition (same formulas, same order).
  const render::DirectResult direct = render::exponentiate_and_shade(tables, f, tau, p, normal);
  shade.value = luminance(direct.irradiance);
  return shade;
}

MethodShade shade_method(const render::FrameTables& tables, float tau, const glm::vec3& p, const glm::vec3& normal,
                         std::span<const render::Sphere> spheres) {
  const std::vector<float> f = render::accumulate_log_occlusion(tables, p, normal, spheres);
  return shade_log_sum(tables, tau, f, p, normal);
}

MethodShade shade_ambient_occlusion(const render::FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                    std::span<const render::Sphere> spheres) {
  const render::AmbientOcclusionResult ao = render::ambient_occlusion(tables, p, normal, spheres);
  MethodShade out;
  out.unshadowed = luminance(render::unshadowed_irradiance(tables, p, normal));
  out.unclamped = luminance(ao.irradiance);
  out.value = std::clamp(out.unclamped, 0.0, out.unshadowed);
  return out;
}

MethodShade shade_vertex_ground(const render::FrameTables& tables, float tau, const glm::vec3& p, std::span<const render::Sphere> spheres) {
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const float spacing = 1.0f / render::kGroundVerticesPerMetre;
  const glm::vec2 origin = kVertexGridOffset * spacing;
  const glm::vec2 cell = glm::floor((glm::vec2(p.x, p.z) - origin) / spacing);
  auto vertex = [&](float dx, float dz) {
    const glm::vec2 at = origin + (cell + glm::vec2(dx, dz)) * spacing;
    return glm::vec3(at.x, 0.0f, at.y);
  };
  // make_ground_grid's two triangles per cell: (corner, +z, +x) and (+x, +z, far).
  const glm::vec2 local = (glm::vec2(p.x, p.z) - origin) / spacing - cell;
  const bool first = local.x + local.y <= 1.0f;
  const glm::vec3 a = first ? vertex(0, 0) : vertex(1, 0), b = vertex(0, 1), c = first ? vertex(1, 0) : vertex(1, 1);
  glm::vec3 values[3];
  const glm::vec3* corners[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const MethodShade at = shade_method(tables, tau, *corners[i], up, spheres);
    values[i] = glm::vec3(float(at.value), float(at.unshadowed), float(at.unclamped));
  }
  const glm::vec3 mixed = render::interpolate_triangle(p, a, b, c, values[0], values[1], values[2]);
  MethodShade out;
  out.value = mixed.x;
  out.unshadowed = mixed.y;
  out.unclamped = mixed.z;
  return out;
}

MethodShade shade_ground_method(std::string_view method, const render::FrameTables& tables, float tau, const glm::vec3& p,
                                std::span<const render::Sphere> spheres) {
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  if (method == "hyb") return shade_method(tables, tau, p, up, spheres);
  if (method == "ol") return shade_method(tables, kOptimalLinearOnly, p, up, spheres);
  if (method == "ao") return shade_ambient_occlusion(tables, p, up, spheres);
  PROXYGI_CHECK(method == "vertex", "shade_ground_method: unknown method");
  return shade_vertex_ground(tables, tau, p, spheres);
}

std::vector<float> product_space_visibility(const render::FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                            std::span<const render::Sphere> spheres) {
  const int order = tables.settings.sh_order;
  const std::size_t count = std::size_t(order * order);
  std::vector<double> product(count, 0.0), rotated(count), next(count);
  product[0] = kSqrtFourPi;
  const float minimum_sine = 1.0f / tables.shadow_eta;
  for (const render::Sphere& sphere : spheres) {
    const glm::vec3 offset = sphere.center - p;
    const float reach = tables.shadow_eta * sphere.radius;
    if (glm::dot(offset, offset) >= reach * reach) continue;
    const auto seen = sh::proxy_at_receiver(p, normal, {sphere.center, sphere.radius});
    if (!seen || seen->sine <= minimum_sine) continue;
    const std::vector<double> zonal = sh::occlusion_zonal(order, seen->sine);
    sh::rotate_zonal(order, zonal, glm::dvec3(seen->direction), rotated);
    sh::product(order, product, rotated, next);
    product = next;
  }
  return std::vector<float>(product.begin(), product.end());
}

TruthIntegrator::TruthIntegrator(const render::FrameTables& tables, int z_nodes)
    : order_(tables.settings.sh_order), quadrature_(sh::make_sphere_quadrature(z_nodes, 2 * z_nodes)) {
  const std::size_t count = std::size_t(order_ * order_);
  luminance_sh_.assign(count, 0.0);
  for (std::size_t i = 0; i < count; ++i)
    luminance_sh_[i] = 0.2126 * tables.lighting.channels[0][i] + 0.7152 * tables.lighting.channels[1][i] +
                       0.0722 * tables.lighting.channels[2][i];
  light_at_.resize(quadrature_.size());
  basis_at_.resize(quadrature_.size() * count);
  for (std::size_t q = 0; q < quadrature_.size(); ++q) {
    std::span<double> basis(basis_at_.data() + q * count, count);
    sh::evaluate_basis(order_, quadrature_.directions[q], basis);
    double l = 0.0;
    for (std::size_t i = 0; i < count; ++i) l += luminance_sh_[i] * basis[i];
    light_at_[q] = l;
  }
}

double TruthIntegrator::light(const glm::dvec3& direction) const {
  return sh::evaluate_expansion(order_, luminance_sh_, direction);
}

double TruthIntegrator::unshadowed(const glm::dvec3& normal) const {
  // LH_0 by exact hemisphere quadrature, as the frame's cube maps are built.
  const std::vector<double> lh = sh::lighting_times_clamped_cosine(order_, luminance_sh_, normal);
  return kSqrtFourPi * lh[0];
}

double TruthIntegrator::shadowed(const glm::dvec3& p, const glm::dvec3& normal, std::span<const render::Sphere> spheres) const {
  for (const render::Sphere& s : spheres)
    if (glm::distance(glm::dvec3(s.center), p) < s.radius) return 0.0;
  double blocked = 0.0;
  for (std::size_t q = 0; q < quadrature_.size(); ++q) {
    const double cosine = glm::dot(normal, quadrature_.directions[q]);
    if (cosine <= 0.0) continue;
    for (const render::Sphere& s : spheres)
      if (ray_hits(p, quadrature_.directions[q], s)) {
        blocked += quadrature_.weights[q] * light_at_[q] * cosine;
        break;
      }
  }
  return unshadowed(normal) - blocked;
}

double TruthIntegrator::shadowed_one(const glm::dvec3& p, const glm::dvec3& normal, const render::Sphere& sphere) const {
  const glm::dvec3 offset = glm::dvec3(sphere.center) - p;
  const double d = glm::length(offset);
  if (d < sphere.radius) return 0.0;
  const double cos_alpha = std::sqrt(std::max(0.0, 1.0 - (sphere.radius / d) * (sphere.radius / d)));
  const sh::SphereQuadrature cap = sh::make_cap_quadrature(cos_alpha, 48, 96);
  const glm::dmat3 turn = sh::rotation_between(glm::dvec3(0, 0, 1), offset / d);
  double blocked = 0.0;
  for (std::size_t q = 0; q < cap.size(); ++q) {
    const glm::dvec3 direction = turn * cap.directions[q];
    const double cosine = glm::dot(normal, direction);
    if (cosine > 0.0) blocked += cap.weights[q] * light(direction) * cosine;
  }
  return unshadowed(normal) - blocked;
}

std::vector<double> TruthIntegrator::visibility_sh(const glm::dvec3& p, std::span<const render::Sphere> spheres) const {
  const std::size_t count = std::size_t(order_ * order_);
  std::vector<double> out(count, 0.0);
  for (std::size_t q = 0; q < quadrature_.size(); ++q) {
    bool hit = false;
    for (const render::Sphere& s : spheres) hit = hit || ray_hits(p, quadrature_.directions[q], s);
    if (hit) continue;
    for (std::size_t i = 0; i < count; ++i) out[i] += quadrature_.weights[q] * basis_at_[q * count + i];
  }
  return out;
}

}  // namespace proxygi::study
