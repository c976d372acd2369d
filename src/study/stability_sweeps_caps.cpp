// S2 pass-through, S3 large caps and the HYB switch, S4 order and window.
#include <algorithm>
#include <cmath>
#include <random>

#include "sh/convolution.h"
#include "sh/exponential.h"
#include "sh/occlusion_tables.h"
#include "sh/rotation.h"
#include "study/stability_sweep_parts.h"

namespace proxygi::study {
namespace {

SweepResult pass_through(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S2";
  sweep.title = "pass-through: a sphere of radius r slides through the receiver (n = 4, sky, step r/200)";
  sweep.x_label = "position / r (h: height of the center above the receiver's plane; x: sideways)";
  sweep.metrics = {{"excess step over the truth's", "u", 2.0}, {"error while abs(h) < r", "% of unshadowed", 10.0}};
  const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const TruthIntegrator truth(tables, 32);
  const float r = 0.25f;
  const int stride = options.quick ? 4 : 1;  // quick: step r/50 for the chart, the steps still at r/200
  const double open = truth.unshadowed(glm::dvec3(kUp));
  const glm::vec3 p(0.0f);
  struct Path {
    std::string name;
    glm::vec3 from, to;
  };
  std::vector<Path> paths = {{"vertical", {0.0f, 3.0f * r, 0.0f}, {0.0f, -1.5f * r, 0.0f}}};
  for (float h : {-0.5f, 0.0f, 0.5f}) paths.push_back({"sideways h=" + fixed(h, 1) + "r", {-2.0f * r, h * r, 0.0f}, {2.0f * r, h * r, 0.0f}});
  for (const Path& path : paths) {
    const int steps = int(std::round(glm::length(path.to - path.from) / (r / 200.0f)));
    for (const char* name : {"hyb", "ol", "ao", "vertex"}) {
      double previous_method = 0.0, previous_truth = 0.0, worst_step = 0.0, worst_error = 0.0;
      double worst_step_at = 0.0;
      for (int i = 0; i <= steps; ++i) {
        const glm::vec3 center = path.from + (path.to - path.from) * (float(i) / float(steps));
        const render::Sphere sphere{center, r, glm::vec3(0.8f)};
        const MethodShade shade = shade_ground_method(name, tables, kTau, p, std::span(&sphere, 1));
        count_output(sweep, shade);
        const double exact = truth.shadowed_one(p, kUp, sphere);
        const double blocked_method = shade.unshadowed - shade.value, blocked_truth = open - exact;
        if (i > 0) {
          const double excess = (std::abs(blocked_method - previous_method) - std::abs(blocked_truth - previous_truth)) / (open * kDisplayStep);
          if (excess > worst_step) worst_step = excess, worst_step_at = (path.name == "vertical" ? center.y : center.x) / r;
        }
        previous_method = blocked_method, previous_truth = blocked_truth;
        if (std::abs(center.y) < r) worst_error = std::max(worst_error, 100.0 * std::abs(blocked_method - blocked_truth) / open);
        if (i % (50 * stride) == 0) {
          const double x = (path.name == "vertical" ? center.y : center.x) / r;
          if (std::abs(center.y) < r) add_point(sweep, name, std::string(name) + " " + path.name, x, 1, 100.0 * std::abs(blocked_method - blocked_truth) / open);
        }
      }
      add_point(sweep, name, std::string(name) + " " + path.name + " (max)", 0.0, 0, worst_step);
      sweep.notes.push_back(std::string(name) + " " + path.name + ": largest excess step " + fixed(worst_step, 2) + "u at " +
                            fixed(worst_step_at, 3) + "r; largest error while abs(h) < r " + fixed(worst_error, 1) + " %");
    }
  }
  return sweep;
}

// Log occlusion of one cap of half-angle alpha about direction d (no receiver plane).
std::vector<float> cap_log(int order, double alpha, const glm::dvec3& d) {
  std::vector<double> rotated(std::size_t(order * order));
  sh::rotate_zonal(order, sh::log_occlusion_zonal(order, std::sin(alpha)), d, rotated);
  return std::vector<float>(rotated.begin(), rotated.end());
}

SweepResult large_caps(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S3";
  sweep.title = "large caps and the HYB switch: one cap of half-angle alpha, 2-12 caps around a receiver, |f| through tau 2^s";
  sweep.x_label = "half-angle alpha (deg) / HYB switch norm tau 2^s";
  sweep.metrics = {{"SH-vector error, one cap", "%", 5.0}, {"SH-vector error, several caps", "%", 5.0}, {"HYB switch jump", "u", 1.0}};
  std::vector<double> alphas;
  for (double a = 1.0; a < 89.0; a += options.quick ? 8.0 : 2.0) alphas.push_back(a);
  alphas.push_back(89.9);
  const std::vector<int> orders = {3, 4, 5, 6};
  const glm::dvec3 up(0, 1, 0);
  for (int order : orders) {
    const int count = order * order;
    const sh::OptimalLinearTable table = sh::make_optimal_linear_table(order);
    for (double alpha_degrees : alphas) {
      const double alpha = alpha_degrees * sh::kPi / 180.0;
      const std::vector<float> f = cap_log(order, alpha, up);
      std::vector<double> truth(static_cast<std::size_t>(count));
      sh::rotate_zonal(order, sh::occlusion_zonal(order, std::sin(alpha)), up, truth);
      std::vector<float> out(static_cast<std::size_t>(count));
      auto score = [&](const char* name) {
        bool finite = true;
        for (float v : out) finite = finite && std::isfinite(v);
        const double error = finite ? relative_l2(std::vector<double>(out.begin(), out.end()), truth) : INFINITY;
        add_point(sweep, name, std::string(name) + " n=" + std::to_string(order), alpha_degrees, 0, 100.0 * error);
      };
      sh::exp_hybrid(order, f, table, kTau, out);
      score("hyb");
      sh::exp_optimal_linear(order, f, table, out);
      score("ol");
      sh::exp_product_series(order, f, 8, out);
      score("ps8");
      const std::vector<double> exact = sh::exp_exact(order, std::vector<double>(f.begin(), f.end()));
      out.assign(exact.begin(), exact.end());
      score("exact");
    }
  }
  // Several caps around one receiver: the truth is the projected product, by quadrature.
  const render::FrameTables tables4 = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const TruthIntegrator truth4(tables4, options.quick ? 96 : 160);
  std::mt19937 random(3);
  std::normal_distribution<double> gaussian;
  for (int m : {2, 4, 8, 12}) {
    for (double alpha_degrees : {10.0, 20.0, 30.0}) {
      std::vector<render::Sphere> spheres;
      std::vector<float> f(16, 0.0f);
      for (int i = 0; i < m; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(gaussian(random), gaussian(random), gaussian(random)));
        spheres.push_back({glm::vec3(d * 1.0), float(std::sin(alpha_degrees * sh::kPi / 180.0)), glm::vec3(0.8f)});
        const std::vector<float> one = cap_log(4, alpha_degrees * sh::kPi / 180.0, d);
        for (int j = 0; j < 16; ++j) f[std::size_t(j)] += one[std::size_t(j)];
      }
      const std::vector<double> truth = truth4.visibility_sh(glm::dvec3(0.0), spheres);
      std::vector<float> out(16);
      sh::exp_hybrid(4, f, tables4.optimal_linear, kTau, out);
      const std::string tag = " alpha=" + fixed(alpha_degrees, 0);
      add_point(sweep, "hyb", "hyb n=4" + tag, m, 1, 100.0 * relative_l2(std::vector<double>(out.begin(), out.end()), truth));
      sh::exp_optimal_linear(4, f, tables4.optimal_linear, out);
      add_point(sweep, "ol", "ol n=4" + tag, m, 1, 100.0 * relative_l2(std::vector<double>(out.begin(), out.end()), truth));
      const std::vector<double> exact = sh::exp_exact(4, std::vector<double>(f.begin(), f.end()));
      add_point(sweep, "exact", "exact n=4" + tag, m, 1, 100.0 * relative_l2(exact, truth));
    }
  }
  // The HYB switch: f(t) = t f0 drives |f̂| through tau 2^s; the jump at each switch in shading.
  for (int order : orders) {
    const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), order, 2.0 * order);
    const glm::vec3 direction = glm::normalize(glm::vec3(0.6f, 0.8f, 0.0f));
    const std::vector<float> f0 = cap_log(order, 30.0 * sh::kPi / 180.0, glm::dvec3(direction));
    double norm0 = 0.0;
    for (std::size_t i = 1; i < f0.size(); ++i) norm0 += double(f0[i]) * f0[i];
    norm0 = std::sqrt(norm0);
    double worst = 0.0;
    for (int s = 0; s <= 4; ++s) {
      const double t_switch = kTau * std::ldexp(1.0, s) / norm0;
      auto at = [&](double t) {
        std::vector<float> f(f0.size());
        for (std::size_t i = 0; i < f.size(); ++i) f[i] = float(t * f0[i]);
        const MethodShade shade = shade_log_sum(tables, kTau, f, glm::vec3(0.0f), kUp);
        count_output(sweep, shade);
        return shade;
      };
      const MethodShade below = at(t_switch * (1.0 - 1e-4)), above = at(t_switch * (1.0 + 1e-4));
      const double jump = std::abs(above.value - below.value) / (below.unshadowed * kDisplayStep);
      worst = std::max(worst, jump);
      add_point(sweep, "hyb", "hyb switch n=" + std::to_string(order), kTau * std::ldexp(1.0, s), 2, jump);
    }
    sweep.notes.push_back("HYB n=" + std::to_string(order) + ": largest jump at a squaring switch " + fixed(worst, 2) + "u");
  }
  return sweep;
}

