#include "run/settings_sweep.h"

namespace proxygi::run {

Status sweep_settings(gpu::SceneRenderer& renderer, std::span<const settings::RenderSettings> grid,
                      const SettingVisitor& visit) {
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const gpu::FrameConfig& config = renderer.config();
    if (Status applied = renderer.apply_settings(grid[i], config.width, config.height); !applied)
      return make_error("setting " + std::to_string(i) + ": " + applied.message());
    if (Status visited = visit(i, renderer); !visited)
      return make_error("setting " + std::to_string(i) + ": " + visited.message());
  }
  return {};
}

}  // namespace proxygi::run
