// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Speed of maximal Poisson-disk sampling against the white-noise floor: drawing the same number of
// uniform random points with CGAL::Polygon_mesh_processing::sample_triangle_mesh on the same mesh, in
// the same process and run. See benchmark/README.md for the command and the latest results.
//
// Every case but count_spread and count_search (small sets at many seeds) validates its output
// outside the timed region (exact minimum distance and maximality certificate) and reports an error
// if either fails: quality is not traded for speed. sampling_only, the case to profile, validates an
// untimed second run (the same seed: as many points), unless the environment variable
// PDS_BENCH_PROFILE is set, so that a profile or a heap peak shows the sampler alone.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/point_generators_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "bench_meshes.h"

#include <benchmark/benchmark.h>
#include <boost/iterator/function_output_iterator.hpp>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <cstdint>
#include <fstream>
#include <new>
#include <optional>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

namespace PDS = CGAL::Poisson_disk_sampling_3;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
using bench::Mesh;
using bench::distance_for;
using bench::mesh;

// ---- measurements -------------------------------------------------------------------------------

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Heap accounting: every allocation of the process goes through these operators, which keep the bytes
// live now and the most live since the last reset. Exact and independent of what the allocator keeps
// cached between cases (resident-size differences are not: they went negative).
std::atomic<long long> live_bytes{0}, peak_bytes{0};

void count_allocation(long long n)
{
  const long long now = live_bytes += n;
  long long peak = peak_bytes.load();
  while(now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {}
}

/// the peak heap use, above what was live at the reset, of what ran since the reset
struct Heap_peak
{
  long long base = live_bytes.load();
  Heap_peak() { peak_bytes = base; }
  double bytes() const { return double(peak_bytes.load() - base); }
};

// Resident memory, where the system tells it (Linux): the peak resident set of the process since the
// reset, above the resident set at the reset, less the file pages that became resident meanwhile (the
// program's code first run during the call, a few hundred kilobytes: memory, but not the data that
// grows with points and faces). The reset first returns the allocator's free pages to the system
// (glibc's malloc_trim), so that pages an earlier case freed and this one reuses count again, then
// resets the kernel's record of the peak (VmHWM) by writing 5 to /proc/self/clear_refs. Pages, not
// bytes: a reserved array whose end is never written is not resident, so this can be below the heap
// peak. bytes() is negative where it cannot be measured; the cases then report no resident counters.
long long status_kilobytes(const char* key)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(key);
  while(std::getline(status, line))
    if(line.compare(0, length, key) == 0 && line.size() > length && line[length] == ':')
      return std::atoll(line.c_str() + length + 1);
  return -1;
}

struct Resident_peak
{
  long long base = -1, base_files = -1;
  Resident_peak()
  {
#if defined(__linux__)
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5" << std::flush;
    if(reset) {
      base = status_kilobytes("VmRSS");
      base_files = status_kilobytes("RssFile");
    }
#endif
  }
  double bytes() const
  {
    if(base < 0 || base_files < 0) return -1;
    const long long peak = status_kilobytes("VmHWM"), files = status_kilobytes("RssFile");
    if(peak < 0 || files < 0) return -1;
    return 1024 * double(peak - base - (files - base_files));
  }
};

// Both peaks of what runs between construction and read(), taken in the order they need: the resident
// reset allocates, so it comes before the heap's base is read; reading the status allocates, so it
// comes after the heap's peak is read.
struct Memory_peak
{
  const Resident_peak pages;
  const Heap_peak heap;
  void read(double& heap_bytes, double& resident_bytes) const
  {
    heap_bytes = heap.bytes();
    resident_bytes = pages.bytes();
  }
};

// The memory counters of a case against its budget (<= 1 is the target): the heap, whose peak does not
// count the mesh, allocated before; and the resident pages, if they could be measured.
void report_memory(benchmark::State& state, double heap, double resident, double n, double budget)
{
  state.counters["peak_heap_bytes_per_point"] = heap / n;
  state.counters["memory_budget_use"] = heap / budget;
  if(resident < 0) return;
  state.counters["peak_resident_bytes_per_point"] = resident / n;
  state.counters["resident_budget_use"] = resident / budget;
}

// The white-noise floor: the fastest of five runs of `draw(points)`, which writes n uniform random
// points into `points` (reserved for them): a run this short is easily disturbed, and the minimum makes
// floor_ratio err on the high side.
template <class Draw>
double fastest_of_five(std::size_t n, Draw draw)
{
  double best = 1e300;
  for(int run = 0; run < 5; ++run) {
    std::vector<Point> points;
    points.reserve(n);
    const auto start = std::chrono::steady_clock::now();
    draw(points);
    best = (std::min)(best, seconds_since(start));
    benchmark::DoNotOptimize(points.data());
  }
  return best;
}

