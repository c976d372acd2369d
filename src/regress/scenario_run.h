#pragma once
// One scenario being checked: its world (loaded once, shared with the renderer), a renderer,
// states evaluated with the run's fault, and rendered frames cached by frame number.
// Frames render one at a time (the AOVs and the G-buffer hold only the latest frame).
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "regress/faults.h"
#include "regress/scenario.h"
#include "world/world.h"

namespace proxygi::regress {

// RGBA8 sRGB pixels, row 0 on top.
struct Rgba8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};

enum PixelClass : std::uint8_t { kBackground = 0, kGround = 1, kCharacter = 2 };

struct RenderedFrame {
  int frame = 0;
  Rgba8 final_frame;
  std::vector<std::uint8_t> classes;  // PixelClass per pixel, from the G-buffer
  image::ImageF irradiance;           // E/π, linear float (when asked)
  image::ImageF albedo;               // G-buffer albedo, linear float (when asked)
  const image::ImageF& aov(Aov aov) const;  // irradiance or albedo (not the final frame)
};

// Pixels of `region` (1) in a frame's classes.
std::vector<std::uint8_t> region_mask(const std::vector<std::uint8_t>& classes, Region region);

class ScenarioRun {
 public:
  static Result<std::unique_ptr<ScenarioRun>> create(gpu::Context& context, const Scenario& scenario,
                                                     const std::filesystem::path& assets_dir, const Fault& fault);
  const Scenario& scenario() const { return scenario_; }
  const world::World& world() const { return *world_; }
  gpu::SceneRenderer& renderer() { return *renderer_; }
  const Fault& fault() const { return fault_; }

  // The world at frame `frame` with the fault applied (tracks read it; frames render it).
  Status evaluate(int frame, world::WorldState& state) const;
  // Cached: rendered once per frame (with AOVs when any check asks for them).
  Result<const RenderedFrame*> frame(int frame);
  // Not cached, on this renderer as it is now (differential checks change its settings).
  Result<RenderedFrame> render(int frame, bool aovs);
  // The scenario's settings (with the fault) changed by `overrides`, applied in place.
  Status apply_overrides(const Overrides& overrides);

 private:
  ScenarioRun(const Scenario& scenario, const Fault& fault) : scenario_(scenario), fault_(fault) {}
  const Scenario& scenario_;
  Fault fault_;
  bool aovs_ = false;
  std::shared_ptr<const world::World> world_;
  std::unique_ptr<gpu::SceneRenderer> renderer_;
  std::map<int, RenderedFrame> cache_;
};

}  // namespace proxygi::regress
