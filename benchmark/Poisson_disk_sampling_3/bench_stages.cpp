// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where a dart's time goes: the engine's clock between the stages of its batches (see Stage_clock in
// internal/Dart_throwing_engine.h), in nanoseconds per dart, on the triangle meshes of
// bench_sampling.cpp. Reading the clock between stages costs a few percent of the run; the shares
// are what this profile is for. See benchmark/README.md.

#define CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include "bench_meshes.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

namespace PDS = CGAL::Poisson_disk_sampling_3;

void stages_case(benchmark::State& state, const std::string& name)
{
  const bench::Mesh& m = bench::mesh(name);
  const double d = bench::distance_for(CGAL::Polygon_mesh_processing::area(m), double(state.range(0)));
  std::vector<bench::Mesh::Face_index> face_of;
  const PDS::Triangle_fragment_traits_3 traits =
      PDS::internal::triangles_of_mesh(m, CGAL::parameters::default_values(), face_of);
  PDS::internal::Engine_statistics stats;
  std::size_t n = 0;
  for(auto _ : state) {
    n = 0;
    PDS::internal::Dart_throwing_engine<PDS::Triangle_fragment_traits_3> engine(traits, d, 0, 100000000);
    stats = engine.run([&](const auto&) { ++n; });
  }
  state.counters["points"] = double(n);
  state.counters["darts_per_point"] = double(stats.darts) / double(n);
  for(int s = 0; s < PDS::internal::number_of_stages; ++s)
    state.counters[std::string("ns_per_dart_") + std::to_string(s) + "_" + PDS::internal::engine_stage_name(s)] =
        1e9 * stats.stage_seconds[std::size_t(s)] / double(stats.darts);
}

} // namespace

int main(int argc, char** argv)
{
  for(const char* name : {"lion.off", "armadillo_loop3"})
    for(int n : {100000, 1000000})
      benchmark::RegisterBenchmark((std::string("stages/") + name).c_str(),
                                   [name](benchmark::State& s) { stages_case(s, name); })
          ->Arg(n)->Iterations(1)->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if(benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
