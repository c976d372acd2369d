#include "render/shading.h"

#include <algorithm>
#include <cmath>

#include "render/exact_indirect.h"
#include "sh/indirect.h"
#include "sh/tangent_plane.h"
#include "sh/basis.h"

namespace proxygi::render {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kSqrtFourPi = 3.5449077018110318f;

// sqrt(4π / (2l + 1)), the ZH rotation scale of band l.
float zonal_scale(int band) { return std::sqrt(4.0f * kPi / float(2 * band + 1)); }

// f += rot(zonal, direction) for the first order² coefficients.
void add_rotated(int order, std::span<const float> zonal, const glm::vec3& direction, float weight, std::span<float> f) {
  float basis[36];
  sh::evaluate_basis(order, direction, std::span<float>(basis, std::size_t(order * order)));
  for (int l = 0; l < order; ++l) {
    const float scaled = zonal_scale(l) * zonal[std::size_t(l)] * weight;
    for (int m = -l; m <= l; ++m) {
      const int i = l * (l + 1) + m;
      f[std::size_t(i)] += scaled * basis[i];
    }
  }
}

// The cheap reject both shaders do first: p outside the sphere of influence η·r.
bool outside_influence(const glm::vec3& p, const Sphere& sphere, float eta) {
  const glm::vec3 offset = sphere.center - p;
  const float reach = eta * sphere.radius;
  return glm::dot(offset, offset) >= reach * reach;
}

}  // namespace

std::vector<float> accumulate_log_occlusion(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                            std::span<const Sphere> spheres) {
  const int order = tables.settings.sh_order;
  std::vector<float> f(std::size_t(order * order), 0.0f);
  float zonal[6];
  const float minimum_sine = 1.0f / tables.shadow_eta;
  for (const Sphere& sphere : spheres) {
    if (outside_influence(p, sphere, tables.shadow_eta)) continue;
    const auto seen = sh::proxy_at_receiver(p, normal, {sphere.center, sphere.radius});
    if (!seen || seen->sine <= minimum_sine) continue;
    tables.log_occlusion.lookup(seen->sine, std::span<float>(zonal, std::size_t(order)));
    add_rotated(order, std::span<const float>(zonal, std::size_t(order)), seen->direction, sphere.weight, f);
  }
  return f;
}

void lookup_lighting_cube(const sh::LightingCubeMap& cube, const glm::vec3& n, std::span<float> out) {
  const glm::vec3 a = glm::abs(n);
  int face;
  float sc, tc, major;
  if (a.x >= a.y && a.x >= a.z) {
    face = n.x >= 0 ? 0 : 1;
    major = a.x;
    sc = n.x >= 0 ? -n.z : n.z;
    tc = -n.y;
  } else if (a.y >= a.z) {
    face = n.y >= 0 ? 2 : 3;
    major = a.y;
    sc = n.x;
    tc = n.y >= 0 ? n.z : -n.z;
  } else {
    face = n.z >= 0 ? 4 : 5;
    major = a.z;
    sc = n.z >= 0 ? n.x : -n.x;
    tc = -n.y;
  }
  const int size = cube.face_size;
  const float u = std::clamp((0.5f * (sc / major + 1.0f)) * float(size) - 0.5f, 0.0f, float(size - 1));
  const float v = std::clamp((0.5f * (tc / major + 1.0f)) * float(size) - 0.5f, 0.0f, float(size - 1));
  const int x0 = std::min(int(u), size - 1), y0 = std::min(int(v), size - 1);
  const int x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
  const float fx = u - float(x0), fy = v - float(y0);
  const std::size_t count = std::size_t(cube.order * cube.order);
  auto texel = [&](int x, int y) { return cube.values.data() + ((std::size_t(face) * size + y) * size + x) * count; };
  const float* t00 = texel(x0, y0);
  const float* t10 = texel(x1, y0);
  const float* t01 = texel(x0, y1);
  const float* t11 = texel(x1, y1);
  for (std::size_t i = 0; i < count; ++i) {
    const float top = t00[i] + fx * (t10[i] - t00[i]);
    const float bottom = t01[i] + fx * (t11[i] - t01[i]);
    out[i] = top + fy * (bottom - top);
  }
}

