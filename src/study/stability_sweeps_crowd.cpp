// S9 crowd (F1, F13): five-sphere characters on a square grid, from spread to clustered, over
// ground receivers. Log-space accumulation double-counts the solid angle that several spheres
// block at once; the sweep measures the shadow error against that overlap and the time per
// receiver against the sphere count, and whether either grows faster than linearly.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "sh/exponential.h"
#include "sh/quadrature.h"
#include "study/stability_sweep_parts.h"

namespace proxygi::study {
namespace {

// N characters on a ceil(√N)-column grid, `spacing` m between neighbouring axes, centred on 0.
std::vector<render::Sphere> crowd(int count, float spacing) {
  const int columns = int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + columns - 1) / columns;
  std::vector<render::Sphere> spheres;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 offset(spacing * (float(i % columns) - 0.5f * float(columns - 1)), 0.0f,
                           spacing * (float(i / columns) - 0.5f * float(rows - 1)));
    for (render::Sphere s : five_sphere_character()) {
      s.center += offset;
      spheres.push_back(s);
    }
  }
  return spheres;
}

// Cosine-weighted solid angle blocked more than once, / π: ∫ max(c(ω) − 1, 0) cos θ dω / π with
// c(ω) the number of spheres the ray from p hits (what a log-space sum counts twice or more).
double redundant_blocking(const sh::SphereQuadrature& hemisphere, const glm::vec3& p, std::span<const render::Sphere> spheres) {
  double sum = 0.0;
  for (std::size_t q = 0; q < hemisphere.size(); ++q) {
    const glm::dvec3 z_up = hemisphere.directions[q];
    const glm::dvec3 d(z_up.x, z_up.z, z_up.y);  // about +Y (a reflection: the integral is the same)
    int hits = 0;
    for (const render::Sphere& s : spheres) {
      const glm::dvec3 offset = glm::dvec3(s.center) - glm::dvec3(p);
      const double c = glm::dot(offset, offset) - double(s.radius) * double(s.radius);
      const double b = glm::dot(offset, d);
      if (c < 0.0 || (b > 0.0 && b * b > c)) ++hits;
    }
    sum += hemisphere.weights[q] * d.y * double(std::max(hits - 1, 0));
  }
  return sum / 3.14159265358979323846;
}

// Least-squares slope of log y against log x over the points with x, y > 0 (0 when fewer than 2).
double log_log_slope(const std::vector<std::pair<double, double>>& points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const auto& [x, y] : points) {
    if (x <= 0.0 || y <= 0.0) continue;
    const double lx = std::log(x), ly = std::log(y);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++n;
  }
  const double denominator = double(n) * sxx - sx * sx;
  return n >= 2 && denominator > 0.0 ? (double(n) * sxy - sx * sy) / denominator : 0.0;
}