// n uniform random points on the mesh with CGAL's sampler
double white_noise_seconds(const Mesh& m, std::size_t n)
{
  return fastest_of_five(n, [&](std::vector<Point>& points) {
    PMP::sample_triangle_mesh(m, std::back_inserter(points),
                              CGAL::parameters::use_random_uniform_sampling(true)
                                  .number_of_points_on_faces(n)
                                  .do_sample_vertices(false)
                                  .do_sample_edges(false)
                                  .random_seed(1));
  });
}

// A case's error: reported as the case's, and the program's exit status is 1 (see main()), so that a
// script that runs the benchmark sees it.
bool any_case_failed = false;

void fail(benchmark::State& state, const std::string& message)
{
  any_case_failed = true;
  state.SkipWithError(message.c_str());
}

// Checks the output, outside the timed region; reports how long each check took (what a user who
// validates a result waits for, beside the sampling itself), unless `report_seconds` is false.
template <class Surface>
bool validate(benchmark::State& state, const Surface& surface, const std::vector<Point>& points, double d,
              bool report_seconds = true)
{
  auto start = std::chrono::steady_clock::now();
  if(!PDS::is_poisson_disk_set(points, d)) {
    fail(state, "output is not a Poisson-disk set");
    return false;
  }
  if(report_seconds) state.counters["check_seconds"] = seconds_since(start);
  start = std::chrono::steady_clock::now();
  if(!PDS::is_maximal(surface, points, d)) {
    fail(state, "output is not maximal");
    return false;
  }
  if(report_seconds) state.counters["certify_seconds"] = seconds_since(start);
  return true;
}

// ---- cases --------------------------------------------------------------------------------------

// The cases that compare variants (two sizes, with and without a test) run them in turn,
// `comparison_runs` times each, and keep the fastest of each: a change of the host's speed during the
// case (which moves a single run by 10 to 20% on the machine of benchmark/README.md) then weighs on
// all alike. `run(v)` runs variant v (0 to N - 1) once; returns the fastest seconds of each variant
// and sets the case's time to the total.
constexpr int comparison_runs = 3;
template <std::size_t N = 2, class Run>
std::array<double, N> fastest_alternating(benchmark::State& state, Run run)
{
  std::array<double, N> best;
  best.fill(1e300);
  for(auto _ : state) {
    double total = 0;
    for(int r = 0; r < comparison_runs; ++r)
      for(std::size_t v = 0; v < N; ++v) {
        const auto start = std::chrono::steady_clock::now();
        run(v);
        const double s = seconds_since(start);
        best[v] = std::min(best[v], s);
        total += s;
      }
    state.SetIterationTime(total);
  }
  state.counters["runs"] = comparison_runs;
  return best;
}

// Radius mode on a mesh, with about `n` points; args: n
void mesh_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double area = PMP::area(m);
  const double d = distance_for(area, double(state.range(0)));
  std::vector<Point> points;
  double seconds = 0, peak = 0, resident = 0;
  PDS::Sampling_statistics stats;
  for(auto _ : state) {
    points.clear();
    points.shrink_to_fit();
    const Memory_peak memory;
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, std::back_inserter(points), PDS::parameters::minimum_distance(d).statistics(std::ref(stats)));
    seconds = seconds_since(start);
    memory.read(peak, resident);
    state.SetIterationTime(seconds);
  }
  if(!validate(state, m, points, d)) return;
  const double floor = white_noise_seconds(m, points.size());
  const double n = double(points.size()), faces = double(num_faces(m));
  state.counters["points"] = n;
  state.counters["seconds"] = seconds;
  state.counters["points_per_second"] = n / seconds;
  state.counters["faces_per_second"] = faces / seconds;
  report_memory(state, peak, resident, n, 200 * n + 300 * faces);
  state.counters["peak_active_fragments_per_point"] = double(stats.peak_active_fragments) / n;
  state.counters["floor_seconds"] = floor;
  state.counters["floor_ratio"] = seconds / floor;
}

// n uniform random points on the sphere with CGAL's generator
double white_noise_seconds(const K::Sphere_3& sphere, std::size_t n)
{
  return fastest_of_five(n, [&](std::vector<Point>& points) {
    CGAL::Random rng(1);
    CGAL::Random_points_on_sphere_3<Point> g(std::sqrt(sphere.squared_radius()), rng);
    for(std::size_t i = 0; i < n; ++i, ++g) points.push_back(*g + (sphere.center() - CGAL::ORIGIN));
  });
}