SweepResult order_window(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S4";
  sweep.title = "order and window: ground receivers around a sphere (r = 0.25 m, center 0.5 m up), before the F4 clamp";
  sweep.x_label = "SH order n";
  sweep.metrics = {{"overshoot above unshadowed", "u", 1.0}, {"negativity (-min psi)", "u", 0.0}};
  const float r = 0.25f;
  const render::Sphere sphere{{0.0f, 0.5f, 0.0f}, r, glm::vec3(0.8f)};
  for (SweepLight light : {SweepLight::sky, SweepLight::delta}) {
    const sh::RgbSh lighting = sweep_lighting(light);
    const glm::vec3 sun = glm::vec3(sh::AnalyticSky{}.sun_direction);
    const glm::vec3 across = glm::normalize(glm::vec3(sun.x, 0.0f, sun.z));
    for (int order = 3; order <= 6; ++order)
      for (int w = 0; w < 3; ++w) {
        const double window = w == 0 ? 0.0 : w == 1 ? 2.0 * order : double(order);
        const render::FrameTables tables = sweep_tables(lighting, order, window);
        double overshoot = -INFINITY, negativity = 0.0;
        const int steps = options.quick ? 40 : 160;
        for (int i = 0; i <= steps; ++i) {
          const float x = -2.5f + 5.0f * float(i) / float(steps);
          const glm::vec3 p = -across * x;
          const MethodShade shade = shade_method(tables, kTau, p, kUp, std::span(&sphere, 1));
          count_output(sweep, shade);
          const double u = shade.unshadowed * kDisplayStep;
          overshoot = std::max(overshoot, (shade.unclamped - shade.unshadowed) / u);
          negativity = std::max(negativity, -shade.unclamped / u);
        }
        const std::string series = std::string(light == SweepLight::sky ? "sky" : "delta") + " " +
                                   (w == 0 ? "no window" : w == 1 ? "window h=2n" : "window h=n");
        add_point(sweep, "hyb", series, order, 0, overshoot);
        add_point(sweep, "hyb", series, order, 1, negativity);
      }
  }
  sweep.notes.push_back("the frame clamps E to [0, unshadowed] per channel (F4), so its output stays in bounds; the metrics "
                        "measure what the clamp removes");
  return sweep;
}

}  // namespace

SweepResult sweep_pass_through(const StabilityOptions& options) { return timed(pass_through, options); }
SweepResult sweep_large_caps(const StabilityOptions& options) { return timed(large_caps, options); }
SweepResult sweep_order_window(const StabilityOptions& options) { return timed(order_window, options); }

}  // namespace proxygi::study
