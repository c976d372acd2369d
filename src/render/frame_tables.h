#pragma once
// Everything the frame's shaders read besides geometry and proxies, built once per lighting and
// settings on the CPU (and uploaded by the GPU frame): the log-occlusion and proxy-visibility ZH
// tables with the sphere-of-influence fade, the OL (a, b) table, the LH(N) cube maps (one per
// colour channel), the order-3 irradiance vector L̃ = L * clamped cosine for indirect light and the
// exact indirect operator M(s) (order 3, faded like the visibility table).
// Lighting is the environment's SH projection with the ringing window applied.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "settings/render_settings.h"
#include "sh/environment.h"
#include "sh/exponential.h"
#include "sh/indirect.h"
#include "sh/occlusion_tables.h"

namespace proxygi::render {

// Sizes of the tables (not settings: they are fixed for the frame and the CPU twins alike).
struct TableResolution {
  int table_rows = 256;           // log-occlusion, visibility and exact-indirect tables
  int optimal_linear_rows = 256;  // OL table
  int cube_face_size = 16;        // LH cube map texels per face edge
};

struct FrameTables {
  settings::RenderSettings settings;             // what the tables were built for (sh_order, η, sh_window)
  TableResolution resolution;
  sh::RgbSh lighting;                          // windowed when settings.sh_window, order = settings.sh_order
  sh::ZonalTable log_occlusion;                // order settings.sh_order, faded at 1/η_shadow
  sh::ZonalTable proxy_visibility;             // order 3, faded at 1/η_indirect
  sh::OptimalLinearTable optimal_linear;       // order settings.sh_order
  sh::ExactIndirectTable exact_indirect;       // M(s), order 3, faded at 1/η_indirect
  std::array<sh::LightingCubeMap, 3> lighting_cube;  // LH(N) per channel r, g, b
  std::array<std::array<float, 9>, 3> irradiance_order3;  // L̃ per channel, order 3
};

// `lighting` is the unwindowed SH projection of the environment (order ≥ settings.sh_order). Reads
// the table settings of `settings` (sh_order, shadow_eta, indirect_eta, sh_window).
FrameTables make_frame_tables(const sh::RgbSh& lighting, const settings::RenderSettings& settings,
                              const TableResolution& resolution = {});

}  // namespace proxygi::render