void sphere_case(benchmark::State& state)
{
  const K::Sphere_3 sphere(CGAL::ORIGIN, 1);
  const double d = distance_for(4 * 3.14159265358979323846, double(state.range(0)));
  std::vector<Point> points;
  PDS::Sampling_statistics stats;
  double seconds = 0, peak = 0, resident = 0;
  for(auto _ : state) {
    points.clear();
    points.shrink_to_fit();
    const Memory_peak memory;
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_sphere(sphere, std::back_inserter(points), PDS::parameters::minimum_distance(d).statistics(std::ref(stats)));
    seconds = seconds_since(start);
    memory.read(peak, resident);
    state.SetIterationTime(seconds);
  }
  if(!validate(state, sphere, points, d)) return;
  const double floor = white_noise_seconds(sphere, points.size());
  const double n = double(points.size());
  state.counters["points"] = n;
  state.counters["seconds"] = seconds;
  state.counters["points_per_second"] = n / seconds;
  state.counters["darts_per_point"] = double(stats.darts) / n;
  report_memory(state, peak, resident, n, 200 * n); // no faces: 200 bytes a point
  state.counters["peak_active_fragments_per_point"] = double(stats.peak_active_fragments) / n;
  state.counters["floor_seconds"] = floor;
  state.counters["floor_ratio"] = seconds / floor;
}

// The number_of_points mode at `seed` on `m`, and the radius mode at the distance and seed its
// search settled on, in turn, `comparison_runs` times each (the fastest of each is kept, see
// fastest_alternating()): checks that each run of the count mode gives the same points, that the
// radius mode gives as many, and validates the output (outside the timings). Returns false if a
// check failed (the case's error is set). The first run of each mode measures the heap's peak, the
// output vector included, as in mesh/.
struct Count_run
{
  std::size_t points = 0, runs = 0, stopped_runs = 0;
  double seconds = 1e300, radius_seconds = 1e300, peak_heap = 0, radius_peak_heap = 0;
};
bool count_and_radius(benchmark::State& state, const Mesh& m, std::size_t n, std::uint64_t seed, Count_run& out,
                      bool report_check_seconds)
{
  std::vector<Point> first;
  PDS::Sampling_statistics stats;
  for(int r = 0; r < comparison_runs; ++r) {
    std::vector<Point> points, again;
    const Heap_peak heap;
    auto start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, std::back_inserter(points),
                              PDS::parameters::number_of_points(n).random_seed(seed).statistics(std::ref(stats)));
    out.seconds = (std::min)(out.seconds, seconds_since(start));
    if(r == 0) out.peak_heap = heap.bytes();
    const Heap_peak radius_heap;
    start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, std::back_inserter(again), PDS::parameters::minimum_distance(stats.minimum_distance)
                                                                .random_seed(stats.random_seed));
    out.radius_seconds = (std::min)(out.radius_seconds, seconds_since(start));
    if(r == 0) out.radius_peak_heap = radius_heap.bytes();
    if(again.size() != points.size()) {
      fail(state, "the radius mode at the distance and seed the search settled on gave another number of points");
      return false;
    }
    if(r == 0) {
      first = std::move(points);
    } else if(points != first) {
      fail(state, "the count mode gave other points at the same seed");
      return false;
    }
  }
  out.points = first.size();
  out.runs = stats.number_of_runs;
  out.stopped_runs = stats.stopped_runs;
  return validate(state, m, first, stats.minimum_distance, report_check_seconds);
}

