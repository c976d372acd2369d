// S1–S4 (single frame, receiver sets) and the sweep registry.
#include "study/stability_sweeps.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "sh/basis.h"
#include "sh/exponential.h"
#include "sh/occlusion_tables.h"
#include "sh/rotation.h"
#include "sh/tangent_plane.h"
#include "study/stability_shading.h"
#include "study/stability_sweep_parts.h"

namespace proxygi::study {

std::size_t SweepResult::failures() const {
  return std::size_t(std::count_if(points.begin(), points.end(), [](const SweepPoint& p) { return !p.pass; }));
}

void add_point(SweepResult& sweep, std::string method, std::string series, double x, int metric, double value) {
  const bool finite = std::isfinite(value);
  sweep.points.push_back({std::move(method), std::move(series), x, metric, value,
                          finite && value <= sweep.metrics[std::size_t(metric)].threshold});
}

void count_output(SweepResult& sweep, const MethodShade& shade) {
  ref::Plane value(1, 1, float(shade.value)), open(1, 1, float(shade.unshadowed));
  sweep.bounds.merge(count_bounds(value, open));
}

double blocked_error_u(const MethodShade& shade, double truth_unshadowed, double truth_shadowed) {
  const double u = truth_unshadowed * kDisplayStep;
  return std::abs((shade.unshadowed - shade.value) - (truth_unshadowed - truth_shadowed)) / u;
}

std::string fixed(double value, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

namespace {

// S1: m identical spheres of radius r, centers 2r above the plane, jittered by δr.
SweepResult overlap_stack(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S1";
  sweep.title = "overlap stack: m spheres of radius r, 2r above the plane, centers jittered by delta r (n = 4, sky)";
  sweep.x_label = "spheres m";
  sweep.log_x = true;
  sweep.metrics = {{"shadow error", "u", 4.0}, {"indirect change from m = 1 (delta = 0)", "u", 4.0}};
  const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const TruthIntegrator truth(tables, options.quick ? 96 : 192);
  const float r = 0.25f;
  std::mt19937 random(16);
  std::normal_distribution<float> gaussian;
  std::vector<glm::vec3> jitter(32);
  for (glm::vec3& j : jitter) j = glm::normalize(glm::vec3(gaussian(random), gaussian(random), gaussian(random)));
  const std::vector<float> receivers_x = {0.0f, 0.5f * r, r, 1.5f * r, 2.0f * r, 3.0f * r};
  const std::vector<int> counts = {1, 2, 4, 8, 16, 32};
  double worst_vector_error = 0.0;
  std::string worst_vector;
  for (double delta : {0.0, 0.25, 0.5, 1.0}) {
    double indirect_one = 0.0;
    for (int m : counts) {
      std::vector<render::Sphere> spheres;
      for (int i = 0; i < m; ++i)
        spheres.push_back({glm::vec3(0.0f, 2.0f * r, 0.0f) + float(delta) * r * jitter[std::size_t(i)], r, glm::vec3(0.8f)});
      double error[6] = {0, 0, 0, 0, 0, 0};  // hyb, ol, product, exact, ao, vertex
      double indirect_change = 0.0;
      for (float x : receivers_x) {
        const glm::vec3 p(x, 0.0f, 0.0f);
        const double open = truth.unshadowed(glm::dvec3(kUp));
        const double shadowed = delta == 0.0 ? truth.shadowed_one(p, kUp, spheres.front()) : truth.shadowed(p, kUp, spheres);
        const std::vector<float> f = render::accumulate_log_occlusion(tables, p, kUp, spheres);
        const MethodShade hyb = shade_log_sum(tables, kTau, f, p, kUp);
        const MethodShade ol = shade_log_sum(tables, kOptimalLinearOnly, f, p, kUp);
        const MethodShade product = shade_visibility(tables, product_space_visibility(tables, p, kUp, spheres), p, kUp);
        const std::vector<double> exact = sh::exp_exact(4, std::vector<double>(f.begin(), f.end()));
        const MethodShade exp_exact = shade_visibility(tables, std::vector<float>(exact.begin(), exact.end()), p, kUp);
        const MethodShade ao = shade_ambient_occlusion(tables, p, kUp, spheres);
        const MethodShade vertex = shade_vertex_ground(tables, kTau, p, spheres);
        const MethodShade* shades[6] = {&hyb, &ol, &product, &exp_exact, &ao, &vertex};
        for (int i = 0; i < 6; ++i) {
          error[i] = std::max(error[i], blocked_error_u(*shades[i], open, shadowed));
          count_output(sweep, *shades[i]);
        }
        // The SH-vector error of the log-space result against the projected true product.
        const std::vector<double> true_vector = delta == 0.0 ? [&] {
          std::vector<double> v(16);
          const auto seen = sh::proxy_at_receiver(p, kUp, {spheres.front().center, r});
          sh::rotate_zonal(4, sh::occlusion_zonal(4, seen->sine), glm::dvec3(seen->direction), v);
          return v;
        }()
                                                             : truth.visibility_sh(p, spheres);
        const double vector_error = relative_l2(std::vector<double>(hyb.visibility.begin(), hyb.visibility.end()), true_vector);
        if (vector_error > worst_vector_error)
          worst_vector_error = vector_error, worst_vector = "m = " + std::to_string(m) + ", delta = " + fixed(delta, 2);
        if (delta == 0.0) {
          const render::DirectResult direct = render::exponentiate_and_shade(tables, f, kTau, p, kUp);
          const render::IndirectResult indirect = render::accumulate_indirect(tables, p, kUp, spheres, direct.occlusion_dc);
          const double value = luminance(indirect.irradiance);
          if (m == 1 && x == receivers_x.front()) indirect_one = value;
          if (x == receivers_x.front()) indirect_change = std::abs(value - indirect_one) / (open * kDisplayStep);
        }
      }
      const std::string tag = " delta=" + fixed(delta, 2);
      const char* names[6] = {"hyb", "ol", "product", "exact", "ao", "vertex"};
      for (int i = 0; i < 6; ++i) add_point(sweep, names[i], std::string(names[i]) + tag, m, 0, error[i]);
      if (delta == 0.0) add_point(sweep, "hyb", "indirect, averaged operator", m, 1, indirect_change);
    }
  }
  sweep.notes.push_back("worst SH-vector error of HYB against the projected true product: " + fixed(100 * worst_vector_error, 1) +
                        " % at " + worst_vector);
  return sweep;
}

}  // namespace

SweepResult sweep_overlap_stack(const StabilityOptions& options) { return timed(overlap_stack, options); }

std::vector<std::string> stability_sweep_ids() { return {"S1", "S2", "S3", "S4", "S5", "S6", "S7", "S8", "S9", "S10"}; }

Result<SweepResult> run_stability_sweep(const std::string& id, const StabilityOptions& options) {
  if (id == "S1") return sweep_overlap_stack(options);
  if (id == "S2") return sweep_pass_through(options);
  if (id == "S3") return sweep_large_caps(options);
  if (id == "S4") return sweep_order_window(options);
  if (id == "S5") return sweep_silhouettes(options);
  if (id == "S6") return sweep_influence_fade(options);
  if (id == "S7") return sweep_camera_crawl(options);
  if (id == "S8") return sweep_lod_switch(options);
  if (id == "S9") return sweep_crowd(options);
  if (id == "S10") return sweep_noise_floor(options);
  std::string known;
  for (const std::string& name : stability_sweep_ids()) known += (known.empty() ? "" : ", ") + name;
  return make_error("unknown sweep '" + id + "' (known: " + known + ")");
}

}  // namespace proxygi::study
