#include "render/frame_tables.h"

#include "base/check.h"
#include "sh/convolution.h"

namespace proxygi::render {

FrameTables make_frame_tables(const sh::RgbSh& lighting, const FrameTableSettings& settings) {
  PROXYGI_CHECK(settings.order >= 3 && settings.order <= 6, "frame SH order is 3..6");
  PROXYGI_CHECK(lighting.order >= settings.order, "lighting projected at a lower order than the frame");
  FrameTables tables;
  tables.settings = settings;
  const int count = settings.order * settings.order;
  tables.lighting.order = settings.order;
  for (int channel = 0; channel < 3; ++channel) {
    auto& coefficients = tables.lighting.channels[std::size_t(channel)];
    coefficients.assign(lighting.channels[std::size_t(channel)].begin(),
                        lighting.channels[std::size_t(channel)].begin() + count);
    if (settings.window) sh::apply_ringing_window(settings.order, coefficients);
  }

  tables.log_occlusion = sh::make_log_occlusion_table(settings.order, settings.table_rows);
  sh::apply_influence_fade(tables.log_occlusion, settings.eta_shadow);
  tables.proxy_visibility = sh::make_proxy_visibility_table(3, settings.table_rows);
  sh::apply_influence_fade(tables.proxy_visibility, settings.eta_indirect);
  tables.exact_indirect = sh::make_exact_indirect_table(3, settings.table_rows);
  sh::apply_influence_fade(tables.exact_indirect, settings.eta_indirect);
  tables.optimal_linear = sh::make_optimal_linear_table(settings.order, settings.optimal_linear_rows);

  for (int channel = 0; channel < 3; ++channel)
    tables.lighting_cube[std::size_t(channel)] = sh::make_lighting_cube_map(
        settings.order, tables.lighting.channels[std::size_t(channel)], settings.cube_face_size);

  const std::vector<double> cosine = sh::clamped_cosine_zonal(3);
  for (int channel = 0; channel < 3; ++channel) {
    std::vector<double> irradiance(tables.lighting.channels[std::size_t(channel)].begin(),
                                   tables.lighting.channels[std::size_t(channel)].begin() + 9);
    sh::convolve_zonal(3, cosine, irradiance);
    for (int i = 0; i < 9; ++i) tables.irradiance_order3[std::size_t(channel)][std::size_t(i)] = float(irradiance[std::size_t(i)]);
  }
  return tables;
}

}  // namespace proxygi::render
