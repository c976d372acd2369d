#include "study/chart_regions.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "base/check.h"
#include "render/environment_lighting.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "study/stability_metrics.h"

namespace proxygi::study {
namespace {

bool hit(const image::ImageF& depth, int x, int y) { return depth.at(x, y).r > 0.0f; }

// Summed-area table of a 0/1 grid: sums[(y + 1) * (w + 1) + x + 1] = count over [0, x] × [0, y].
std::vector<int> summed_area(int w, int h, const std::vector<std::uint8_t>& grid) {
  std::vector<int> sums(std::size_t(w + 1) * std::size_t(h + 1), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      sums[std::size_t(y + 1) * std::size_t(w + 1) + std::size_t(x + 1)] =
          int(grid[std::size_t(y) * std::size_t(w) + std::size_t(x)]) + sums[std::size_t(y) * std::size_t(w + 1) + std::size_t(x + 1)] +
          sums[std::size_t(y + 1) * std::size_t(w + 1) + std::size_t(x)] - sums[std::size_t(y) * std::size_t(w + 1) + std::size_t(x)];
  return sums;
}

// Count over the box [x0, x1) × [y0, y1), clipped to the grid.
int box_count(const std::vector<int>& sums, int w, int h, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, w), y1 = std::min(y1, h);
  if (x0 >= x1 || y0 >= y1) return 0;
  auto at = [&](int x, int y) { return sums[std::size_t(y) * std::size_t(w + 1) + std::size_t(x)]; };
  return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
}

}  // namespace

Result<sh::RgbSh> reference_lighting_sh(const scene::Scene& scene, ref::LightingKind kind, int reference_order) {
  const int order = kind == ref::LightingKind::sh ? reference_order : sh::kMaxOrder;
  auto environment = render::make_environment_lighting(scene, order);
  if (!environment) return environment.error();
  sh::RgbSh lighting = std::move(environment->lighting);
  if (kind == ref::LightingKind::sh)
    for (auto& channel : lighting.channels) sh::apply_ringing_window(order, std::span<double>(channel));  // as the reference
  return lighting;
}

image::ImageF unshadowed_radiance(const ref::PixelFeatures& features, const sh::RgbSh& lighting) {
  const int w = features.mask.width, h = features.mask.height, order = lighting.order;
  const std::vector<double> zonal = sh::clamped_cosine_zonal(order);
  std::vector<double> factor(std::size_t(order * order));  // A_l per coefficient
  for (int l = 0; l < order; ++l)
    for (int m = -l; m <= l; ++m)
      factor[std::size_t(sh::coefficient_index(l, m))] = std::sqrt(4.0 * std::numbers::pi / double(2 * l + 1)) * zonal[std::size_t(l)];
  image::ImageF out(w, h, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  std::vector<double> basis(std::size_t(order * order));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (features.mask.at(x, y).r <= 0.5f) continue;
      const glm::dvec3 normal = glm::normalize(glm::dvec3(glm::vec3(features.normal.at(x, y))));
      sh::evaluate_basis(order, normal, basis);
      glm::dvec3 irradiance(0.0);
      for (std::size_t i = 0; i < basis.size(); ++i)
        for (int c = 0; c < 3; ++c) irradiance[c] += factor[i] * lighting.channels[std::size_t(c)][i] * basis[i];
      const glm::dvec3 radiance = glm::dvec3(glm::vec3(features.albedo.at(x, y))) / std::numbers::pi * irradiance;
      out.at(x, y) = glm::vec4(glm::vec3(radiance), 1.0f);
    }
  return out;
}

ref::ReceiverMask shadow_region(const image::ImageF& direct, const image::ImageF& unshadowed, const ref::ReceiverMask& where,
                                double fraction) {
  PROXYGI_CHECK(direct.width == unshadowed.width && direct.height == unshadowed.height && direct.width == where.width &&
                    direct.height == where.height,
                "shadow_region: sizes differ");
  return ref::mask_where(direct.width, direct.height, [&](int x, int y) {
    if (!where.contains(std::size_t(y) * std::size_t(where.width) + std::size_t(x))) return false;
    const double open = image::rec709_luminance(unshadowed.at(x, y));
    return open > 0.0 && image::rec709_luminance(direct.at(x, y)) < (1.0 - fraction) * open;
  });
}

ref::ReceiverMask discontinuity_band(const image::ImageF& depth, const image::ImageF& normal, int radius, double depth_jump,
                                     double normal_jump_degrees) {
  PROXYGI_CHECK(depth.width == normal.width && depth.height == normal.height, "discontinuity_band: sizes differ");
  const int w = depth.width, h = depth.height;
  const double cos_limit = std::cos(normal_jump_degrees * std::numbers::pi / 180.0);
  auto discontinuous = [&](int ax, int ay, int bx, int by) {
    const bool a = hit(depth, ax, ay), b = hit(depth, bx, by);
    if (a != b) return true;
    if (!a) return false;
    const double da = depth.at(ax, ay).r, db = depth.at(bx, by).r;
    if (std::abs(da - db) > depth_jump * std::min(da, db)) return true;
    const glm::vec3 na = glm::vec3(normal.at(ax, ay)), nb = glm::vec3(normal.at(bx, by));
    const double lengths = double(glm::length(na)) * double(glm::length(nb));
    return lengths > 0.0 && double(glm::dot(na, nb)) < cos_limit * lengths;
  };
  std::vector<std::uint8_t> edge(std::size_t(w) * std::size_t(h), 0);
  auto mark = [&](int x, int y) { edge[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x + 1 < w && discontinuous(x, y, x + 1, y)) mark(x, y), mark(x + 1, y);
      if (y + 1 < h && discontinuous(x, y, x, y + 1)) mark(x, y), mark(x, y + 1);
    }
  const std::vector<int> sums = summed_area(w, h, edge);
  return ref::mask_where(w, h, [&](int x, int y) { return box_count(sums, w, h, x - radius, y - radius, x + radius + 1, y + radius + 1) > 0; });
}

ref::ReceiverMask thin_region(const ref::ReceiverMask& mask, int width) {
  PROXYGI_CHECK(width >= 1, "thin_region: width must be positive");
  const int w = mask.width, h = mask.height;
  const std::vector<int> sums = summed_area(w, h, mask.receiver);
  // fits(x, y): the width × width square with top-left corner (x, y) lies inside the mask.
  std::vector<std::uint8_t> fits(std::size_t(w) * std::size_t(h), 0);
  for (int y = 0; y + width <= h; ++y)
    for (int x = 0; x + width <= w; ++x)
      fits[std::size_t(y) * std::size_t(w) + std::size_t(x)] = box_count(sums, w, h, x, y, x + width, y + width) == width * width;
  const std::vector<int> fit_sums = summed_area(w, h, fits);
  return ref::mask_where(w, h, [&](int x, int y) {
    if (!mask.contains(std::size_t(y) * std::size_t(w) + std::size_t(x))) return false;
    // Covered by a fitting square: its corner lies in [x − width + 1, x] × [y − width + 1, y].
    return box_count(fit_sums, w, h, x - width + 1, y - width + 1, x + 1, y + 1) == 0;
  });
}

ChartRegions make_chart_regions(const ReferenceRegionInputs& in, const sh::RgbSh& lighting, const ChartRegionSettings& settings) {
  PROXYGI_CHECK(in.features && in.radiance && in.indirect && in.receivers && in.character && in.character_hits && in.contact,
                "make_chart_regions: an input is missing");
  const int w = in.radiance->width, h = in.radiance->height;
  ChartRegions regions;
  regions.receivers = *in.receivers;
  const image::ImageF unshadowed = unshadowed_radiance(*in.features, lighting);
  image::ImageF direct(w, h);
  regions.upper_bound = image::ImageF(w, h);
  for (std::size_t i = 0; i < direct.pixels.size(); ++i) {
    direct.pixels[i] = in.radiance->pixels[i] - in.indirect->pixels[i];
    regions.upper_bound.pixels[i] = unshadowed.pixels[i] + in.indirect->pixels[i];
  }
  auto masks = [&](ChartRegion r) -> ref::ReceiverMask& { return regions.masks[std::size_t(r)]; };
  masks(ChartRegion::shadow) =
      shadow_region(direct, unshadowed, mask_and_not(*in.receivers, *in.character_hits), settings.shadow_fraction);
  masks(ChartRegion::edge) = mask_and(discontinuity_band(in.features->depth, in.features->normal, settings.edge_radius,
                                                         settings.depth_jump, settings.normal_jump_degrees),
                                      *in.receivers);
  masks(ChartRegion::thin) = mask_and(thin_region(*in.character_hits, settings.thin_width), *in.receivers);
  masks(ChartRegion::character) = mask_and(*in.character, *in.receivers);
  masks(ChartRegion::contact) = mask_and(*in.contact, *in.receivers);
  const ref::ReceiverMask none = ref::mask_where(w, h, [](int, int) { return false; });
  masks(ChartRegion::near_wall) = mask_and(in.near_wall ? *in.near_wall : none, *in.receivers);
  masks(ChartRegion::open_floor) = mask_and(in.open_floor ? *in.open_floor : none, *in.receivers);
  return regions;
}

Result<RegionErrors> score_regions(const image::ImageF& test, const image::ImageF& reference, const ChartRegions& regions) {
  auto relative = ref::relative_mse(test, reference, &regions.receivers);
  if (!relative) return relative.error();
  RegionErrors errors;
  errors.measured = true;
  for (std::size_t r = 0; r < std::size_t(kChartRegionCount); ++r) {
    const ref::ReceiverMask& mask = regions.masks[r];
    for (std::size_t i = 0; i < mask.receiver.size(); ++i)
      if (mask.contains(i)) errors.error_sum[r] += relative->map.values[i], errors.pixels[r] += 1.0;
  }
  for (std::size_t i = 0; i < test.pixels.size(); ++i) {
    if (!regions.receivers.contains(i)) continue;
    const glm::vec4& v = test.pixels[i];
    const glm::vec4& bound = regions.upper_bound.pixels[i];
    bool negative = false, above = false, non_finite = false;
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(v[c])) {
        non_finite = true;
        continue;
      }
      negative = negative || v[c] < 0.0f;
      above = above || double(v[c]) > double(bound[c]) * (1.0 + kDisplayStep);
    }
    errors.negative += negative ? 1.0 : 0.0;
    errors.above_unshadowed += above ? 1.0 : 0.0;
    errors.non_finite += non_finite ? 1.0 : 0.0;
  }
  return errors;
}

}  // namespace proxygi::study