// number_of_points mode against the radius mode giving the same count, at the default seed (0), the
// fastest of three alternating runs of each: args: n. On the strips, the sheets and the tubes, where
// the search takes several full runs and its time depends on where they land, the same for seeds 1 to
// 4 (their smallest and largest ratio).
void count_mode_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const std::size_t n = std::size_t(state.range(0));
  Count_run run;
  for(auto _ : state) {
    if(!count_and_radius(state, m, n, 0, run, true)) return;
    state.SetIterationTime(run.seconds); // the fastest of the count mode's runs
  }
  state.counters["points"] = double(run.points);
  state.counters["runs"] = double(run.runs);
  state.counters["stopped_runs"] = double(run.stopped_runs);
  state.counters["seconds"] = run.seconds;
  state.counters["radius_mode_seconds"] = run.radius_seconds;
  state.counters["count_vs_radius"] = run.seconds / run.radius_seconds; // <= 3 is the target
  const double budget = 200 * double(run.points) + 300 * double(num_faces(m));
  report_memory(state, run.peak_heap, -1, double(run.points), budget);
  state.counters["radius_mode_memory_budget_use"] = run.radius_peak_heap / budget;
  if(name.rfind("strips", 0) == 0 || name == "sheets" || name == "tubes") {
    double lowest = std::numeric_limits<double>::infinity(), highest = 0;
    std::size_t fewest_runs = std::size_t(-1), most_runs = 0;
    for(std::uint64_t seed = 1; seed <= 4; ++seed) {
      Count_run other;
      if(!count_and_radius(state, m, n, seed, other, false)) return;
      lowest = (std::min)(lowest, other.seconds / other.radius_seconds);
      highest = (std::max)(highest, other.seconds / other.radius_seconds);
      fewest_runs = (std::min)(fewest_runs, other.runs);
      most_runs = (std::max)(most_runs, other.runs);
    }
    state.counters["count_vs_radius_seeds_1_to_4_min"] = lowest;
    state.counters["count_vs_radius_seeds_1_to_4_max"] = highest;
    state.counters["runs_seeds_1_to_4_min"] = double(fewest_runs);
    state.counters["runs_seeds_1_to_4_max"] = double(most_runs);
  }
}

// Small targets, whose count spreads from seed to seed by more than the 1% tolerance: the search over
// 1,000 seeds (0 to 999), how many of them fail with Target_not_reached, the mean and the largest
// number of runs. Outputs are not validated here (test_triangle_mesh does, for some of these seeds).
void count_search_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const std::size_t n = std::size_t(state.range(0));
  constexpr unsigned seeds = 1000;
  std::size_t failures = 0, runs = 0, most_runs = 0;
  double seconds = 0;
  for(auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    for(unsigned seed = 0; seed < seeds; ++seed) {
      std::vector<Point> points;
      PDS::Sampling_statistics stats;
      try {
        PDS::sample_triangle_mesh(
            m, std::back_inserter(points),
            PDS::parameters::number_of_points(n).random_seed(seed).statistics(std::ref(stats)));
      } catch(const PDS::Target_not_reached&) {
        ++failures;
      }
      runs += stats.number_of_runs;
      most_runs = (std::max)(most_runs, std::size_t(stats.number_of_runs));
    }
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  state.counters["seeds"] = double(seeds);
  state.counters["failures"] = double(failures);
  state.counters["mean_runs"] = double(runs) / seeds;
  state.counters["most_runs"] = double(most_runs);
}

// How much the count of a maximal set varies from one seed to the next at one distance (the one that
// gives about N points with `number_of_points(N)` at seed 0): the radius mode at seeds 0 to 99, the
// mean and the standard deviation of their counts, and that deviation over sqrt(mean).
void count_spread_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const std::size_t n = std::size_t(state.range(0));
  constexpr unsigned seeds = 100;
  double sum = 0, sum_of_squares = 0, seconds = 0;
  for(auto _ : state) {
    std::vector<Point> points;
    PDS::Sampling_statistics stats;
    PDS::sample_triangle_mesh(m, std::back_inserter(points),
                              PDS::parameters::number_of_points(n).statistics(std::ref(stats)));
    const auto start = std::chrono::steady_clock::now();
    for(unsigned seed = 0; seed < seeds; ++seed) {
      points.clear();
      PDS::sample_triangle_mesh(m, std::back_inserter(points),
                                PDS::parameters::minimum_distance(stats.minimum_distance).random_seed(seed));
      sum += double(points.size());
      sum_of_squares += double(points.size()) * double(points.size());
    }
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  const double mean = sum / seeds, deviation = std::sqrt((std::max)(0., sum_of_squares / seeds - mean * mean));
  state.counters["seeds"] = double(seeds);
  state.counters["mean_points"] = mean;
  state.counters["deviation"] = deviation;
  state.counters["deviation_over_sqrt_mean"] = deviation / std::sqrt(mean);
}

// seconds at 1M points over seconds at 100k points, same mesh, same run
void linearity_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double area = PMP::area(m);
  const double d[2] = {distance_for(area, 1e5), distance_for(area, 1e6)};
  std::vector<Point> last[2]; // the last run's points of each size, validated after the timed runs
  const std::array<double, 2> best = fastest_alternating(state, [&](std::size_t v) {
    std::vector<Point> points;
    PDS::sample_triangle_mesh(m, std::back_inserter(points), PDS::parameters::minimum_distance(d[v]));
    last[v] = std::move(points); // frees the run before's vector, as the end of `points` did
  });
  for(std::size_t v = 0; v < 2; ++v)
    if(!validate(state, m, last[v], d[v], false)) return;
  state.counters["seconds_1M_over_100k"] = best[1] / best[0]; // <= 12 is the target
}

