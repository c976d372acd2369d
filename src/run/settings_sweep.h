#pragma once
// A sweep over a grid of render settings on one live renderer: each setting is applied in place
// (gpu::SceneRenderer::apply_settings rebuilds only what the change needs), so a sweep loads and
// poses its world once instead of once per setting. The chart and the studies walk their grids
// with it, ordered so that consecutive settings share pipelines where they can.
#include <functional>
#include <span>

#include "base/result.h"
#include "gpu/scene_renderer.h"
#include "settings/render_settings.h"

namespace proxygi::run {

using SettingVisitor = std::function<Status(std::size_t index, gpu::SceneRenderer& renderer)>;

// For each grid[i] in order: apply it at the renderer's current size, then visit(i, renderer).
// A visitor error stops the sweep and is returned with the setting's index.
Status sweep_settings(gpu::SceneRenderer& renderer, std::span<const settings::RenderSettings> grid,
                      const SettingVisitor& visit);

}  // namespace proxygi::run