DirectResult exponentiate_and_shade(const FrameTables& tables, std::span<const float> log_occlusion, float tau,
                                    const glm::vec3& p, const glm::vec3& normal) {
  const int order = tables.settings.sh_order;
  const std::size_t count = std::size_t(order * order);
  std::vector<float> visibility(count);
  DirectResult result;
  result.squarings = sh::exp_hybrid(order, log_occlusion, tables.optimal_linear, tau, visibility);
  result.occlusion_dc = visibility[0];
  std::vector<float> lh(count);
  const int set = lighting_cube_set(p);
  for (int channel = 0; channel < 3; ++channel) {
    lookup_lighting_cube(tables.lighting_cube[std::size_t(set + channel)], normal, lh);
    float irradiance = 0.0f;
    for (std::size_t i = 0; i < count; ++i) irradiance += visibility[i] * lh[i];
    // F4: the band-limited visibility rings; a blocker can only take light away (exponentiate.comp).
    result.irradiance[channel] = std::clamp(irradiance, 0.0f, std::max(kSqrtFourPi * lh[0], 0.0f));
  }
  return result;
}

std::array<std::array<float, 9>, 3> sender_light(const FrameTables& tables, const glm::vec3& normal) {
  std::array<std::array<float, 9>, 3> light{};
  for (std::size_t c = 0; c < 3; ++c) lookup_lighting_cube(tables.sender_light_cube[c], normal, light[c]);
  return light;
}

IndirectResult accumulate_indirect(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                   std::span<const Sphere> spheres, float occlusion_dc, settings::IndirectOperator op) {
  IndirectResult result;
  float normal_basis[9];
  sh::evaluate_basis(3, normal, std::span<float>(normal_basis, 9));
  const float cosine[3] = {0.886226925f, 1.023326708f, 0.495415912f};  // clamped cosine h_l
  const float minimum_sine = 1.0f / tables.settings.indirect_eta;
  const std::array<std::array<float, 9>, 3> light = sender_light(tables, normal);
  glm::vec3 summed(0.0f);
  for (const Sphere& sphere : spheres) {
    if (outside_influence(p, sphere, tables.settings.indirect_eta)) continue;
    const auto seen = sh::proxy_at_receiver(p, normal, {sphere.center, sphere.radius});
    if (!seen || seen->sine <= minimum_sine) continue;
    if (op == settings::IndirectOperator::exact) {
      // H(N) · I_i = W · L̃ per channel (render/exact_indirect.h); the table carries the fade.
      const std::array<float, 9> weights = exact_indirect_weights(tables.exact_indirect, seen->sine, seen->direction, normal);
      glm::vec3 radiance(0.0f);
      for (int i = 0; i < 9; ++i)
        for (int c = 0; c < 3; ++c) radiance[c] += weights[std::size_t(i)] * light[std::size_t(c)][std::size_t(i)];
      summed += sphere.weight * (sphere.albedo / kPi * glm::max(radiance, glm::vec3(0.0f)));
    } else {
      float visibility[3];
      tables.proxy_visibility.lookup(seen->sine, std::span<float>(visibility, 3));
      float basis[9];
      sh::evaluate_basis(3, seen->direction, std::span<float>(basis, 9));
      // The zonal kernel K_l: D_l (the averaged operator's polynomial fit) or, for the point
      // operator, K_l = (−1)^l sqrt((2l+1)/4π), whose rotation to d̂ is y(−d̂).
      const auto fit = sh::averaged_indirect_polynomial(seen->sine);
      const glm::vec3 averaged{float(fit[0]), float(fit[1]), float(fit[2])};
      // V_i · H(N) and κ_i = rot(K, d) · L̃, band by band.
      float seen_cosine = 0.0f;
      glm::vec3 kappa(0.0f);
      for (int l = 0; l < 3; ++l) {
        float band_normal = 0.0f;
        glm::vec3 band_light(0.0f);
        for (int m = -l; m <= l; ++m) {
          const int i = l * (l + 1) + m;
          band_normal += basis[i] * normal_basis[i];
          for (int c = 0; c < 3; ++c) band_light[c] += basis[i] * light[std::size_t(c)][std::size_t(i)];
        }
        const float scale = zonal_scale(l);
        seen_cosine += scale * visibility[l] * scale * cosine[l] * band_normal;
        if (op == settings::IndirectOperator::point)
          kappa += (l % 2 == 0 ? 1.0f : -1.0f) * band_light;  // sqrt(4π/(2l+1)) K_l = (−1)^l
        else
          kappa += scale * averaged[l] * band_light;
      }
      summed += sphere.weight * (sphere.albedo / kPi * glm::max(kappa, glm::vec3(0.0f)) * std::max(seen_cosine, 0.0f));
    }
    // ω_i, faded like the tables so the normalization fades with them.
    const float solid_angle = 2.0f * kPi * (1.0f - std::sqrt(std::max(1.0f - seen->sine * seen->sine, 0.0f)));
    result.summed_solid_angle += solid_angle * sh::influence_fade_weight(seen->sine, tables.settings.indirect_eta,
                                                                         tables.proxy_visibility.rows) * sphere.weight;
  }
  if (result.summed_solid_angle > 0.0f) {
    // ξ_p = (V_p)_0 / (ω_p / √4π), V_p = 1 − O_p; clamped to [0, 1] so overlap never brightens.
    // The same for every operator.
    const float covered_dc = std::max(kSqrtFourPi - occlusion_dc, 0.0f);
    const float normalization = std::clamp(covered_dc * kSqrtFourPi / result.summed_solid_angle, 0.0f, 1.0f);
    result.irradiance = summed * normalization;
  }
  return result;
}