SweepResult crowd_sweep(const StabilityOptions& options) {
  SweepResult sweep;
  sweep.id = "S9";
  sweep.title = "crowd: 1-20 five-sphere characters on a grid, spacing 2 m down to 0.4 m, ground receivers (n = 4, sky)";
  sweep.x_label = "redundant blocking (cos-weighted solid angle blocked twice or more, / pi)";
  sweep.log_x = true;
  sweep.metrics = {{"mean shadow error over the ground receivers", "u", 4.0},
                   {"max shadow error over the ground receivers", "u", INFINITY},
                   {"log-log slope of the mean error against redundant blocking", "exponent", 1.0},
                   {"log-log slope of the time per receiver against the sphere count", "exponent", 1.0}};
  const render::FrameTables tables = sweep_tables(sweep_lighting(SweepLight::sky), 4, 8.0);
  const TruthIntegrator truth(tables, options.quick ? 64 : 128);
  const sh::SphereQuadrature hemisphere = sh::make_cap_quadrature(0.0, options.quick ? 24 : 48, options.quick ? 96 : 192);
  const std::vector<int> counts = options.quick ? std::vector<int>{1, 5, 20} : std::vector<int>{1, 2, 5, 10, 20};
  const std::vector<float> spacings = options.quick ? std::vector<float>{1.0f, 0.4f} : std::vector<float>{2.0f, 1.0f, 0.6f, 0.4f};
  const int grid = options.quick ? 6 : 10;
  constexpr int kMethods = 5;
  const char* names[kMethods] = {"hyb", "product", "exact", "ao", "vertex"};
  std::vector<std::pair<double, double>> error_by_overlap[kMethods];
  std::vector<std::pair<double, double>> time_by_spheres;
  std::string worst_text;
  double worst = -1.0, worst_mean[kMethods] = {-1.0, -1.0, -1.0, -1.0, -1.0};
  sweep.heat_maps.resize(kMethods);
  for (float spacing : spacings)
    for (int count : counts) {
      const std::vector<render::Sphere> spheres = crowd(count, spacing);
      // Ground receivers over the crowd's footprint plus 0.5 m.
      float extent = 0.0f;
      for (const render::Sphere& s : spheres) extent = std::max({extent, std::abs(s.center.x), std::abs(s.center.z)});
      extent += 0.5f;
      double sum[kMethods] = {}, peak[kMethods] = {}, overlap = 0.0, hyb_seconds = 0.0;
      std::vector<ref::Plane> error_map(kMethods, ref::Plane(grid, grid));
      int receivers = 0;
      for (int iz = 0; iz < grid; ++iz)
        for (int ix = 0; ix < grid; ++ix) {
          const glm::vec3 p(extent * (2.0f * (float(ix) + 0.5f) / float(grid) - 1.0f), 0.0f,
                            extent * (2.0f * (float(iz) + 0.5f) / float(grid) - 1.0f));
          const double open = truth.unshadowed(glm::dvec3(kUp));
          const double shadowed = truth.shadowed(p, kUp, spheres);
          const auto start = std::chrono::steady_clock::now();
          const MethodShade hyb = shade_method(tables, kTau, p, kUp, spheres);
          hyb_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const MethodShade product = shade_visibility(tables, product_space_visibility(tables, p, kUp, spheres), p, kUp);
          const std::vector<float> f = render::accumulate_log_occlusion(tables, p, kUp, spheres);
          const std::vector<double> exp_f = sh::exp_exact(4, std::vector<double>(f.begin(), f.end()));
          const MethodShade exp_exact = shade_visibility(tables, std::vector<float>(exp_f.begin(), exp_f.end()), p, kUp);
          const MethodShade ao = shade_ambient_occlusion(tables, p, kUp, spheres);
          const MethodShade vertex = shade_vertex_ground(tables, kTau, p, spheres);
          const MethodShade* shades[kMethods] = {&hyb, &product, &exp_exact, &ao, &vertex};
          for (int m = 0; m < kMethods; ++m) {
            const double error = blocked_error_u(*shades[m], open, shadowed);
            sum[m] += error, peak[m] = std::max(peak[m], error);
            error_map[std::size_t(m)].at(ix, iz) = float(error);
            count_output(sweep, *shades[m]);
          }
          overlap += redundant_blocking(hemisphere, p, spheres);
          ++receivers;
        }
      overlap /= double(receivers);
      const std::string series = "spacing " + fixed(spacing, 1) + " m";
      for (int m = 0; m < kMethods; ++m) {
        const double mean = sum[m] / double(receivers);
        add_point(sweep, names[m], std::string(names[m]) + " " + series, overlap, 0, mean);
        add_point(sweep, names[m], std::string(names[m]) + " " + series, overlap, 1, peak[m]);
        error_by_overlap[m].push_back({overlap, mean});
        if (mean > worst_mean[m]) {  // the heat map at this method's worst point (rows: z, columns: x)
          worst_mean[m] = mean;
          sweep.heat_maps[std::size_t(m)] = {std::string(names[m]) + ": " + std::to_string(count) + " characters " + fixed(spacing, 1) +
                                                 " m apart, ground +-" + fixed(extent, 2) + " m, mean " + fixed(mean, 2) + "u",
                                             "u", error_map[std::size_t(m)]};
        }
        if (m == 0 && mean > worst)
          worst = mean, worst_text = std::to_string(count) + " characters " + fixed(spacing, 1) + " m apart: mean " +
                                     fixed(mean, 2) + "u, max " + fixed(peak[m], 1) + "u, redundant blocking " + fixed(overlap, 4);
      }
      time_by_spheres.push_back({double(spheres.size()), hyb_seconds / double(receivers)});
    }
  // One slope per method over the whole sweep, drawn at the largest overlap.
  double widest = 0.0;
  for (const auto& [x, y] : error_by_overlap[0]) widest = std::max(widest, x);
  for (int m = 0; m < kMethods; ++m) add_point(sweep, names[m], names[m], widest, 2, log_log_slope(error_by_overlap[m]));
  add_point(sweep, "hyb", "hyb", widest, 3, log_log_slope(time_by_spheres));
  sweep.notes.push_back("worst mean error of HYB: " + worst_text);
  sweep.notes.push_back("ao: the AO baseline (scalar occlusion, render/baselines.h); vertex: HYB at the vertices of the ground grid's "
                        "triangle around each receiver (6.25 cm spacing), interpolated (study::shade_vertex_ground)");
  sweep.notes.push_back("time: the CPU twin's per-receiver shading (accumulate and exponentiate), measured on this machine; the "
                        "slope is noisy at small sphere counts");
  return sweep;
}

}  // namespace

SweepResult sweep_crowd(const StabilityOptions& options) { return timed(crowd_sweep, options); }

}  // namespace proxygi::study
