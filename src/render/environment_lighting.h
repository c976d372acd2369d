#pragma once
// A scene's environment as the frame uses it: its SH projection (unwindowed; the frame tables
// window it) and an equirectangular panorama of its radiance in world space for the background
// (sh/environment.h mapping). The analytic sky is projected exactly (sh::project_sky); a map is
// read with image::read_image, rotated about +Y by the scene's rotation, scaled by intensity.
#include "base/result.h"
#include "image/image.h"
#include "render/frame_tables.h"
#include "scene/scene.h"
#include "sh/environment.h"

namespace proxygi::render {

struct EnvironmentLighting {
  sh::RgbSh lighting;        // SH of radiance, the requested order
  image::ImageF background;  // world-space equirectangular radiance
};

// panorama_width × panorama_width/2 background; order 1..8.
Result<EnvironmentLighting> make_environment_lighting(const scene::Scene& scene, int order, int panorama_width = 256);

// The scene's analytic sky in the SH library's terms (scene/environment.h gives the mapping).
sh::AnalyticSky to_sh_sky(const scene::Environment& environment);

// The scene's sun for the VSGL sun variant (render/frame_tables.h SunInput) at SH order `order`:
// present for the analytic sky only.
SunInput scene_sun(const scene::Scene& scene, int order);

}  // namespace proxygi::render
