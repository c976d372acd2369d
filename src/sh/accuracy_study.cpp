#include "sh/accuracy_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <random>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/exponential.h"
#include "sh/indirect.h"
#include "sh/occlusion_tables.h"
#include "sh/product.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

using Clock = std::chrono::steady_clock;

struct Sphere {
  glm::vec3 direction;
  float sine;  // sin(half-angle)
};
using Receiver = std::vector<Sphere>;

std::vector<Receiver> make_receivers(const AccuracyStudyOptions& options) {
  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> sphere_count(options.min_spheres, options.max_spheres);
  std::vector<Receiver> receivers(std::size_t(options.receivers));
  for (Receiver& receiver : receivers) {
    receiver.resize(std::size_t(sphere_count(random)));
    for (Sphere& sphere : receiver) {
      const double z = 2.0 * unit(random) - 1.0, phi = 2.0 * kPi * unit(random), r = std::sqrt(1.0 - z * z);
      const double degrees = options.min_half_angle_degrees + (options.max_half_angle_degrees - options.min_half_angle_degrees) * unit(random);
      sphere = {glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)), float(std::sin(degrees * kPi / 180.0))};
    }
  }
  return receivers;
}

// SH projection (order max_order) of the true visibility: 1 where no sphere covers the direction.
std::vector<std::vector<double>> reference_projections(const std::vector<Receiver>& receivers, int max_order,
                                                       const AccuracyStudyOptions& options) {
  const SphereQuadrature grid = make_sphere_quadrature(options.reference_z_nodes, options.reference_phi_samples);
  const std::size_t count = std::size_t(max_order * max_order);
  std::vector<double> basis(grid.size() * count);
  for (std::size_t q = 0; q < grid.size(); ++q) evaluate_basis(max_order, grid.directions[q], std::span<double>(basis.data() + q * count, count));
  std::vector<std::vector<double>> result;
  for (const Receiver& receiver : receivers) {
    std::vector<double> projection(count, 0.0);
    for (std::size_t q = 0; q < grid.size(); ++q) {
      bool visible = true;
      for (const Sphere& sphere : receiver) {
        const double cos_alpha = std::sqrt(1.0 - double(sphere.sine) * sphere.sine);
        if (glm::dot(grid.directions[q], glm::dvec3(sphere.direction)) >= cos_alpha) { visible = false; break; }
      }
      if (!visible) continue;
      const double* row = basis.data() + q * count;
      for (std::size_t i = 0; i < count; ++i) projection[i] += grid.weights[q] * row[i];
    }
    result.push_back(std::move(projection));
  }
  return result;
}

struct Tables {
  ZonalTable visibility, log_occlusion;
  OptimalLinearTable optimal_linear;
};

template <int Order>
void accumulate_log(const Receiver& receiver, const ZonalTable& table, float* f) {
  float zonal[Order], rotated[Order * Order];
  std::fill(f, f + Order * Order, 0.0f);
  for (const Sphere& sphere : receiver) {
    table.lookup(sphere.sine, std::span<float>(zonal, Order));
    rotate_zonal<Order>(zonal, sphere.direction, rotated);
    for (int i = 0; i < Order * Order; ++i) f[i] += rotated[i];
  }
}

template <int Order>
void product_space(const Receiver& receiver, const ZonalTable& table, float* out) {
  constexpr int kCount = Order * Order;
  float zonal[Order], occlusion[kCount], next[kCount];
  bool first = true;
  for (const Sphere& sphere : receiver) {
    table.lookup(sphere.sine, std::span<float>(zonal, Order));
    rotate_zonal<Order>(zonal, sphere.direction, occlusion);
    for (int i = 0; i < kCount; ++i) occlusion[i] = -occlusion[i];
    occlusion[0] += float(kSqrtFourPi);
    if (first) {
      std::copy(occlusion, occlusion + kCount, out);
      first = false;
    } else {
      product<Order>(out, occlusion, next);
      std::copy(next, next + kCount, out);
    }
  }
}

using Evaluate = std::function<int(const Receiver&, float*)>;  // returns HYB squarings (else 0)

