#pragma once
// Everything the frame's shaders read besides geometry and proxies, built once per lighting and
// settings on the CPU (and uploaded by the GPU frame): the log-occlusion and proxy-visibility ZH
// tables with the sphere-of-influence fade, the OL (a, b) table, the LH(N) cube maps (one per
// colour channel), the order-3 irradiance vector L̃ = L * clamped cosine for indirect light and the
// exact indirect operator M(s) (order 3, faded like the visibility table), and the proxies' sender
// light by receiver normal (sh/sender_light.h).
// Lighting is the environment's SH projection with the ringing window applied. With the ground
// bounce (render.ground_bounce and a ground), receivers above the ground plane read a second set
// of LH cubes built from the ground-lit lighting L' (sh/ground_bounce.h): L above the horizon,
// the lit ground's radiance g = ρ E_g / π below it.
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

// The ground as the frame sees it: the plane y = 0 reaching the horizon, with this albedo
// (scene::Ground), or no ground at all.
struct GroundInput {
  bool enabled = false;
  glm::vec3 albedo{0.0f};  // linear rgb
};

// The scene's sun for the VSGL sun variant (render.vsgl_sun; sh/vsgl_sun.h): its share of the
// `lighting` given to make_frame_tables (sh::project_sun_disc: same order, unwindowed), its
// direction and irradiance. Absent for environment maps (their sun, if any, is in the map).
struct SunInput {
  bool present = false;
  sh::RgbSh lighting;                   // L_sun
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // s: toward the sun, world, unit
  glm::vec3 irradiance{0.0f};           // E_s onto a surface facing the sun, per channel
};

struct FrameTables {
  settings::RenderSettings settings;             // what the tables were built for (sh_order, η, sh_window)
  // η of shadows in use: settings.shadow_eta, or from `lighting` when that is kEtaFromLighting
  // (√(c_L/ε) of its luminance, sh/influence_eta.h). Everything that cuts shadows reads this.
  float shadow_eta = 0.0f;
  TableResolution resolution;
  sh::RgbSh lighting;                          // windowed when settings.sh_window, order = settings.sh_order
  sh::ZonalTable log_occlusion;                // order settings.sh_order, faded at 1/shadow_eta
  sh::ZonalTable proxy_visibility;             // order 3, faded at 1/η_indirect
  sh::OptimalLinearTable optimal_linear;       // order settings.sh_order
  sh::ExactIndirectTable exact_indirect;       // M(s), order 3, faded at 1/η_indirect
  // LH(N) per channel: r, g, b of `lighting` (receivers on the ground), then r, g, b of
  // `ground_lit` (receivers above it, gpu_layout::kGroundLitCubes on): one buffer on the GPU.
  std::array<sh::LightingCubeMap, 6> lighting_cube;
  sh::RgbSh ground_lit;                  // L' (a copy of `lighting` when the bounce is off)
  glm::vec3 ground_radiance{0.0f};       // g = ρ E_g / π per channel (0 when the bounce is off)
  std::array<std::array<float, 9>, 3> irradiance_order3;  // L̃ per channel, order 3
  // The proxies' sender light by receiver normal N, per channel (order 3, 9 values per texel,
  // sh/sender_light.h): L̃_N of the lighting above the receiver's tangent plane, or L̃ in every
  // texel when settings.mask_sender_light is off. The indirect pass reads it in place of L̃.
  std::array<sh::LightingCubeMap, 3> sender_light_cube;
  // The VSGL sun variant: on when settings.vsgl_sun is auto and the sun is above the horizon
  // (the frame uses it with indirect_method vsgl). The vertex VPLs are then lit by the L̃ of
  // lighting − L_sun (windowed like lighting) and the sun's share comes from the sun map.
  bool vsgl_sun = false;
  glm::vec3 sun_direction{0.0f, 1.0f, 0.0f};  // s (vsgl_sun)
  glm::vec3 sun_irradiance{0.0f};             // E_s (vsgl_sun)
  std::array<std::array<float, 9>, 3> vsgl_sender_order3;  // = irradiance_order3 when !vsgl_sun
};

// `lighting` is the unwindowed SH projection of the environment (order ≥ settings.sh_order). Reads
// the table settings of `settings` (sh_order, shadow_eta, indirect_eta, sh_window, ground_bounce,
// mask_sender_light).
// `ground`: the scene's ground (no ground: the ground-lit cubes equal the others).
// `sun`: the scene's sun (sh/vsgl_sun.h); without one, vsgl_sun is off.
FrameTables make_frame_tables(const sh::RgbSh& lighting, const settings::RenderSettings& settings,
                              const GroundInput& ground = {}, const TableResolution& resolution = {},
                              const SunInput& sun = {});

// The first LH cube of the set that lights a receiver at world point p: 0 on (or below) the
// ground plane, gpu_layout::kGroundLitCubes above it (exponentiate.comp's rule).
int lighting_cube_set(const glm::vec3& p);

}  // namespace proxygi::render
