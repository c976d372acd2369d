// Baseline: the cost of an empty loop iteration, so other numbers can be read against it.
#include <benchmark/benchmark.h>

static void base_empty_iteration(benchmark::State& state) {
  for (auto _ : state) benchmark::ClobberMemory();
}
BENCHMARK(base_empty_iteration)->Name("base/empty_iteration");
