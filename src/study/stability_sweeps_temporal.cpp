// S6 influence fade and S8 LOD switch: sequences of frames on a static receiver set (the exact
// reprojection is the identity), scored with the temporal metrics.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "proxies/lod.h"
#include "scene/scene_defaults.h"
#include "settings/render_settings.h"
#include "study/stability_sweep_parts.h"
#include "world/proxy_lod.h"

namespace proxygi::study {
namespace {

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

// S6's two metrics for one method's blocked light against the truth's, per frame (E units;
// `open` is the truth's unshadowed shade, which sets u).
struct FadeScore {
  double step = 0.0;     // the largest per-frame change minus the truth's, distance ≥ 0.5 η r
  double missing = 0.0;  // the largest blocked light the method misses, distance ≥ 0.7 η r
};
FadeScore score_fade(const std::vector<double>& method, const std::vector<double>& exact, const std::vector<float>& distance_r,
                     double open, float eta) {
  FadeScore score;
  for (std::size_t t = 0; t < method.size(); ++t) {
    if (distance_r[t] >= 0.7f * eta) score.missing = std::max(score.missing, (exact[t] - method[t]) / (open * kDisplayStep));
    // Around the influence boundary only (distance ≥ 0.5 η r): closer in, the change is the shadow's own.
    if (t == 0 || distance_r[t] < 0.5f * eta) continue;
    const ref::Plane x0(1, 1, float(method[t - 1])), x1(1, 1, float(method[t]));
    const ref::Plane r0(1, 1, float(exact[t - 1])), r1(1, 1, float(exact[t]));
    score.step = std::max(score.step, temporal_gradient_error(x0, x1, r0, r1, Reprojection::identity(1, 1)).max / (open * kDisplayStep));
  }
  return score;
}

SweepResult influence_fade(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S6";
  sweep.title = "influence fade: a sphere (r = 0.1 m) approaches a ground receiver from 40r to 2r at 45 deg elevation (n = 4)";
  sweep.x_label = "eta";
  sweep.metrics = {{"entry step (per-frame change minus the truth's, distance >= 0.5 eta r)", "u", 1.0},
                   {"missing shadow (distance >= 0.7 eta r)", "u", 1.0}};
  const float r = 0.1f;
  const int frames = options.quick ? 120 : 240;
  const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
  std::vector<float> distance_r;  // the sphere's center distance / r, per frame
  std::vector<std::vector<render::Sphere>> spheres;
  for (int t = 0; t < frames; ++t) {
    distance_r.push_back(40.0f - 38.0f * float(t) / float(frames - 1));
    spheres.push_back({render::Sphere{direction * (r * distance_r.back()), r, glm::vec3(0.8f)}});
  }
  // Last: η from the lighting (shadow_eta "auto"), at the η it resolves to.
  std::vector<float> etas = options.quick ? std::vector<float>{5, 10, 15, 30} : std::vector<float>{5, 7.5f, 10, 15, 20, 25, 30};
  etas.push_back(settings::kEtaFromLighting);
  const float default_eta = settings::RenderSettings{}.shadow_eta;
  for (SweepLight light : {SweepLight::sky, SweepLight::delta}) {
    const sh::RgbSh lighting = sweep_lighting(light);
    for (float setting : etas) {
      const render::FrameTables tables = sweep_tables(lighting, 4, 8.0, setting);
      const float eta = tables.shadow_eta;
      const std::string name = std::string(light == SweepLight::sky ? "sky" : "delta") +
                               (setting == settings::kEtaFromLighting ? " light, auto eta" : " light");
      const TruthIntegrator truth(tables, 16);
      const double open = truth.unshadowed(glm::dvec3(kUp));
      // Both as blocked light from their own unshadowed shade.
      std::vector<double> method, exact;
      for (int t = 0; t < frames; ++t) {
        const MethodShade shade = shade_method(tables, kTau, glm::vec3(0.0f), kUp, spheres[std::size_t(t)]);
        count_output(sweep, shade);
        method.push_back(shade.unshadowed - shade.value);
        exact.push_back(open - truth.shadowed_one(glm::vec3(0.0f), kUp, spheres[std::size_t(t)][0]));
      }
      const FadeScore twin = score_fade(method, exact, distance_r, open, eta);
      add_point(sweep, "hyb", name, eta, 0, twin.step);
      add_point(sweep, "hyb", name, eta, 1, twin.missing);
      // The baselines: scalar AO (the same influence fade) and the vertex method's interpolation.
      for (const char* baseline : {"ao", "vertex"}) {
        std::vector<double> blocked;
        for (int t = 0; t < frames; ++t) {
          const MethodShade shade = shade_ground_method(baseline, tables, kTau, glm::vec3(0.0f), spheres[std::size_t(t)]);
          count_output(sweep, shade);
          blocked.push_back(shade.unshadowed - shade.value);
        }
        const FadeScore score = score_fade(blocked, exact, distance_r, open, eta);
        add_point(sweep, baseline, std::string(baseline) + ", " + name, eta, 0, score.step);
        add_point(sweep, baseline, std::string(baseline) + ", " + name, eta, 1, score.missing);
      }
      if (setting == settings::kEtaFromLighting)
        sweep.notes.push_back(name + ": eta = " + fixed(eta, 2) + " (c_L = " + fixed(double(eta) * eta * settings::kEtaCutoffError, 2) + ")");
      // The GPU frame's passes at the default and the automatic η: the shadow gather and the raster
      // splat (the splat cuts the influence by its rasterized footprint), against the same truth.
      if (options.gpu != nullptr && (setting == default_eta || setting == settings::kEtaFromLighting))
        for (settings::SplatMethod splat : {settings::SplatMethod::compute, settings::SplatMethod::raster}) {
          auto shaded = options.gpu->shade(tables, splat, spheres);
          const std::string gpu_method = splat == settings::SplatMethod::compute ? "gpu gather" : "gpu splat";
          if (!shaded) {
            sweep.notes.push_back(gpu_method + ", " + name + ": not run: " + shaded.message());
            continue;
          }
          std::vector<double> gpu;
          double from_twin = 0.0;
          for (std::size_t t = 0; t < shaded->size(); ++t) {
            gpu.push_back((*shaded)[t].unshadowed - (*shaded)[t].shadowed);
            from_twin = std::max(from_twin, std::abs(gpu.back() - method[t]) / (open * kDisplayStep));
          }
          const FadeScore score = score_fade(gpu, exact, distance_r, open, eta);
          add_point(sweep, gpu_method, gpu_method + ", " + name, eta, 0, score.step);
          add_point(sweep, gpu_method, gpu_method + ", " + name, eta, 1, score.missing);
          sweep.notes.push_back(gpu_method + ", " + name + " (eta " + fixed(eta, 1) + "): blocked light differs from the CPU twin's by at most " +
                                scientific(from_twin) + "u over the " + std::to_string(frames) + " frames");
        }
      if (setting == default_eta) {  // the default η: the traces behind its two points
        SweepTrace value{"blocked light (u)", "hyb, " + name, {}, {}};
        SweepTrace truth_trace{"blocked light (u)", "truth, " + name, {}, {}};
        SweepTrace change{"per-frame change minus the truth's (u)", "hyb, " + name, {}, {}};
        for (int t = 0; t < frames; ++t) {
          const std::size_t i = std::size_t(t);
          value.x.push_back(distance_r[i]), truth_trace.x.push_back(distance_r[i]);
          value.y.push_back(method[i] / (open * kDisplayStep));
          truth_trace.y.push_back(exact[i] / (open * kDisplayStep));
          if (t > 0) {
            change.x.push_back(distance_r[i]);
            change.y.push_back(((method[i] - method[i - 1]) - (exact[i] - exact[i - 1])) / (open * kDisplayStep));
          }
        }
        sweep.traces.push_back(std::move(value));
        sweep.traces.push_back(std::move(truth_trace));
        sweep.traces.push_back(std::move(change));
      }
    }
  }
  sweep.trace_x_label = "distance of the sphere's center / r (it approaches: time runs right to left), eta = 15";
  sweep.notes.push_back("the fade is over 4 table rows of s = sin(alpha) (about 1.5 % of s's range) below s = 1/eta");
  return sweep;
}

// The pop error at frame t (the second difference over frames t − 1, t, t + 1) of x against the
// reference, both on the same static receivers.
ErrorSummary pop_at(const std::vector<ref::Plane>& x, const std::vector<ref::Plane>& reference, int t,
                    const Reprojection& same) {
  // Frames t − 1, t, t + 1 in place (no copies of the planes).
  const std::span<const ref::Plane, 3> xs(x.data() + (t - 1), 3), rs(reference.data() + (t - 1), 3);
  return pop_error(xs, rs, same, same);
}

// A "character" of 64 spheres (a 4 x 4 x 4 block) and its 8-sphere LOD (one sphere per 2 x 2 x 2
// octant, radius 2r: the same volume up to packing).
std::vector<render::Sphere> block(const glm::vec3& origin, bool coarse) {
  const float r = 0.05f, spacing = 0.09f;
  std::vector<render::Sphere> spheres;
  if (!coarse) {
    for (int i = 0; i < 64; ++i)
      spheres.push_back({origin + spacing * (glm::vec3(float(i % 4), float(i / 4 % 4), float(i / 16)) - glm::vec3(1.5f)), r, glm::vec3(0.8f)});
  } else {
    for (int i = 0; i < 8; ++i)
      spheres.push_back({origin + 2.0f * spacing * (glm::vec3(float(i % 2), float(i / 2 % 2), float(i / 4)) - glm::vec3(0.5f)), 2.0f * r,
                         glm::vec3(0.8f)});
  }
  return spheres;
}

// The mannequin's own levels (proxies/lod.h, world/proxy_lod.h) streamed as the frame streams
// them (weighted spheres, render.proxy_lod auto): its walk pose at t = 0 carried 2 m along +x over
// the same receivers, each level switched to the next at the middle frame, hard or faded over
// settings::kProxyLodFadeFrames frames; the reference keeps the finer level throughout.
void rig_lod_switch(SweepResult& sweep, const render::FrameTables& tables, const std::vector<glm::vec3>& points, int frames,
                    const StabilityOptions& options) {
  scene::Scene scene = scene::default_scene();
  scene.characters[0].path.reset();
  auto world = world::World::load(scene, {.assets_dir = options.assets_dir, .load_rigs = true, .write_rig_cache = false});
  world::WorldState state;
  if (!world || !(*world)->evaluate(0.0, std::nullopt, state)) {
    sweep.notes.push_back("the mannequin's levels: its scene did not load");
    return;
  }
  auto lod = world::ProxyLod::build(**world);
  if (!lod) {
    sweep.notes.push_back("the mannequin's levels: " + lod.message());
    return;
  }
  const proxies::LodLevels& levels = (*lod)->models()[0].levels;
  const std::vector<int> counts = levels.counts();
  const int receivers = int(points.size()), switch_frame = frames / 2;
  std::vector<std::vector<proxies::WorldSphere>> scratch;
  auto shade = [&](int t, proxies::LodChoice choice, float fade) {
    std::vector<proxies::WorldSphere> moved = state.instances[0].spheres;
    for (auto& sphere : moved) sphere.center.x += 2.0f * float(t) / float(frames - 1);
    std::vector<proxies::WeightedSphere> weighted;
    proxies::append_lod_spheres(levels, choice, fade, moved, scratch, weighted);
    std::vector<render::Sphere> spheres;
    for (const auto& w : weighted) spheres.push_back({w.sphere.center, w.sphere.radius, w.sphere.albedo, w.weight});
    ref::Plane out(receivers, 1), open(receivers, 1);
    for (int i = 0; i < receivers; ++i) {
      const glm::vec3& p = points[std::size_t(i)];
      const MethodShade shaded = shade_log_sum(tables, kTau, render::accumulate_log_occlusion(tables, p, kUp, spheres), p, kUp);
      count_output(sweep, shaded);
      out.values[std::size_t(i)] = float(shaded.value);
      open.values[std::size_t(i)] = float(shaded.unshadowed);
    }
    return std::pair{out, open};
  };
  const Reprojection same = Reprojection::identity(receivers, 1);
  for (int level = 0; level + 1 < int(counts.size()); ++level) {
    const std::string series = "mannequin " + std::to_string(counts[std::size_t(level)]) + " -> " +
                               std::to_string(counts[std::size_t(level + 1)]) + " spheres";
    std::vector<ref::Plane> reference;
    double u = 0.0;
    for (int t = 0; t < frames; ++t) {
      auto [value, open] = shade(t, {level, level, 0}, 1.0f);
      reference.push_back(value);
      if (t == 0)
        for (float v : open.values) u += v * kDisplayStep / double(receivers);
    }
    for (int fade : {0, settings::kProxyLodFadeFrames}) {
      std::vector<ref::Plane> x;
      for (int t = 0; t < frames; ++t) {
        const int into = t - switch_frame + 1;  // frames into the fade (1 on the switch frame)
        const proxies::LodChoice choice = into <= 0 ? proxies::LodChoice{level, level, 0}
                                          : fade == 0 || into >= fade ? proxies::LodChoice{level + 1, level + 1, 0}
                                                                      : proxies::LodChoice{level, level + 1, into};
        x.push_back(shade(t, choice, choice.from == choice.to ? 1.0f : float(into) / float(fade)).first);
      }
      double worst = 0.0, mean = 0.0;
      for (int t = 1; t + 1 < frames; ++t) {
        const ErrorSummary pop = pop_at(x, reference, t, same);
        worst = std::max(worst, pop.max / u);
        mean += pop.mean / u / double(frames - 2);
      }
      const std::string method = fade == 0 ? "rig hard" : "rig fade" + std::to_string(fade);
      add_point(sweep, method, series, fade, 0, worst);
      add_point(sweep, method, series, fade, 1, mean);
    }
  }
}

SweepResult lod_switch(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S8";
  sweep.title = "LOD switch: a 64-sphere block walks away over ground receivers, switched to 8 spheres (n = 4, sky)";
  sweep.x_label = "cross-fade frames (0: hard switch)";
  sweep.metrics = {{"pop |a_t(x) - a_t(r)| max", "u", 1.0}, {"pop mean over receivers and frames", "u", 1.0}};
  const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const int frames = options.quick ? 48 : 120;
  const int receivers = options.quick ? 41 : 121;
  const int switch_frame = frames / 2;
  // Receivers on the ground along the walk; the block walks 2 m along +x, 0.35 m up.
  std::vector<glm::vec3> points;
  for (int i = 0; i < receivers; ++i) points.push_back({-0.5f + 3.0f * float(i) / float(receivers - 1), 0.0f, 0.15f});
  auto shade_frame = [&](int t, float fine_weight) {
    const glm::vec3 origin(2.0f * float(t) / float(frames - 1), 0.35f, 0.0f);
    const std::vector<render::Sphere> fine = block(origin, false), coarse = block(origin, true);
    ref::Plane out(receivers, 1), open(receivers, 1);
    for (int i = 0; i < receivers; ++i) {
      const glm::vec3& p = points[std::size_t(i)];
      std::vector<float> f = render::accumulate_log_occlusion(tables, p, kUp, fine);
      const std::vector<float> g = render::accumulate_log_occlusion(tables, p, kUp, coarse);
      // Log sums are linear: the cross-fade blends them (notes F12).
      for (std::size_t j = 0; j < f.size(); ++j) f[j] = fine_weight * f[j] + (1.0f - fine_weight) * g[j];
      const MethodShade shade = shade_log_sum(tables, kTau, f, p, kUp);
      count_output(sweep, shade);
      out.values[std::size_t(i)] = float(shade.value);
      open.values[std::size_t(i)] = float(shade.unshadowed);
    }
    return std::pair{out, open};
  };
  std::vector<ref::Plane> reference;  // the fine set throughout: the pop is the switch's alone
  ref::Plane open;
  for (int t = 0; t < frames; ++t) {
    auto [value, unshadowed] = shade_frame(t, 1.0f);
    reference.push_back(value);
    open = unshadowed;
  }
  const Reprojection same = Reprojection::identity(receivers, 1);
  double u = 0.0;
  for (float v : open.values) u += v * kDisplayStep / double(receivers);
  // Traces at the receiver where the hard switch pops most, and the worst pop over receivers per frame.
  std::size_t watched = 0;
  SweepTrace reference_trace{"shade at the receiver the hard switch pops most at (u)", "reference (64 spheres)", {}, {}};
  for (int fade : {0, 1, 4, 16}) {
    std::vector<ref::Plane> x;
    for (int t = 0; t < frames; ++t) {
      const float weight = fade == 0 ? (t < switch_frame ? 1.0f : 0.0f)
                                     : std::clamp(1.0f - float(t - switch_frame + 1) / float(fade + 1), 0.0f, 1.0f);
      x.push_back(shade_frame(t, weight).first);
    }
    const std::string method = fade == 0 ? "hard" : "fade" + std::to_string(fade);
    double worst = 0.0, mean = 0.0;
    SweepTrace pops{"pop |a_t(x) - a_t(r)|, max over receivers (u)", method, {}, {}};
    for (int t = 1; t + 1 < frames; ++t) {
      const ErrorSummary pop = pop_at(x, reference, t, same);
      worst = std::max(worst, pop.max / u);
      mean += pop.mean / u / double(frames - 2);
      pops.x.push_back(t), pops.y.push_back(pop.max / u);
      if (fade == 0)  // the receiver of the largest hard pop, at the switch
        for (int i = 0; i < receivers && t == switch_frame; ++i) {
          auto a = [&](const std::vector<ref::Plane>& s, int j) {
            return double(s[std::size_t(t + 1)].values[std::size_t(j)]) - 2.0 * s[std::size_t(t)].values[std::size_t(j)] +
                   s[std::size_t(t - 1)].values[std::size_t(j)];
          };
          if (std::abs(a(x, i) - a(reference, i)) > std::abs(a(x, int(watched)) - a(reference, int(watched)))) watched = std::size_t(i);
        }
    }
    if (fade == 0)
      for (int t = 0; t < frames; ++t)
        reference_trace.x.push_back(t), reference_trace.y.push_back(reference[std::size_t(t)].values[watched] / (open.values[watched] * kDisplayStep));
    SweepTrace value{"shade at the receiver the hard switch pops most at (u)", method, {}, {}};
    for (int t = 0; t < frames; ++t) value.x.push_back(t), value.y.push_back(x[std::size_t(t)].values[watched] / (open.values[watched] * kDisplayStep));
    sweep.traces.push_back(std::move(value));
    sweep.traces.push_back(std::move(pops));
    add_point(sweep, method, "64 -> 8 spheres", fade, 0, worst);
    add_point(sweep, method, "64 -> 8 spheres", fade, 1, mean);
  }
  sweep.traces.push_back(std::move(reference_trace));
  sweep.trace_x_label = "frame (the switch at frame " + std::to_string(switch_frame) + ")";
  if (!options.assets_dir.empty()) rig_lod_switch(sweep, tables, points, frames, options);
  return sweep;
}

}  // namespace

SweepResult sweep_influence_fade(const StabilityOptions& options) { return timed(influence_fade, options); }
SweepResult sweep_lod_switch(const StabilityOptions& options) { return timed(lod_switch, options); }

}  // namespace proxygi::study
