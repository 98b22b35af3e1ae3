// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where a dart's time goes: the engine's clock between the stages of its batches (see Stage_clock in
// internal/Dart_throwing_engine.h), in nanoseconds per dart, on the triangle meshes of
// bench_sampling.cpp. Reading the clock between stages costs a few percent of the run; the shares
// are what this profile is for. Also the time of the triangle table and of the clusters' index, in
// nanoseconds per face (table/NAME). See benchmark/README.md.

#define CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include "bench_meshes.h"

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
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

// The triangle table and the clusters' index, what every sampling call on the mesh builds first:
// the fastest of `state.range(0)` builds of each, in nanoseconds per face. `ns_per_face_table`,
// the table as the facade builds it from the mesh (internal::triangles_of_mesh); `ns_per_face_add`,
// add_triangle() alone, on corners read from the mesh beforehand; `ns_per_face_first_roots`, the
// first initial_fragments(out, D) at the distance for 10,000 points (where the faces are small
// enough, that call makes the clusters' index), and `ns_per_face_roots` the second.
void table_case(benchmark::State& state, const std::string& name)
{
  const bench::Mesh& m = bench::mesh(name);
  const double d = bench::distance_for(CGAL::Polygon_mesh_processing::area(m), 10000);
  typedef PDS::Triangle_fragment_traits_3::Point P;
  std::vector<std::array<P, 3>> corners;
  for(auto f : faces(m)) {
    std::array<P, 3> c;
    int j = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) {
      const auto& p = m.point(v);
      c[std::size_t(j++)] = P{{p.x(), p.y(), p.z()}};
    }
    corners.push_back(c);
  }
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  double table = 1e300, add = 1e300, first = 1e300, second = 1e300;
  std::size_t roots = 0;
  struct Count
  {
    std::size_t* n;
    Count& operator*() { return *this; }
    Count& operator++(int) { return *this; }
    Count& operator=(const PDS::Triangle_fragment_traits_3::Fragment&) { ++*n; return *this; }
  };
  for(auto _ : state)
    for(std::int64_t k = 0; k < state.range(0); ++k) {
      std::vector<bench::Mesh::Face_index> face_of;
      Clock::time_point t0 = Clock::now();
      {
        const PDS::Triangle_fragment_traits_3 traits =
            PDS::internal::triangles_of_mesh(m, CGAL::parameters::default_values(), face_of);
        benchmark::DoNotOptimize(traits.number_of_triangles());
      }
      Clock::time_point t1 = Clock::now();
      PDS::Triangle_fragment_traits_3 traits;
      traits.reserve(corners.size());
      for(const auto& c : corners) traits.add_triangle(c[0], c[1], c[2]);
      Clock::time_point t2 = Clock::now();
      roots = 0;
      traits.initial_fragments(Count{&roots}, d);
      Clock::time_point t3 = Clock::now();
      traits.initial_fragments(Count{&roots}, d);
      Clock::time_point t4 = Clock::now();
      table = (std::min)(table, seconds(t0, t1));
      add = (std::min)(add, seconds(t1, t2));
      first = (std::min)(first, seconds(t2, t3));
      second = (std::min)(second, seconds(t3, t4));
    }
  const double n = double(corners.size());
  state.counters["faces"] = n;
  state.counters["roots_at_10000_points"] = double(roots) / 2;
  state.counters["ns_per_face_table"] = 1e9 * table / n;
  state.counters["ns_per_face_add"] = 1e9 * add / n;
  state.counters["ns_per_face_first_roots"] = 1e9 * first / n;
  state.counters["ns_per_face_roots"] = 1e9 * second / n;
}

} // namespace

int main(int argc, char** argv)
{
  for(const char* name : {"lion.off", "armadillo_loop3"})
    for(int n : {100000, 1000000})
      benchmark::RegisterBenchmark((std::string("stages/") + name).c_str(),
                                   [name](benchmark::State& s) { stages_case(s, name); })
          ->Arg(n)->Iterations(1)->Unit(benchmark::kMillisecond);
  for(const char* name : {"lion.off", "armadillo.off", "armadillo_loop3"})
    benchmark::RegisterBenchmark((std::string("table/") + name).c_str(),
                                 [name](benchmark::State& s) { table_case(s, name); })
        ->Arg(std::string(name) == "armadillo_loop3" ? 5 : 40)->Iterations(1)->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if(benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