UpsampleFootprint upsample_footprint(int x, int y, int k, glm::ivec2 receivers) {
  const glm::vec2 coordinate = (glm::vec2(x, y) + 0.5f) / float(k) - 0.5f;
  const glm::ivec2 base = glm::ivec2(glm::floor(coordinate));
  const glm::vec2 fraction = coordinate - glm::vec2(base);
  UpsampleFootprint footprint;
  for (int tap = 0; tap < 4; ++tap) {
    const glm::ivec2 offset(tap & 1, tap >> 1);
    footprint.source[std::size_t(tap)] = glm::clamp(base + offset, glm::ivec2(0), receivers - 1);
    footprint.bilinear_weight[std::size_t(tap)] =
        (offset.x == 1 ? fraction.x : 1.0f - fraction.x) * (offset.y == 1 ? fraction.y : 1.0f - fraction.y);
  }
  return footprint;
}

glm::vec3 upsample(std::span<const UpsampleTap, 4> taps, const glm::vec3& position, float depth, const glm::vec3& normal,
                   settings::Upsampling mode, float depth_epsilon) {
  return upsample_with_match(taps, position, depth, normal, mode, depth_epsilon).value;
}

Upsampled upsample_with_match(std::span<const UpsampleTap, 4> taps, const glm::vec3& position, float depth, const glm::vec3& normal,
                              settings::Upsampling mode, float depth_epsilon) {
  glm::vec3 total(0.0f), fallback_total(0.0f);
  float weight_sum = 0.0f, bilinear_sum = 0.0f, fallback_sum = 0.0f, best_match = 0.0f;
  for (const auto& tap : taps) {
    if (tap.depth <= 0.0f) continue;
    float factor = 1.0f;  // eq. 11's factor on w^b
    bilinear_sum += tap.bilinear_weight;
    if (mode == settings::Upsampling::bilateral) {
      // F8: the tap's distance to this pixel's tangent plane over its eye depth, so a plane seen
      // at any angle and distance weighs its taps bilinearly (scale-invariant; ε dimensionless).
      const float gap = std::abs(glm::dot(normal, tap.position - position)) / depth;
      const float near_plane = depth_epsilon / (depth_epsilon + gap);
      fallback_total += tap.bilinear_weight * near_plane * tap.value;
      fallback_sum += tap.bilinear_weight * near_plane;
      const float facing = std::max(glm::dot(normal, tap.normal), 0.0f);
      factor = std::pow(facing, 32.0f) * near_plane;
    }
    best_match = std::max(best_match, factor);
    total += tap.bilinear_weight * factor * tap.value;
    weight_sum += tap.bilinear_weight * factor;
  }
  if (weight_sum > 1e-6f * std::max(bilinear_sum, 1e-30f)) return {total / weight_sum, best_match};
  // Fallback: interpolate by bilinear × tangent-plane weight alone (the normals disagree).
  if (fallback_sum > 0.0f) return {fallback_total / fallback_sum, best_match};
  // No weight at all (taps with bilinear weight 0): the valid tap nearest in depth.
  const UpsampleTap* nearest = nullptr;
  for (const auto& tap : taps)
    if (tap.depth > 0.0f && (!nearest || std::abs(tap.depth - depth) < std::abs(nearest->depth - depth))) nearest = &tap;
  return {nearest ? nearest->value : glm::vec3(0.0f), best_match};
}

glm::vec3 tonemap(const glm::vec3& radiance, float exposure, settings::Tonemap curve) {
  const glm::vec3 x = glm::max(radiance * exposure, glm::vec3(0.0f));
  switch (curve) {
    case settings::Tonemap::aces: {  // Narkowicz's fit of the ACES filmic curve
      const glm::vec3 mapped = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
      return glm::clamp(mapped, 0.0f, 1.0f);
    }
    case settings::Tonemap::reinhard: return x / (1.0f + x);
    case settings::Tonemap::clamp: return glm::clamp(x, 0.0f, 1.0f);
  }
  return glm::clamp(x, 0.0f, 1.0f);
}

}  // namespace proxygi::render
