#pragma once
// A scene file's render settings (scene::RenderSettings, output size) mapped onto the GPU frame's
// settings and the frame tables' settings; src/scene has already validated every value.
#include "gpu/frame_settings.h"
#include "render/frame_tables.h"
#include "scene/scene.h"

namespace proxygi::gpu {

// SH order and the shadow and indirect η of the frame tables.
render::FrameTableSettings scene_table_settings(const scene::RenderSettings& render);
// Method, output size, k, HYB/OL, upsampling, indirect operator, splat, tonemap, exposure 2^EV.
FrameSettings scene_frame_settings(const scene::Scene& scene);

}  // namespace proxygi::gpu
