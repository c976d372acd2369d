#include "regress/scenario_run.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "image/image.h"
#include "scene/camera.h"

namespace proxygi::regress {
namespace {

image::ImageF scaled(image::ImageF image, float scale) {
  for (glm::vec4& p : image.pixels) p = glm::vec4(glm::vec3(p) * scale, 1.0f);
  return image;
}

// A shading-resolution readback (render.antialiasing supersamples by f) at the display size:
// each pixel's f × f block averaged (AOVs), or its sample nearest the pixel centre (positions,
// where a mean would mix the character and the ground). f = 1: unchanged.
image::ImageF at_display(image::ImageF image, int width, int height, bool average) {
  if (image.width == width && image.height == height) return image;
  const int f = image.width / width;
  image::ImageF out{width, height};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::vec4 sum(0.0f);
      for (int j = 0; j < f; ++j)
        for (int i = 0; i < f; ++i)
          if (average || (i == f / 2 && j == f / 2)) sum += image.pixels[std::size_t((y * f + j) * image.width + x * f + i)];
      out.pixels[std::size_t(y * width + x)] = average ? sum / float(f * f) : sum;
    }
  return out;
}

}  // namespace

const image::ImageF& RenderedFrame::aov(Aov aov) const { return aov == Aov::albedo ? albedo : irradiance; }

std::vector<std::uint8_t> region_mask(const std::vector<std::uint8_t>& classes, Region region) {
  std::vector<std::uint8_t> mask(classes.size());
  for (std::size_t i = 0; i < classes.size(); ++i)
    mask[i] = region == Region::all || (region == Region::ground && classes[i] == kGround) ||
              (region == Region::character && classes[i] == kCharacter);
  return mask;
}

Result<std::unique_ptr<ScenarioRun>> ScenarioRun::create(gpu::Context& context, const Scenario& scenario,
                                                         const std::filesystem::path& assets_dir, const Fault& fault) {
  std::unique_ptr<ScenarioRun> run(new ScenarioRun(scenario, fault));
  for (const Check& check : scenario.checks) run->aovs_ = run->aovs_ || (check.type == CheckType::image && check.aov != Aov::final_frame);
  auto world = world::World::load(scenario.scene, {assets_dir, true, false});
  if (!world) return make_error(scenario.name + ": " + world.message());
  run->world_ = std::move(*world);
  settings::RenderSettings settings = scenario.scene.render;
  apply_fault(fault, settings);
  auto renderer = gpu::SceneRenderer::create(context, run->world_, settings, std::uint32_t(scenario.scene.output.width),
                                             std::uint32_t(scenario.scene.output.height), 2);
  if (!renderer) return make_error(scenario.name + ": " + renderer.message());
  run->renderer_ = std::move(*renderer);
  return run;
}

Status ScenarioRun::evaluate(int frame, world::WorldState& state) const {
  const scene::Scene& scene = scenario_.scene;
  const double t = scene::frame_time_s(scene.output, frame);
  const double character_t = fault_character_time(fault_, t, scene.output.fps);
  if (Status s = world_->evaluate(character_t, scene::evaluate_scene_camera(scene, t), state); !s) return s;
  state.time_s = t;
  return apply_fault(fault_, *world_, character_t, state);
}

Result<RenderedFrame> ScenarioRun::render(int frame, bool aovs) {
  world::WorldState state;
  if (Status s = evaluate(frame, state); !s) return make_error(scenario_.name + ": frame " + std::to_string(frame) + ": " + s.message());
  gpu::FrameRequest request;
  request.state = &state;
  request.frame = frame;
  request.output = gpu::FrameOutput::readback(false);
  auto finished = renderer_->render(request);
  if (!finished) return make_error(scenario_.name + ": frame " + std::to_string(frame) + ": " + finished.message());
  RenderedFrame out;
  out.frame = frame;
  const int width = int(renderer_->config().width), height = int(renderer_->config().height);
  out.final_frame = Rgba8{width, height, std::move(finished->ldr)};
  auto positions = renderer_->frame().read_gbuffer_positions();
  if (!positions) return positions.error();
  *positions = at_display(std::move(*positions), width, height, false);
  out.classes.resize(positions->pixels.size());
  const bool ground = scenario_.scene.ground.enabled;
  for (std::size_t i = 0; i < positions->pixels.size(); ++i) {
    const glm::vec4 p = positions->pixels[i];
    out.classes[i] = p.w <= 0.0f ? kBackground : (ground && std::abs(p.y) < 1e-3f) ? kGround : kCharacter;
  }
  if (aovs) {
    auto irradiance = renderer_->frame().read_irradiance();
    if (!irradiance) return irradiance.error();
    out.irradiance = scaled(at_display(std::move(*irradiance), width, height, true), float(1.0 / std::numbers::pi));
    auto albedo = renderer_->frame().read_gbuffer_albedo();
    if (!albedo) return albedo.error();
    out.albedo = scaled(at_display(std::move(*albedo), width, height, true), 1.0f);
  }
  return out;
}

Result<const RenderedFrame*> ScenarioRun::frame(int frame) {
  if (auto found = cache_.find(frame); found != cache_.end()) return &found->second;
  auto rendered = render(frame, aovs_);
  if (!rendered) return rendered.error();
  return &cache_.emplace(frame, std::move(*rendered)).first->second;
}

Status ScenarioRun::apply_overrides(const Overrides& overrides) {
  scene::Scene changed = scenario_.scene;
  if (Status s = regress::apply_overrides(changed, overrides); !s) return s;
  apply_fault(fault_, changed.render);
  return renderer_->apply_settings(changed.render, std::uint32_t(changed.output.width), std::uint32_t(changed.output.height));
}

}  // namespace proxygi::regress
