// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Speed of maximal Poisson-disk sampling against the white-noise floor: drawing the same number of
// uniform random points with CGAL::Polygon_mesh_processing::sample_triangle_mesh on the same mesh, in
// the same process and run. See README.md beside this file for the command and the latest results.
//
// Every case validates its output outside the timed region (exact minimum distance and maximality
// certificate) and reports an error if either fails: quality is not traded for speed.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace PDS = CGAL::Poisson_disk_sampling_3;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

// ---- inputs -------------------------------------------------------------------------------------

const Mesh& mesh(const std::string& name)
{
  static std::map<std::string, std::unique_ptr<Mesh>> cache;
  auto& m = cache[name];
  if(!m) {
    m.reset(new Mesh);
    if(name == "armadillo_loop3") { // 52,000 faces x 4^3: 3.3 million faces
      *m = mesh("armadillo.off");
      CGAL::Subdivision_method_3::Loop_subdivision(*m, CGAL::parameters::number_of_iterations(3));
    } else if(!CGAL::IO::read_polygon_mesh(std::string(CGAL_PDS_DATA_DIR) + "/" + name, *m)) {
      throw std::runtime_error("cannot read " + name);
    }
  }
  return *m;
}

// ---- measurements -------------------------------------------------------------------------------

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Linux: "5" in /proc/self/clear_refs resets the peak resident size (VmHWM) to the current one
double status_bytes(const char* key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.rfind(key, 0) == 0) return 1024. * std::stod(line.substr(line.find(':') + 1));
  return 0;
}
void reset_peak() { std::ofstream("/proc/self/clear_refs") << "5"; }

double white_noise_seconds(const Mesh& m, std::size_t n)
{
  std::vector<Point> points;
  points.reserve(n);
  const auto start = std::chrono::steady_clock::now();
  PMP::sample_triangle_mesh(m, std::back_inserter(points),
                            CGAL::parameters::use_random_uniform_sampling(true)
                                .number_of_points_on_faces(n)
                                .do_sample_vertices(false)
                                .do_sample_edges(false)
                                .random_seed(1));
  const double s = seconds_since(start);
  benchmark::DoNotOptimize(points.data());
  return s;
}

template <class Surface>
bool validate(benchmark::State& state, const Surface& surface, const std::vector<Point>& points, double d)
{
  if(!PDS::is_poisson_disk_set(points, d)) {
    state.SkipWithError("output is not a Poisson-disk set");
    return false;
  }
  if(!PDS::is_maximal(surface, points, d)) {
    state.SkipWithError("output is not maximal");
    return false;
  }
  return true;
}

// ---- cases --------------------------------------------------------------------------------------

// Radius mode on a mesh, with about `n` points; args: n
void mesh_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double area = PMP::area(m);
  const double d = std::sqrt(0.6965 * area / double(state.range(0)));
  std::vector<Point> points;
  double seconds = 0, peak = 0;
  for(auto _ : state) {
    points.clear();
    points.shrink_to_fit();
    reset_peak();
    const double base = status_bytes("VmRSS");
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, std::back_inserter(points), PDS::parameters::minimum_distance(d));
    seconds = seconds_since(start);
    peak = status_bytes("VmHWM") - base;
    state.SetIterationTime(seconds);
  }
  if(!validate(state, m, points, d)) return;
  const double floor = white_noise_seconds(m, points.size());
  const double n = double(points.size()), faces = double(num_faces(m));
  state.counters["points"] = n;
  state.counters["seconds"] = seconds;
  state.counters["points_per_second"] = n / seconds;
  state.counters["faces_per_second"] = faces / seconds;
  state.counters["peak_bytes_per_point"] = peak / n;
  state.counters["memory_budget_use"] = peak / (200 * n + 300 * faces); // <= 1 is the target
  state.counters["floor_seconds"] = floor;
  state.counters["floor_ratio"] = seconds / floor;
}

void sphere_case(benchmark::State& state)
{
  const K::Sphere_3 sphere(CGAL::ORIGIN, 1);
  const double d = std::sqrt(0.6965 * 4 * 3.14159265358979323846 / double(state.range(0)));
  std::vector<Point> points;
  double seconds = 0;
  for(auto _ : state) {
    points.clear();
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_sphere(sphere, std::back_inserter(points), PDS::parameters::minimum_distance(d));
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  if(!validate(state, sphere, points, d)) return;
  state.counters["points"] = double(points.size());
  state.counters["seconds"] = seconds;
  state.counters["points_per_second"] = double(points.size()) / seconds;
}

// number_of_points mode against the radius mode giving the same count: args: n
void count_mode_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const std::size_t n = std::size_t(state.range(0));
  std::vector<Point> points;
  PDS::Sampling_statistics stats;
  double seconds = 0;
  for(auto _ : state) {
    points.clear();
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, std::back_inserter(points),
                              PDS::parameters::number_of_points(n).statistics(std::ref(stats)));
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  if(!validate(state, m, points, stats.minimum_distance)) return;
  std::vector<Point> again;
  const auto start = std::chrono::steady_clock::now();
  PDS::sample_triangle_mesh(m, std::back_inserter(again), PDS::parameters::minimum_distance(stats.minimum_distance));
  const double radius_seconds = seconds_since(start);
  state.counters["points"] = double(points.size());
  state.counters["runs"] = double(stats.number_of_runs);
  state.counters["seconds"] = seconds;
  state.counters["radius_mode_seconds"] = radius_seconds;
  state.counters["count_vs_radius"] = seconds / radius_seconds; // <= 3 is the target
}

// seconds at 1M points over seconds at 100k points, same mesh, same run
void linearity_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double area = PMP::area(m);
  double ratio = 0;
  for(auto _ : state) {
    double s[2];
    int i = 0;
    for(double n : {1e5, 1e6}) {
      std::vector<Point> points;
      const auto start = std::chrono::steady_clock::now();
      PDS::sample_triangle_mesh(m, std::back_inserter(points),
                                PDS::parameters::minimum_distance(std::sqrt(0.6965 * area / n)));
      s[i++] = seconds_since(start);
    }
    ratio = s[1] / s[0];
    state.SetIterationTime(s[0] + s[1]);
  }
  state.counters["seconds_1M_over_100k"] = ratio; // <= 12 is the target
}

void register_cases()
{
  for(const char* name : {"lion.off", "armadillo.off", "armadillo_loop3"})
    for(int n : {10000, 100000, 1000000})
      benchmark::RegisterBenchmark((std::string("mesh/") + name).c_str(),
                                   [name](benchmark::State& s) { mesh_case(s, name); })
          ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {10000, 100000, 1000000})
    benchmark::RegisterBenchmark("sphere", sphere_case)
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100000, 1000000})
    benchmark::RegisterBenchmark("count_mode/lion.off",
                                 [](benchmark::State& s) { count_mode_case(s, "lion.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(const char* name : {"lion.off", "armadillo_loop3"})
    benchmark::RegisterBenchmark((std::string("linearity/") + name).c_str(),
                                 [name](benchmark::State& s) { linearity_case(s, name); })
        ->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
}

} // namespace

int main(int argc, char** argv)
{
  register_cases();
  benchmark::Initialize(&argc, argv);
  if(benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
