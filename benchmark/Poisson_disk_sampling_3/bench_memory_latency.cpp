// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The latency of one memory access that depends on the previous one (a pointer chase through a random
// cycle), by the size of the memory walked. On large sample sets a dart's cost is a few such accesses
// (pool entry, face, bucket), so this sets what a dart costs on a given machine; the design page and
// benchmark/README.md quote it.

#include <benchmark/benchmark.h>

#include <cstddef>
#include <numeric>
#include <random>
#include <vector>

namespace {

// args: megabytes walked
void pointer_chase(benchmark::State& state)
{
  const std::size_t lines = std::size_t(state.range(0)) * 1024 * 1024 / 64;
  // one index a cache line (8 of 8 bytes), visited in a random cycle
  std::vector<std::size_t> order(lines);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
  std::vector<std::size_t> next(lines * 8);
  for(std::size_t i = 0; i < lines; ++i) next[order[i] * 8] = order[(i + 1) % lines] * 8;
  std::size_t p = 0;
  const std::size_t steps = 4000000;
  for(auto _ : state) {
    for(std::size_t i = 0; i < steps; ++i) p = next[p];
    benchmark::DoNotOptimize(p);
  }
  state.counters["ns_per_dependent_load"] =
      benchmark::Counter(double(steps) * double(state.iterations()) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(pointer_chase)->Arg(1)->Arg(8)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