// One sampling call, the points counted, not stored (no white-noise floor): the case the profiles of
// README.md are taken on, with perf at one million points and under valgrind's cachegrind at 100,000,
// with PDS_BENCH_PROFILE set so that the validation of an untimed second run is skipped.
void sampling_only_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double d = distance_for(PMP::area(m), double(state.range(0)));
  PDS::Sampling_statistics stats;
  std::size_t n = 0;
  double peak = 0, resident = 0;
  for(auto _ : state) {
    n = 0;
    const Memory_peak memory;
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, boost::make_function_output_iterator([&](const auto&) { ++n; }),
                              PDS::parameters::minimum_distance(d).statistics(std::ref(stats)));
    state.SetIterationTime(seconds_since(start));
    memory.read(peak, resident);
  }
  if(!std::getenv("PDS_BENCH_PROFILE")) {
    std::vector<Point> points;
    PDS::sample_triangle_mesh(m, std::back_inserter(points), PDS::parameters::minimum_distance(d));
    if(points.size() != n) {
      fail(state, "a second run with the same seed gave another number of points");
      return;
    }
    if(!validate(state, m, points, d, false)) return;
  }
  state.counters["points"] = double(n);
  state.counters["darts_per_point"] = double(stats.darts) / double(n);
  // the sampler's own heap: the points are counted, not stored (the other cases store them)
  report_memory(state, peak, resident, double(n), 200 * double(n) + 300 * double(num_faces(m)));
}

// The triangle model without its optional union test and refine(): the operations the concept
// requires and the optional root pieces for a distance, level() and prefetch(), so the engine falls back to single-ball coverage.
// What the union test saves is measured against it.
class Without_union_test
{
public:
  typedef PDS::Triangle_fragment_traits_3 Base;
  typedef Base::Point Point;
  typedef Base::Fragment Fragment;
  typedef Base::Sample Sample;

  explicit Without_union_test(const Base& base) : base_(base) {}
  template <class Out> Out initial_fragments(Out out) const { return base_.initial_fragments(out); }
  template <class Out> Out initial_fragments(Out out, double d) const { return base_.initial_fragments(out, d); }
  double area(const Fragment& f) const { return base_.area(f); }
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const { return base_.random_sample(f, rng); }
  const Point& point(const Sample& s) const { return base_.point(s); }
  Point reference_point(const Fragment& f) const { return base_.reference_point(f); }
  bool is_covered(const Fragment& f, const Point& c, double r) const { return base_.is_covered(f, c, r); }
  template <class Out> Out split(const Fragment& f, Out out) const { return base_.split(f, out); }
  double position_error() const { return base_.position_error(); }
  // the optional operations that do not decide coverage, as the model has them
  int level(const Fragment& f) const { return base_.level(f); }
  void prefetch(const Fragment& f) const { base_.prefetch(f); }

protected:
  const Base& base_;
};

// The same with the union test, and still without the optional refine(): the two runs of the case
// differ by the union test only.
class With_union_test_only : public Without_union_test
{
public:
  using Without_union_test::Without_union_test;
  template <class PointRange>
  bool is_covered_by_union(const Fragment& f, const PointRange& centers, double radius) const
  {
    return base_.is_covered_by_union(f, centers, radius);
  }
};

// the triangle model of a mesh, its faces in the mesh's order
PDS::Triangle_fragment_traits_3 triangles_of(const Mesh& m)
{
  PDS::Triangle_fragment_traits_3 traits;
  for(auto f : faces(m)) {
    const auto h = halfedge(f, m);
    auto p = [&](Mesh::Vertex_index v) { const Point& q = m.point(v); return PDS::Triangle_fragment_traits_3::Point{{q.x(), q.y(), q.z()}}; };
    traits.add_triangle(p(source(h, m)), p(target(h, m)), p(target(next(h, m), m)));
  }
  return traits;
}

