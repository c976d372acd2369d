// SH hot paths: basis evaluation, zonal rotation, products, squares and the exponentials per
// order. Run with `proxygi bench micro --filter '^sh/'`.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "sh/basis.h"
#include "sh/environment.h"
#include "sh/exponential.h"
#include "sh/ground_bounce.h"
#include "sh/sender_light.h"
#include "sh/occlusion_tables.h"
#include "sh/product.h"
#include "sh/rotation.h"

namespace {

using namespace proxygi::sh;

// A log vector like a receiver sees: the sum of 4 rotated log-occlusion rows of 10..40 degrees.
template <int Order>
std::vector<float> typical_log_vector() {
  std::mt19937 random(1);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const ZonalTable table = make_log_occlusion_table(Order, 256);
  std::vector<float> f(Order * Order, 0.0f), rotated(Order * Order), zonal(Order);
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 dir = glm::normalize(glm::vec3(unit(random) - 0.5f, unit(random) - 0.5f, unit(random) - 0.5f));
    table.lookup(std::sin((10.0f + 30.0f * unit(random)) * 3.14159265f / 180.0f), zonal);
    rotate_zonal<Order>(zonal.data(), dir, rotated.data());
    for (int i = 0; i < Order * Order; ++i) f[std::size_t(i)] += rotated[std::size_t(i)];
  }
  return f;
}

template <int Order>
void sh_basis(benchmark::State& state) {
  float out[Order * Order];
  glm::vec3 dir = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  for (auto _ : state) {
    evaluate_basis<Order>(dir, out);
    benchmark::DoNotOptimize(out);
    dir.x += 1e-7f;
  }
}

template <int Order>
void sh_rotate_zonal(benchmark::State& state) {
  float zonal[Order] = {}, out[Order * Order];
  for (int l = 0; l < Order; ++l) zonal[l] = 0.1f * float(l + 1);
  const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  for (auto _ : state) {
    benchmark::DoNotOptimize(zonal);
    rotate_zonal<Order>(zonal, dir, out);
    benchmark::DoNotOptimize(out);
  }
}

template <int Order>
void sh_product(benchmark::State& state) {
  const std::vector<float> a = typical_log_vector<Order>();
  std::vector<float> out(a.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(a.data());
    product<Order>(a.data(), a.data(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
}

template <int Order>
void sh_square(benchmark::State& state) {
  const std::vector<float> a = typical_log_vector<Order>();
  std::vector<float> out(a.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(a.data());
    square<Order>(a.data(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
}

template <int Order>
void sh_exp_hybrid(benchmark::State& state) {
  const float tau = float(state.range(0)) / 100.0f;
  const std::vector<float> f = typical_log_vector<Order>();
  const OptimalLinearTable table = make_optimal_linear_table(Order, 256);
  std::vector<float> out(f.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.data());
    exp_hybrid<Order>(f.data(), table, tau, out.data());
    benchmark::DoNotOptimize(out.data());
  }
}

template <int Order>
void sh_exp_optimal_linear(benchmark::State& state) {
  const std::vector<float> f = typical_log_vector<Order>();
  const OptimalLinearTable table = make_optimal_linear_table(Order, 256);
  std::vector<float> out(f.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.data());
    exp_optimal_linear<Order>(f.data(), table, out.data());
    benchmark::DoNotOptimize(out.data());
  }
}

template <int Order>
void sh_exp_product_series(benchmark::State& state) {
  const std::vector<float> f = typical_log_vector<Order>();
  std::vector<float> out(f.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.data());
    exp_product_series<Order>(f.data(), int(state.range(0)), out.data());
    benchmark::DoNotOptimize(out.data());
  }
}

template <int Order>
void sh_exp_exact(benchmark::State& state) {
  const std::vector<float> f = typical_log_vector<Order>();
  const std::vector<double> f_double(f.begin(), f.end());
  for (auto _ : state) benchmark::DoNotOptimize(exp_exact(Order, f_double));
}

}  // namespace

// The frame tables' LH cubes (16² per face) of the default sky, r, g, b: what every table build
// pays, and what the ground bounce adds (E_g, L' and a second set of cubes).
void sh_lighting_cubes(benchmark::State& state) {
  const RgbSh sky = project_sky(4, AnalyticSky{});
  for (auto _ : state)
    for (const auto& channel : sky.channels) benchmark::DoNotOptimize(make_lighting_cube_map(4, channel, 16));
}
BENCHMARK(sh_lighting_cubes)->Name("sh/lighting_cubes/4")->Unit(benchmark::kMillisecond);

void sh_ground_lit_cubes(benchmark::State& state) {
  const RgbSh sky = project_sky(4, AnalyticSky{});
  for (auto _ : state)
    for (const auto& channel : sky.channels) {
      const std::vector<double> lit = replace_below_horizon(4, channel, 0.8 * ground_irradiance(4, channel) / kPi);
      benchmark::DoNotOptimize(make_lighting_cube_map(4, lit, 16));
    }
}
BENCHMARK(sh_ground_lit_cubes)->Name("sh/ground_lit_cubes/4")->Unit(benchmark::kMillisecond);

// The proxies' sender light (sh/sender_light.h): three order-3 cubes of the order-4 sky, 16² per
// face, what render.mask_sender_light adds to every table build.
void sh_sender_light_cubes(benchmark::State& state) {
  const RgbSh sky = project_sky(4, AnalyticSky{});
  for (auto _ : state)
    for (const auto& channel : sky.channels) benchmark::DoNotOptimize(make_sender_light_cube(4, channel, 16));
}
BENCHMARK(sh_sender_light_cubes)->Name("sh/sender_light_cubes/4")->Unit(benchmark::kMillisecond);

#define PROXYGI_SH_BENCHMARKS(ORDER)                                                                                 \
  BENCHMARK(sh_basis<ORDER>)->Name("sh/basis/" #ORDER);                                                              \
  BENCHMARK(sh_rotate_zonal<ORDER>)->Name("sh/rotate_zonal/" #ORDER);                                                \
  BENCHMARK(sh_product<ORDER>)->Name("sh/product/" #ORDER);                                                          \
  BENCHMARK(sh_square<ORDER>)->Name("sh/square/" #ORDER);                                                            \
  BENCHMARK(sh_exp_optimal_linear<ORDER>)->Name("sh/exp_ol/" #ORDER);                                                \
  BENCHMARK(sh_exp_hybrid<ORDER>)->Name("sh/exp_hyb/" #ORDER)->ArgName("tau_percent")->Arg(25)->Arg(100);            \
  BENCHMARK(sh_exp_product_series<ORDER>)->Name("sh/exp_ps/" #ORDER)->ArgName("degree")->Arg(4)->Arg(8);             \
  BENCHMARK(sh_exp_exact<ORDER>)->Name("sh/exp_exact/" #ORDER);
PROXYGI_SH_BENCHMARKS(3)
PROXYGI_SH_BENCHMARKS(4)
PROXYGI_SH_BENCHMARKS(5)
PROXYGI_SH_BENCHMARKS(6)
