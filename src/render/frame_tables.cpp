#include "render/frame_tables.h"

#include <algorithm>
#include <array>

#include "base/check.h"
#include "image/image.h"
#include "shaders/shared/layouts.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/ground_bounce.h"
#include "sh/sender_light.h"
#include "sh/influence_eta.h"
#include "sh/vsgl_sun.h"

namespace proxygi::render {
namespace {

// The frame's lighting coefficients: the first order² of `coefficients` (zero beyond its size),
// ringing-windowed when the settings ask (the window scales each band: linear, per coefficient).
std::vector<double> frame_coefficients(int order, bool window, const std::vector<double>& coefficients) {
  std::vector<double> out(std::size_t(order * order), 0.0);
  std::copy_n(coefficients.begin(), std::min(out.size(), coefficients.size()), out.begin());
  if (window) sh::apply_ringing_window(order, out);
  return out;
}

// Unshadowed irradiance at order 3 (the clamped cosine convolved) of a frame's coefficients.
std::array<float, 9> order3_irradiance(const std::vector<double>& coefficients, const std::vector<double>& cosine) {
  std::vector<double> irradiance(coefficients.begin(), coefficients.begin() + 9);
  sh::convolve_zonal(3, cosine, irradiance);
  std::array<float, 9> out{};
  for (int i = 0; i < 9; ++i) out[std::size_t(i)] = float(irradiance[std::size_t(i)]);
  return out;
}

}  // namespace

int lighting_cube_set(const glm::vec3& p) {
  return p.y > gpu_layout::kGroundBounceMinHeight ? int(gpu_layout::kGroundLitCubes) : 0;
}

FrameTables make_frame_tables(const sh::RgbSh& lighting, const settings::RenderSettings& settings,
                              const GroundInput& ground, const TableResolution& resolution, const SunInput& sun) {
  const int order = settings.sh_order;
  PROXYGI_CHECK(order >= settings::kMinShOrder && order <= settings::kMaxShOrder, "frame SH order out of range");
  PROXYGI_CHECK(lighting.order >= order, "lighting projected at a lower order than the frame");
  FrameTables tables;
  tables.settings = settings;
  tables.resolution = resolution;
  const int count = order * order;
  tables.lighting.order = order;
  for (int channel = 0; channel < 3; ++channel)
    tables.lighting.channels[std::size_t(channel)] =
        frame_coefficients(order, settings.sh_window, lighting.channels[std::size_t(channel)]);

  tables.shadow_eta = settings.shadow_eta;
  if (settings.shadow_eta == settings::kEtaFromLighting) {
    std::vector<double> luminance(std::size_t(count), 0.0);
    for (std::size_t i = 0; i < luminance.size(); ++i)
      luminance[i] = image::rec709_luminance(
          glm::dvec3(tables.lighting.channels[0][i], tables.lighting.channels[1][i], tables.lighting.channels[2][i]));
    tables.shadow_eta = sh::eta_for_cutoff(sh::lighting_concentration(order, luminance), settings::kEtaCutoffError);
  }
  tables.log_occlusion = sh::make_log_occlusion_table(order, resolution.table_rows);
  sh::apply_influence_fade(tables.log_occlusion, tables.shadow_eta);
  tables.proxy_visibility = sh::make_proxy_visibility_table(3, resolution.table_rows);
  sh::apply_influence_fade(tables.proxy_visibility, settings.indirect_eta);
  tables.exact_indirect = sh::make_exact_indirect_table(3, resolution.table_rows);
  sh::apply_influence_fade(tables.exact_indirect, settings.indirect_eta);
  tables.optimal_linear = sh::make_optimal_linear_table(order, resolution.optimal_linear_rows);

  tables.ground_lit = tables.lighting;
  const bool bounce = settings.ground_bounce && ground.enabled;
  for (int channel = 0; channel < 3; ++channel) {
    const auto& sky = tables.lighting.channels[std::size_t(channel)];
    tables.lighting_cube[std::size_t(channel)] = sh::make_lighting_cube_map(order, sky, resolution.cube_face_size);
    const std::size_t lit = gpu_layout::kGroundLitCubes + std::size_t(channel);
    if (!bounce) {
      tables.lighting_cube[lit] = tables.lighting_cube[std::size_t(channel)];
      continue;
    }
    // The ground shows the windowed lighting's unshadowed irradiance (what the frame draws on it).
    const double radiance = std::max(0.0, sh::ground_irradiance(order, sky)) * ground.albedo[channel] / sh::kPi;
    tables.ground_radiance[channel] = float(radiance);
    tables.ground_lit.channels[std::size_t(channel)] = sh::replace_below_horizon(order, sky, radiance);
    tables.lighting_cube[lit] =
        sh::make_lighting_cube_map(order, tables.ground_lit.channels[std::size_t(channel)], resolution.cube_face_size);
  }

  const std::vector<double> cosine = sh::clamped_cosine_zonal(3);
  for (int channel = 0; channel < 3; ++channel)
    tables.irradiance_order3[std::size_t(channel)] = order3_irradiance(tables.lighting.channels[std::size_t(channel)], cosine);
  for (int channel = 0; channel < 3; ++channel) {
    sh::LightingCubeMap& sender = tables.sender_light_cube[std::size_t(channel)];
    if (settings.mask_sender_light) {
      sender = sh::make_sender_light_cube(order, tables.lighting.channels[std::size_t(channel)], resolution.cube_face_size);
      continue;
    }
    // Unmasked: L̃ in every texel, so the lookup returns it exactly (bilinear of equal values).
    const auto& irradiance = tables.irradiance_order3[std::size_t(channel)];
    sender = {3, resolution.cube_face_size, {}};
    for (int texel = 0; texel < 6 * resolution.cube_face_size * resolution.cube_face_size; ++texel)
      sender.values.insert(sender.values.end(), irradiance.begin(), irradiance.end());
  }

  tables.vsgl_sender_order3 = tables.irradiance_order3;
  const sh::SunLight sun_light{glm::dvec3(sun.direction), glm::dvec3(sun.irradiance)};
  tables.vsgl_sun = settings.vsgl_sun == settings::VsglSun::automatic && sun.present && sun_light.above_horizon();
  if (tables.vsgl_sun) {
    PROXYGI_CHECK(sun.lighting.order >= 3, "the sun's SH share is needed at order 3 at least");
    tables.sun_direction = sun.direction;
    tables.sun_irradiance = sun.irradiance;
    for (int channel = 0; channel < 3; ++channel) {
      // L̃ of the windowed (lighting − L_sun), from its first 9 coefficients: the window and the
      // convolution are linear and per band.
      std::vector<double> rest(9);
      for (int i = 0; i < 9; ++i)
        rest[std::size_t(i)] = lighting.channels[std::size_t(channel)][std::size_t(i)] -
                               sun.lighting.channels[std::size_t(channel)][std::size_t(i)];
      tables.vsgl_sender_order3[std::size_t(channel)] =
          order3_irradiance(frame_coefficients(order, settings.sh_window, rest), cosine);
    }
  }
  return tables;
}

}  // namespace proxygi::render