// Darts per sample and time with and without the union test, same mesh, distance and seed; args: n
void union_test_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double d = distance_for(PMP::area(m), double(state.range(0)));
  const PDS::Triangle_fragment_traits_3 traits = triangles_of(m);
  const With_union_test_only with_union(traits);
  const Without_union_test plain(traits);
  PDS::Sampling_statistics with, without, refined;
  std::size_t n_with = 0, n_without = 0, n_refined = 0;
  const std::array<double, 3> best = fastest_alternating<3>(state, [&](std::size_t v) {
    if(v == 0) {
      n_with = 0;
      PDS::sample_surface(with_union, boost::make_function_output_iterator([&](const auto&) { ++n_with; }),
                          PDS::parameters::minimum_distance(d).statistics(std::ref(with)));
    } else if(v == 1) {
      n_without = 0;
      PDS::sample_surface(plain, boost::make_function_output_iterator([&](const auto&) { ++n_without; }),
                          PDS::parameters::minimum_distance(d).statistics(std::ref(without)));
    } else {
      // the model as it is, with refine(), which also cuts fragments along chords
      n_refined = 0;
      PDS::sample_surface(traits, boost::make_function_output_iterator([&](const auto&) { ++n_refined; }),
                          PDS::parameters::minimum_distance(d).statistics(std::ref(refined)));
    }
  });
  // Each variant's output, sampled once more outside the timed runs (the same seed, so the same points
  // as its timed runs), each validated.
  std::vector<Point> out[3];
  for(std::size_t v = 0; v < 3; ++v) {
    auto store = boost::make_function_output_iterator([&](const PDS::Triangle_fragment_traits_3::Sample& s) {
      out[v].push_back(Point(s.point[0], s.point[1], s.point[2]));
    });
    const auto np = PDS::parameters::minimum_distance(d);
    if(v == 0) PDS::sample_surface(with_union, store, np);
    else if(v == 1) PDS::sample_surface(plain, store, np);
    else PDS::sample_surface(traits, store, np);
  }
  if(out[0].size() != n_with || out[1].size() != n_without || out[2].size() != n_refined) {
    fail(state, "a run with the same seed gave another number of points");
    return;
  }
  for(std::size_t v = 0; v < 3; ++v)
    if(!validate(state, m, out[v], d, false)) return;
  state.counters["darts_per_point_with_union_test"] = double(with.darts) / double(n_with);
  state.counters["darts_per_point_with_refine"] = double(refined.darts) / double(out[2].size());
  state.counters["darts_per_point_without"] = double(without.darts) / double(n_without);
  state.counters["seconds_with_over_without"] = best[0] / best[1];
  state.counters["seconds_with_refine_over_without"] = best[2] / best[1];
  // with the union test: the darts spent finding out that a fragment was covered, and the accepted ones
  state.counters["share_of_darts_on_covered_fragments"] = double(with.darts_on_covered_fragments) / double(with.darts);
  state.counters["share_of_darts_accepted"] = double(n_with) / double(with.darts);
}

// The model as it is, without the pieces it cuts long thin faces into: whole faces only.
class Whole_faces_only : public With_union_test_only
{
public:
  using With_union_test_only::With_union_test_only;
  // hides the base's initial_fragments(out, d)
  template <class Out> Out initial_fragments(Out out) const { return base_.initial_fragments(out); }
  template <class PointRange, class OutputIterator>
  bool refine(const Fragment& f, const PointRange& near, const PointRange& around, double radius,
              OutputIterator children) const
  {
    return base_.refine(f, near, around, radius, children);
  }
};

// Long thin faces cut into pieces (the model as it is) against whole faces, about n points; args: n
void long_faces_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double d = distance_for(PMP::area(m), double(state.range(0)));
  std::vector<Point> points[2];
  PDS::Sampling_statistics stats[2];
  double peak[2] = {0, 0};
  const std::array<double, 2> best = fastest_alternating<2>(state, [&](std::size_t v) {
    points[v].clear();
    points[v].shrink_to_fit();
    const Heap_peak heap;
    // the triangle table in the timed run and the heap's peak, as sample_triangle_mesh() in mesh/
    const PDS::Triangle_fragment_traits_3 traits = triangles_of(m);
    const Whole_faces_only whole(traits);
    auto out = boost::make_function_output_iterator([&](const PDS::Triangle_fragment_traits_3::Sample& s) {
      points[v].push_back(Point(s.point[0], s.point[1], s.point[2]));
    });
    const auto np = PDS::parameters::minimum_distance(d).statistics(std::ref(stats[v]));
    if(v == 0) PDS::sample_surface(traits, out, np);
    else PDS::sample_surface(whole, out, np);
    peak[v] = heap.bytes();
  });
  // (the check times reported are those of the model's output)
  for(std::size_t v = 0; v < 2; ++v)
    if(!validate(state, m, points[v], d, v == 0)) return;
  state.counters["faces"] = double(num_faces(m));
  state.counters["points"] = double(points[0].size());
  state.counters["seconds"] = best[0];
  state.counters["seconds_whole_faces"] = best[1];
  state.counters["whole_faces_over_pieces"] = best[1] / best[0];
  state.counters["darts_per_point"] = double(stats[0].darts) / double(points[0].size());
  state.counters["darts_per_point_whole_faces"] = double(stats[1].darts) / double(points[1].size());
  state.counters["peak_active_fragments_per_point"] = double(stats[0].peak_active_fragments) / double(points[0].size());
  state.counters["peak_active_fragments_per_point_whole_faces"] =
      double(stats[1].peak_active_fragments) / double(points[1].size());
  // the peak of the heap during the run, the triangle table and the output vector included, against
  // the budget of 200 bytes a point and 300 a face, each variant against its own number of points
  for(std::size_t v = 0; v < 2; ++v)
    state.counters[v == 0 ? "memory_budget_use" : "memory_budget_use_whole_faces"] =
        peak[v] / (200 * double(points[v].size()) + 300 * double(num_faces(m)));
}

