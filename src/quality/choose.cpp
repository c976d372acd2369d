#include "quality/choose.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "image/image.h"
#include "proxies/lod.h"
#include "quality/calibration.h"
#include "quality/predictors.h"
#include "world/world.h"

namespace proxygi::quality {
namespace {

constexpr int kLightingOrder = 6;

std::string format(const char* pattern, double a) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, a);
  return text;
}

std::string target_name(double target) {
  for (const auto& [name, value] : settings::kQualityLevels)
    if (double(value) == target) return std::string(name) + " (target " + format("%.4g", target) + ")";
  return "target " + format("%.4g", target);
}

}  // namespace

std::string describe(const QualityChoice& choice) {
  if (!choice.automatic) return "quality manual";
  const settings::RenderSettings& s = choice.settings;
  std::string out = "quality " + target_name(choice.target) + ": n" + std::to_string(s.sh_order) + " k" +
                    std::to_string(s.receiver_scale) + " " + std::string(settings::name_of(s.upsampling)) +
                    ", shadow_eta " + (s.shadow_eta == settings::kEtaFromLighting ? std::string("auto") : format("%g", s.shadow_eta)) +
                    ", proxy_lod " + std::string(settings::name_of(s.proxy_lod));
  if (s.method != settings::ShadingMethod::image_space) return out + " (method " + std::string(settings::name_of(s.method)) + ": as written)";
  out += "; predicted relative MSE " + format("%.4f", choice.predicted);
  if (!choice.met) out += " (target not reachable: the lowest predicted)";
  return out;
}

bool ChooseSettingsJob::validate() const {
  if (requested == nullptr || shot == nullptr || out == nullptr) return false;
  if (shot->lighting.size() < std::size_t(kLightingOrder * kLightingOrder)) return false;
  for (const CharacterView& c : shot->characters)
    if (!(c.radius_px > 0.0f) || !std::isfinite(c.radius_px) || c.spheres < 0) return false;
  return true;
}

bool ChooseSettingsJob::run() const {
  if (!validate()) return false;
  QualityChoice& choice = *out;
  choice = QualityChoice{};
  choice.settings = *requested;
  if (requested->quality == settings::kQualityManual) return true;
  choice.automatic = true;
  choice.target = double(requested->quality);
  if (requested->method != settings::ShadingMethod::image_space) {
    choice.reasons.push_back("method " + std::string(settings::name_of(requested->method)) +
                             ": quality chooses image-space settings only; every setting as written");
    return true;
  }

  // The characters' floor and size, weighted by their projected area (their share of the pixels).
  double weight = 0.0, floor = 0.0, radius = 0.0;
  for (const CharacterView& c : shot->characters) {
    const double w = double(c.radius_px) * double(c.radius_px);
    weight += w;
    floor += w * floor_from_fit(c.outside_volume_ratio ? std::optional<double>(*c.outside_volume_ratio) : std::nullopt);
    radius += w * double(c.radius_px);
  }
  choice.floor = weight > 0.0 ? floor / weight : calibration::kUnknownFloor;
  choice.radius_px = weight > 0.0 ? radius / weight : calibration::kReferenceRadiusPx;
  choice.energy = energy_above(shot->lighting);

  // The grid, cheapest first by the chart's time; the first that meets the target wins.
  struct Candidate {
    int order, k;
    settings::Upsampling upsampling;
    double error, ms;
  };
  std::vector<Candidate> grid;
  for (int n = settings::kMinShOrder; n <= settings::kMaxShOrder; ++n)
    for (int k : settings::kReceiverScales)
      for (settings::Upsampling up : {settings::Upsampling::bilinear, settings::Upsampling::bilateral}) {
        if (k == 1 && up == settings::Upsampling::bilateral) continue;  // k = 1 has no upsampling
        grid.push_back({n, k, up, predict_error(choice.floor, choice.energy, n, k, up, choice.radius_px), predicted_ms(n, k, up)});
      }
  const Candidate* best = nullptr;
  const Candidate* lowest = nullptr;
  for (const Candidate& c : grid) {
    if (c.error <= choice.target && (best == nullptr || c.ms < best->ms)) best = &c;
    if (lowest == nullptr || c.error < lowest->error || (c.error == lowest->error && c.ms < lowest->ms)) lowest = &c;
  }
  choice.met = best != nullptr;
  const Candidate& chosen = best != nullptr ? *best : *lowest;
  choice.predicted = chosen.error;
  settings::RenderSettings& s = choice.settings;
  s.sh_order = chosen.order;
  s.receiver_scale = chosen.k;
  if (chosen.k > 1) s.upsampling = chosen.upsampling;
  s.shadow_eta = settings::kEtaFromLighting;

  const std::size_t i = std::size_t(chosen.order - settings::kMinShOrder);
  choice.reasons.push_back("sh_order " + std::to_string(chosen.order) + ": lighting energy above band " +
                           std::to_string(chosen.order) + " is " + format("%.3g", choice.energy[i]) + " (chart " +
                           format("%.3g", calibration::kChartEnergyAbove[i]) + "), order factor R = " +
                           format("%.3f", order_ratio(chosen.order, choice.energy)));
  choice.reasons.push_back("receiver_scale " + std::to_string(chosen.k) + " " + std::string(settings::name_of(chosen.upsampling)) +
                           ": characters " + format("%.0f", choice.radius_px) + " px in radius (reference " +
                           format("%.0f", calibration::kReferenceRadiusPx) + "), k_eff " +
                           format("%.2f", double(chosen.k) * calibration::kReferenceRadiusPx / choice.radius_px) +
                           ", scale factor K = " + format("%.3f", scale_ratio(chosen.k, chosen.upsampling, choice.radius_px)));
  choice.reasons.push_back("floor F = " + format("%.4f", choice.floor) + " from the rigs' outside volume; predicted " +
                           format("%.4f", chosen.error) + (choice.met ? " <= " : " > ") + format("%.4f", choice.target) +
                           (choice.met ? ", the cheapest that meets it" : ": no setting meets it, the lowest predicted"));
  choice.reasons.push_back("shadow_eta auto: sqrt(c_L / (1/255)) from the lighting's concentration");

  // LOD: as requested. The error model has no LOD term, and on the chart (2026-12-04, frame 0 of
  // each scene's quality rows) turning it on raised the chosen setting's error 1.33x on the
  // default scene (0.0103 -> 0.0137) and 1.6x on Fox (0.0050 -> 0.0081) while the LOD saved no
  // time on lavapipe (README "Levels of detail"): choosing it would buy error for nothing.
  float smallest = std::numeric_limits<float>::infinity();
  bool coarser_level = false;
  for (const CharacterView& c : shot->characters) {
    coarser_level = coarser_level || c.radius_px / settings::kProxyLodPixelsPerSphere < float(c.spheres);
    smallest = std::min(smallest, c.radius_px);
  }
  if (shot->characters.empty()) {
    choice.reasons.push_back(std::string("proxy_lod ") + std::string(settings::name_of(s.proxy_lod)) + " as requested: no characters");
  } else {
    choice.reasons.push_back(std::string("proxy_lod ") + std::string(settings::name_of(s.proxy_lod)) +
                             " as requested (not modelled; measured costlier in error, no cheaper): smallest character " +
                             format("%.0f", smallest) + " px, " + format("%g", settings::kProxyLodPixelsPerSphere) +
                             " px per sphere " + (coarser_level ? "would ask for fewer spheres than a rig has" : "needs every rig's spheres"));
  }
  return true;
}