template <int Order>
std::vector<std::pair<std::string, Evaluate>> methods(const Tables& tables) {
  constexpr int kCount = Order * Order;
  std::vector<std::pair<std::string, Evaluate>> list;
  list.emplace_back("product", [&tables](const Receiver& r, float* out) { product_space<Order>(r, tables.visibility, out); return 0; });
  list.emplace_back("log_exact", [&tables](const Receiver& r, float* out) {
    float f[kCount];
    accumulate_log<Order>(r, tables.log_occlusion, f);
    const std::vector<double> g = exp_exact(Order, std::vector<double>(f, f + kCount));
    for (int i = 0; i < kCount; ++i) out[i] = float(g[std::size_t(i)]);
    return 0;
  });
  for (int degree : {4, 8})
    list.emplace_back("ps_" + std::to_string(degree), [&tables, degree](const Receiver& r, float* out) {
      float f[kCount];
      accumulate_log<Order>(r, tables.log_occlusion, f);
      exp_product_series<Order>(f, degree, out);
      return 0;
    });
  list.emplace_back("ol", [&tables](const Receiver& r, float* out) {
    float f[kCount];
    accumulate_log<Order>(r, tables.log_occlusion, f);
    exp_optimal_linear<Order>(f, tables.optimal_linear, out);
    return 0;
  });
  for (float tau : {0.25f, 1.0f})
    list.emplace_back(tau == 0.25f ? "hyb_0.25" : "hyb_1", [&tables, tau](const Receiver& r, float* out) {
      float f[kCount];
      accumulate_log<Order>(r, tables.log_occlusion, f);
      return exp_hybrid<Order>(f, tables.optimal_linear, tau, out);
    });
  return list;
}

double percentile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  const double position = fraction * double(values.size() - 1);
  const std::size_t lower = std::size_t(position);
  const std::size_t upper = std::min(lower + 1, values.size() - 1);
  return values[lower] + (position - double(lower)) * (values[upper] - values[lower]);
}

template <int Order>
void study_order(const std::vector<Receiver>& receivers, const std::vector<std::vector<double>>& references,
                 const AccuracyStudyOptions& options, std::vector<ExponentialMethodResult>& results) {
  constexpr int kCount = Order * Order;
  const Tables tables{make_proxy_visibility_table(Order, options.table_rows), make_log_occlusion_table(Order, options.table_rows),
                      make_optimal_linear_table(Order, options.table_rows)};
  for (const auto& [name, evaluate] : methods<Order>(tables)) {
    ExponentialMethodResult result{name, Order};
    std::vector<double> errors;
    long total_squarings = 0;
    float out[kCount];
    for (std::size_t r = 0; r < receivers.size(); ++r) {
      const int squarings = evaluate(receivers[r], out);
      total_squarings += squarings;
      result.max_squarings = std::max(result.max_squarings, squarings);
      double difference = 0.0, norm = 0.0;
      for (int i = 0; i < kCount; ++i) {
        const double expected = references[r][std::size_t(i)];
        difference += (out[i] - expected) * (out[i] - expected);
        norm += expected * expected;
      }
      errors.push_back(std::sqrt(difference / norm));
    }
    double sum = 0.0;
    for (double e : errors) sum += e;
    result.mean_error = sum / double(errors.size());
    result.median_error = percentile(errors, 0.5);
    result.p95_error = percentile(errors, 0.95);
    result.mean_squarings = double(total_squarings) / double(receivers.size());
    // Cost: whole passes over all receivers until the time budget is used.
    volatile float sink = 0.0f;
    long evaluations = 0;
    const Clock::time_point start = Clock::now();
    double elapsed = 0.0;
    do {
      for (const Receiver& receiver : receivers) {
        evaluate(receiver, out);
        sink = sink + out[0];
      }
      evaluations += long(receivers.size());
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < options.min_timing_seconds);
    result.ns_per_evaluation = elapsed * 1e9 / double(evaluations);
    results.push_back(result);
  }
}

}  // namespace

AccuracyStudyResult run_accuracy_study(const AccuracyStudyOptions& options) {
  PROXYGI_CHECK(options.receivers >= 1 && options.min_spheres >= 1 && options.max_spheres >= options.min_spheres, "bad study options");
  const Clock::time_point start = Clock::now();
  AccuracyStudyResult study;
  study.options = options;
  const std::vector<Receiver> receivers = make_receivers(options);
  double sphere_total = 0.0;
  for (const Receiver& receiver : receivers) sphere_total += double(receiver.size());
  study.mean_spheres_per_receiver = sphere_total / double(receivers.size());
  int max_order = 0;
  for (int order : options.orders) {
    PROXYGI_CHECK(has_product(order), "study orders must be 3..6");
    max_order = std::max(max_order, order);
  }
  if (max_order > 0) {
    const std::vector<std::vector<double>> references = reference_projections(receivers, max_order, options);
    for (int order : options.orders) {
      switch (order) {
        case 3: study_order<3>(receivers, references, options, study.exponential); break;
        case 4: study_order<4>(receivers, references, options, study.exponential); break;
        case 5: study_order<5>(receivers, references, options, study.exponential); break;
        default: study_order<6>(receivers, references, options, study.exponential); break;
      }
    }
  }
  for (int order : options.indirect_orders) {
    for (int k = 1; k <= options.indirect_samples; ++k) {
      const double s = double(k) / double(options.indirect_samples + 1);
      const IndirectOperatorErrors errors = indirect_operator_errors(order, s);
      study.indirect.push_back({order, s, errors.point, errors.averaged, errors.averaged_polynomial});
    }
  }
  study.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return study;
}

}  // namespace proxygi::sh