// A needle longer than 2^12 times the distance: the triangle (0, 0, 0), (L, 0, 0), (L, 10^-8, 0) at
// D = 10^-4, L = 2^k D; args: k. The triangle model cuts a face into at most 2^12 rows, so beyond
// L = 2^14 D its rows are more than four times D long, and the darts and the fragments in wait per
// point grow with their length (user manual, "Long thin triangles"). The heap's peak, as in
// long_faces/. The output is checked to be a Poisson-disk set; `certified` is 1 where is_maximal()
// proves it maximal, 0 where it answers undecided (its bounds ran out on the rows' slivers), and the
// case fails where it finds a point farther than D from every sample.
void long_rows_case(benchmark::State& state)
{
  const double d = 1e-4, length = std::ldexp(d, int(state.range(0)));
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(length, 0, 0)), m.add_vertex(Point(length, 1e-8, 0)));
  std::vector<Point> points;
  PDS::Sampling_statistics stats;
  double seconds = 0, peak = 0;
  for(auto _ : state) {
    points.clear();
    points.shrink_to_fit();
    const Heap_peak heap;
    const auto start = std::chrono::steady_clock::now();
    PDS::sample_triangle_mesh(m, std::back_inserter(points), PDS::parameters::minimum_distance(d).statistics(
                                                                  std::ref(stats)));
    seconds = seconds_since(start);
    peak = heap.bytes();
    state.SetIterationTime(seconds);
  }
  if(!PDS::is_poisson_disk_set(points, d)) {
    fail(state, "output is not a Poisson-disk set");
    return;
  }
  const auto maximal = PDS::is_maximal(m, points, d);
  if(!maximal && maximal.uncovered_point) {
    fail(state, "output is not maximal");
    return;
  }
  state.counters["certified"] = maximal ? 1 : 0;
  state.counters["dropped_fragments"] = double(stats.dropped_fragments); // at the engine's depth floor
  state.counters["points"] = double(points.size());
  state.counters["seconds"] = seconds;
  state.counters["darts_per_point"] = double(stats.darts) / double(points.size());
  state.counters["peak_active_fragments_per_point"] = double(stats.peak_active_fragments) / double(points.size());
  state.counters["memory_budget_use"] = peak / (200 * double(points.size()) + 300);
}

// concurrency(CGAL::Parallel_tag()) against the sequential run, alternating (see above), on TBB's
// default number of threads: args: n. The two give the same points, which is checked; the parallel
// run's output is validated.
void threads_case(benchmark::State& state, const std::string& name)
{
  const Mesh& m = mesh(name);
  const double d = distance_for(PMP::area(m), double(state.range(0)));
  std::vector<Point> points[2];
  const std::array<double, 2> best = fastest_alternating(state, [&](std::size_t v) {
    points[v].clear();
    if(v == 0) PDS::sample_triangle_mesh(m, std::back_inserter(points[v]), PDS::parameters::minimum_distance(d));
    else
      PDS::sample_triangle_mesh(m, std::back_inserter(points[v]),
                                PDS::parameters::minimum_distance(d).concurrency(CGAL::Parallel_tag()));
  });
  if(points[0] != points[1]) {
    fail(state, "the parallel run gave other points than the sequential one");
    return;
  }
  if(!validate(state, m, points[1], d)) return;
  state.counters["points"] = double(points[1].size());
  state.counters["threads"] = double(tbb::this_task_arena::max_concurrency());
  state.counters["sequential_seconds"] = best[0];
  state.counters["parallel_seconds"] = best[1];
  state.counters["speedup"] = best[0] / best[1];
}

// Registers a case whose exceptions are reported as its error (Target_not_reached from a search, say),
// instead of ending the whole run.
template <class Case>
benchmark::internal::Benchmark* add(const std::string& name, Case run)
{
  return benchmark::RegisterBenchmark(name.c_str(), [run](benchmark::State& state) {
    try {
      run(state);
    } catch(const std::exception& e) {
      fail(state, std::string("exception: ") + e.what());
    }
  });
}