Result<ShotInputs> shot_inputs(const world::World& world, const world::WorldState& state, std::uint32_t height) {
  if (height == 0) return make_error("quality: output height 0");
  ShotInputs shot;
  auto environment = world.environment(kLightingOrder);
  if (!environment) return make_error("quality: " + environment.message());
  const auto& channels = (*environment)->lighting.channels;
  shot.lighting.resize(std::size_t(kLightingOrder * kLightingOrder));
  for (std::size_t i = 0; i < shot.lighting.size(); ++i)
    shot.lighting[i] = image::rec709_luminance(glm::dvec3(channels[0][i], channels[1][i], channels[2][i]));

  const scene::CameraState& camera = state.camera;
  const float focal = float(height) / (2.0f * std::tan(glm::radians(camera.fov_y_degrees) * 0.5f));
  for (std::size_t i = 0; i < state.instances.size() && i < world.instances().size(); ++i) {
    const auto& spheres = state.instances[i].spheres;
    if (spheres.empty()) continue;
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (const auto& s : spheres) lo = glm::min(lo, s.center - s.radius), hi = glm::max(hi, s.center + s.radius);
    const glm::vec3 center = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (const auto& s : spheres) radius = std::max(radius, glm::length(s.center - center) + s.radius);
    CharacterView view;
    view.radius_px = std::max(proxies::projected_radius_pixels(center, radius, camera.eye, focal), 1e-3f);
    const proxies::ProxyRig& rig = world.instances()[i].model->rig;
    view.spheres = int(rig.spheres.size());
    if (rig.has_quality) view.outside_volume_ratio = rig.quality.outside_volume_ratio;
    shot.characters.push_back(view);
  }
  return shot;
}

Result<QualityChoice> choose_for_shot(const world::World& world, const settings::RenderSettings& requested, double time_s,
                                      const std::optional<scene::CameraState>& camera, std::uint32_t height) {
  QualityChoice choice;
  choice.settings = requested;
  if (requested.quality == settings::kQualityManual) return choice;
  world::WorldState state;
  if (Status evaluated = world.evaluate(time_s, camera, state); !evaluated) return make_error("quality: " + evaluated.message());
  auto shot = shot_inputs(world, state, height * std::uint32_t(settings::supersampling_factor(requested.antialiasing)));
  if (!shot) return shot.error();
  ChooseSettingsJob job{&requested, &*shot, &choice};
  if (!job.run()) return make_error("quality: invalid shot inputs (a character with no projected size)");
  return choice;
}

}  // namespace proxygi::quality