void register_cases()
{
  for(const char* name : {"lion.off", "armadillo.off", "armadillo_loop3"})
    for(int n : {10000, 100000, 1000000})
      add(std::string("mesh/") + name, [name](benchmark::State& s) { mesh_case(s, name); })
          ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {10000, 100000, 1000000})
    add("sphere", sphere_case)
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100000, 1000000})
    add("count_mode/lion.off", [](benchmark::State& s) { count_mode_case(s, "lion.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  // strips far narrower than the distance, where a sample covers far less than the first estimate
  // assumes (first runs of 1,267 and 127 times the target, stopped at twice it)
  for(const char* name : {"strips_1e-7", "strips_1e-5"})
    add(std::string("count_mode/") + name, [name](benchmark::State& s) { count_mode_case(s, name); })
        ->Arg(10000)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  // surfaces that are neither a plane nor a line at the scale of d, where the count does not go as
  // d^-2: stacked sheets closer than d, tubes about as wide as d
  for(int n : {10000, 100000})
    add("count_mode/sheets", [](benchmark::State& s) { count_mode_case(s, "sheets"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  add("count_mode/tubes", [](benchmark::State& s) { count_mode_case(s, "tubes"); })
      ->Arg(10000)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100, 150})
    add("count_search/elephant.off", [](benchmark::State& s) { count_search_case(s, "elephant.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100, 1000, 10000})
    add("count_spread/elephant.off", [](benchmark::State& s) { count_spread_case(s, "elephant.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100000, 1000000})
    add("sampling_only/lion.off", [](benchmark::State& s) { sampling_only_case(s, "lion.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  // a mesh of few faces, where the budget has almost nothing but the points: what the sampler itself
  // holds (see benchmark/README.md, "Where the figures are short")
  add("sampling_only/pipe.off", [](benchmark::State& s) { sampling_only_case(s, "pipe.off"); })
      ->Arg(10000)->Arg(100000)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100000, 1000000})
    add("union_test/lion.off", [](benchmark::State& s) { union_test_case(s, "lion.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  // CGAL's meshes with the longest faces at D (the slowest at 10,000 points with whole faces), two
  // without such faces, and a cylinder of full-height triangles against the same surface in rings
  for(const char* name : {"pinion.off", "pipe.off", "anchor.off", "joint.off", "boeing.off", "cheese.off",
                          "blade.off", "lion.off", "fandisk.off", "cylinder_128", "cylinder_rings"})
    add(std::string("long_faces/") + name, [name](benchmark::State& s) { long_faces_case(s, name); })
        ->Arg(std::string(name).rfind("cylinder", 0) == 0 ? 2000 : 10000)
        ->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int k : {12, 14, 16, 17, 18})
    add("long_rows", long_rows_case)
        ->Arg(k)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(int n : {100000, 1000000})
    add("threads/lion.off", [](benchmark::State& s) { threads_case(s, "lion.off"); })
        ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  for(const char* name : {"lion.off", "armadillo_loop3"})
    add(std::string("linearity/") + name, [name](benchmark::State& s) { linearity_case(s, name); })
        ->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
}

} // namespace

// Replacements of the global allocation functions, feeding the heap accounting above. With glibc, a
// block's size is the allocator's usable size of it (what it holds for the program, its rounding up
// included); elsewhere each block carries the size asked for in a header of 16 bytes (which keeps the
// alignment of new), which the resident figure then counts too.
#if defined(__GLIBC__)
void* operator new(std::size_t n)
{
  void* p = std::malloc(n == 0 ? 1 : n);
  if(!p) throw std::bad_alloc();
  count_allocation((long long)malloc_usable_size(p));
  return p;
}
void operator delete(void* p) noexcept
{
  if(!p) return;
  live_bytes -= (long long)malloc_usable_size(p);
  std::free(p);
}
#else
void* operator new(std::size_t n)
{
  void* p = std::malloc(n + 16);
  if(!p) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  count_allocation((long long)n);
  return static_cast<char*>(p) + 16;
}
void operator delete(void* p) noexcept
{
  if(!p) return;
  char* block = static_cast<char*>(p) - 16;
  live_bytes -= (long long)*reinterpret_cast<std::size_t*>(block);
  std::free(block);
}
#endif
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

int main(int argc, char** argv)
{
  register_cases();
  benchmark::Initialize(&argc, argv);
  if(benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return any_case_failed ? 1 : 0;
}
