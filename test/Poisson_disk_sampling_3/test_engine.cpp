// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The engine's parts: the generator, the log-binned pool's area-proportional choice, and the engine
// on a model of SurfaceFragmentTraits_3 written here (a flat square), as a user would write one.

#include <CGAL/Poisson_disk_sampling_3/is_maximal.h>
#include <CGAL/Poisson_disk_sampling_3/is_poisson_disk_set.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Active_fragment_pool.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Coverage_certifier.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Neighbor_buckets.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Triangle_in_ball_union.h>
#include <CGAL/Poisson_disk_sampling_3/Triangle_fragment_traits_3.h>
#include <CGAL/Poisson_disk_sampling_3/sample_surface.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <gtest/gtest.h>

#include "fragment_checks.h"
#include "square_traits.h"

#include <algorithm>
#include <atomic>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace PDS = CGAL::Poisson_disk_sampling_3;
using PDS::internal::Random;

// uniform_index() takes the upper half of a 128-bit product: the path for compilers without 128-bit
// integers must give the same values, or the points would depend on the compiler
TEST(Random, ProductByHalvesIsTheFullProduct)
{
#if !defined(__SIZEOF_INT128__)
  GTEST_SKIP() << "no 128-bit integers to compare with";
#else
  Random rng(3);
  const std::uint64_t edge[] = {0, 1, 2, 0xffffffffu, 0x100000000u, ~std::uint64_t(0), ~std::uint64_t(0) - 1};
  for(int i = 0; i < 100000; ++i) {
    const std::uint64_t x = i < 49 ? edge[i % 7] : rng.next(), n = i < 49 ? edge[i / 7] : rng.next() >> (i % 64);
    const std::uint64_t full = std::uint64_t((static_cast<unsigned __int128>(x) * n) >> 64);
    ASSERT_EQ(Random::high_half_of_product_by_halves(x, n), full) << x << " " << n;
  }
#endif
}

TEST(Random, SameSeedSameStreamAndRanges)
{
  Random a(5), b(5), c(6);
  bool differs = false;
  for(int i = 0; i < 1000; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    differs = differs || x != c.uniform();
    EXPECT_GE(x, 0.);
    EXPECT_LT(x, 1.);
    EXPECT_LT(a.uniform_index(7), 7u);
    b.uniform_index(7);
    c.uniform_index(7);
  }
  EXPECT_TRUE(differs);
  // the stream is fixed by the algorithm, on every platform: the first values for seed 0 of splitmix64
  // (Stream; its published first output for seed 0) and of xoshiro256** seeded by it (Random; the
  // published definition, evaluated apart from this code), as a change of either would change every
  // seeded output
  EXPECT_EQ(PDS::internal::Stream(0).next(), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(Random(0).next(), 0x99EC5F36CB75F2B4ull);
}

// A dart's own generator (Stream): the same seed gives the same values, in [0, 1); the first values of
// streams seeded by successive draws of Random, as the engine seeds its darts, are uniform (ten bins,
// 5 standard deviations), and so are the second ones.
TEST(Random, DartStreamsAreReproducibleAndUniform)
{
  using CGAL::Poisson_disk_sampling_3::internal::Stream;
  Stream a(17), b(17), c(18);
  EXPECT_EQ(a.uniform(), b.uniform());
  EXPECT_NE(a.uniform(), c.uniform());
  Random seeds(3);
  const int n = 100000;
  std::array<int, 10> first{}, second{};
  for(int i = 0; i < n; ++i) {
    Stream s(seeds.next());
    const double u = s.uniform(), v = s.uniform();
    ASSERT_TRUE(u >= 0 && u < 1 && v >= 0 && v < 1);
    ++first[std::size_t(10 * u)];
    ++second[std::size_t(10 * v)];
  }
  const double sigma = std::sqrt(n * 0.1 * 0.9);
  for(int k = 0; k < 10; ++k) {
    EXPECT_NEAR(first[std::size_t(k)], n / 10, 5 * sigma) << k;
    EXPECT_NEAR(second[std::size_t(k)], n / 10, 5 * sigma) << k;
  }
}

// One complete draw: the pool's rejection step repeated until it accepts; items are indices in `areas`.
template <class Pool>
typename Pool::Handle draw_one(Pool& pool, Random& rng, const std::vector<double>& areas)
{
  pool.begin_batch();
  for(;;) {
    const typename Pool::Handle h = pool.draw(rng);
    if(pool.accepts(h, areas[std::size_t(pool.item(h))], rng.uniform())) return h;
  }
}

// Areas spread over several bins, some exactly on bin boundaries: picked with replacement, each must
// come up in proportion to its area (5 standard deviations; the seed makes the test deterministic).
TEST(ActiveFragmentPool, PicksInProportionToArea)
{
  const std::vector<double> areas{1.0, 0.75, 0.5, 0.5000001, 0.25, 0.3, 0.01, 0.0078125, 1e-4};
  PDS::internal::Active_fragment_pool<int> pool(1.0);
  for(int i = 0; i < int(areas.size()); ++i) pool.push(i, areas[std::size_t(i)]);
  double total = 0;
  for(double a : areas) total += a;
  Random rng(11);
  const int picks = 400000;
  std::vector<double> count(areas.size(), 0);
  typedef PDS::internal::Active_fragment_pool<int> Pool;
  for(int k = 0; k < picks; ++k) {
    const Pool::Handle h = draw_one(pool, rng, areas);
    const int i = pool.item(h);
    count[std::size_t(i)] += 1;
    EXPECT_TRUE(pool.take(h));
    EXPECT_FALSE(pool.take(h)); // taken once per batch
    pool.end_batch();
    pool.push(i, areas[std::size_t(i)]);
  }
  for(std::size_t i = 0; i < areas.size(); ++i) {
    const double p = areas[i] / total, mean = picks * p, sigma = std::sqrt(picks * p * (1 - p));
    EXPECT_NEAR(count[i], mean, 5 * sigma + 1) << "fragment of area " << areas[i];
  }
  EXPECT_EQ(pool.size(), areas.size());
}

// Fragments 80 and 100 bins below the largest (a deep split of a small face next to a large face):
// every fragment comes out, the large one first (the others weigh 2^-80 of it).
TEST(ActiveFragmentPool, ReachesBinsFarBelowTheFirst)
{
  PDS::internal::Active_fragment_pool<int> pool(1.0);
  const std::vector<double> areas{1.0, std::ldexp(1., -80), std::ldexp(0.75, -100)};
  for(int i = 0; i < 3; ++i) pool.push(i, areas[std::size_t(i)]);
  Random rng(3);
  auto pick_and_remove = [&] {
    const auto h = draw_one(pool, rng, areas);
    const int i = pool.item(h);
    pool.take(h);
    pool.end_batch();
    return i;
  };
  EXPECT_EQ(pick_and_remove(), 0);
  std::vector<int> rest{pick_and_remove(), pick_and_remove()};
  std::sort(rest.begin(), rest.end());
  EXPECT_EQ(rest, (std::vector<int>{1, 2}));
  EXPECT_TRUE(pool.empty());
}

// A fragment whose bin's bound, max_area 2^-b, is below the normal doubles, where it is rounded: here
// 1.75 2^-1073, rounded to 4 2^-1074, for an area of 3 2^-1074. The draw must still accept it with
// probability area / bound = 6/7 (3/4 with the rounded bound), and the bin of an area 2^1074 times
// smaller than the largest must be found (a quotient of the two used to overflow).
TEST(ActiveFragmentPool, AcceptsExactlyWhereBinBoundsAreSubnormal)
{
  const double area = 3 * std::numeric_limits<double>::denorm_min();
  PDS::internal::Active_fragment_pool<int> pool(1.75);
  pool.push(0, area);
  pool.begin_batch();
  Random rng(8);
  const int draws = 40000;
  int accepted = 0;
  for(int k = 0; k < draws; ++k) accepted += pool.accepts(pool.draw(rng), area, rng.uniform());
  const double p = 6. / 7, sigma = std::sqrt(draws * p * (1 - p));
  EXPECT_NEAR(accepted, draws * p, 5 * sigma);
  // the largest area subnormal too (a surface of slivers): 2 2^-1074 against 3 2^-1074, 2/3 (1/2
  // where the product u max_area is rounded to a multiple of 2^-1074)
  const double tiny = 2 * std::numeric_limits<double>::denorm_min();
  PDS::internal::Active_fragment_pool<int> slivers(3 * std::numeric_limits<double>::denorm_min());
  slivers.push(0, tiny);
  slivers.begin_batch();
  int kept = 0;
  for(int k = 0; k < draws; ++k) kept += slivers.accepts(slivers.draw(rng), tiny, rng.uniform());
  const double q = 2. / 3, tau = std::sqrt(draws * q * (1 - q));
  EXPECT_NEAR(kept, draws * q, 5 * tau);
}

// A batch takes many entries of the same bins, some twice, while children are pushed: at its end
// exactly the taken ones are gone.
TEST(ActiveFragmentPool, BatchRemovesExactlyTheTakenOnes)
{
  typedef PDS::internal::Active_fragment_pool<int> Pool;
  Pool pool(1.0);
  std::multiset<int> expected;
  Random rng(5);
  int next = 0;
  for(; next < 500; ++next) {
    pool.push(next, 0.25 + 0.75 * rng.uniform() * (next % 3 == 0 ? 0.01 : 1.));
    expected.insert(next);
  }
  for(int batch = 0; batch < 12; ++batch) { // about 25 fewer per batch
    pool.begin_batch();
    std::vector<Pool::Handle> drawn;
    for(int i = 0; i < 60; ++i) drawn.push_back(pool.draw(rng));
    for(const Pool::Handle& h : drawn) {
      const int item = pool.item(h);
      if(pool.take(h)) {
        EXPECT_EQ(expected.count(item), 1u);
        expected.erase(item);
        if(rng.uniform() < 0.5) { // a child, pushed while the batch is open
          pool.push(next, 0.001 + rng.uniform());
          expected.insert(next++);
        }
      }
    }
    pool.end_batch();
    EXPECT_EQ(pool.size(), expected.size());
  }
  // batches that take most of a small pool: taken entries at the end of the bins, and entries
  // refilled in this batch that end up last
  for(int batch = 0; batch < 40; ++batch) {
    for(int i = 0; i < 30; ++i) {
      pool.push(next, 0.5 + 0.5 * rng.uniform());
      expected.insert(next++);
    }
    pool.begin_batch();
    std::vector<Pool::Handle> drawn;
    const std::size_t n = pool.size();
    for(std::size_t i = 0; i < n; ++i) drawn.push_back(pool.draw(rng));
    for(const Pool::Handle& h : drawn)
      if(pool.take(h)) expected.erase(expected.find(pool.item(h)));
    pool.end_batch();
    EXPECT_EQ(pool.size(), expected.size());
  }
  std::multiset<int> left;
  while(!pool.empty()) {
    pool.begin_batch();
    const Pool::Handle h = pool.draw(rng);
    left.insert(pool.item(h));
    pool.take(h);
    pool.end_batch();
  }
  EXPECT_EQ(left, expected);
}

// The pool's free room: a bin of few fragments holds a small first chunk, not a whole one, a bin
// holds at most one chunk of free room, and an emptied bin keeps at most a first chunk of 16, the pool
// four spare chunks.
TEST(ActiveFragmentPool, FreeRoomIsBounded)
{
  typedef PDS::internal::Active_fragment_pool<int> Pool;
  Pool pool(1.0);
  // ten fragments in each of 30 bins (areas 2^-b)
  for(int b = 0; b < 30; ++b)
    for(int i = 0; i < 10; ++i) pool.push(b, std::ldexp(0.75, -b));
  EXPECT_LE(pool.capacity(), 30u * 16u);
  // then thousands in the first six of them (bins 0 to 5), taken away in random batches: less than a
  // chunk of free room in each of these, a first chunk of 16 in each of the others, and four spares
  Random rng(9);
  for(int i = 0; i < 20000; ++i) pool.push(i, std::ldexp(0.5 + 0.5 * rng.uniform(), -int(rng.uniform_index(6))));
  const std::size_t bins_in_use = 30, large_bins = 6, chunk = 256;
  while(!pool.empty()) {
    pool.begin_batch();
    for(int i = 0; i < 300; ++i) pool.take(pool.draw(rng));
    pool.end_batch();
    ASSERT_LE(pool.capacity(), pool.size() + large_bins * (chunk - 1) + (bins_in_use - large_bins) * 16 + 4 * chunk);
  }
  // the emptied bins keep their first chunk only where it is the smallest, besides the four spares
  EXPECT_LE(pool.capacity(), 4 * chunk + bins_in_use * 16);
}

// The square, with samples that count how many of them are alive at once, and how many were alive
// when each run of the engine asked for the roots (at its start: no dart is thrown yet).
struct Counted_square : pds_test::Square_traits
{
  struct Sample
  {
    Point point;
    static inline long live = 0, peak = 0, live_at_a_start = 0;
    explicit Sample(const Point& p) : point(p) { up(); }
    Sample(const Sample& s) : point(s.point) { up(); }
    Sample& operator=(const Sample&) = default;
    ~Sample() { --live; }
    static void up() { peak = (std::max)(peak, ++live); }
    static void reset() { live = peak = live_at_a_start = 0; }
  };
  template <class Out> Out initial_fragments(Out out) const
  {
    Sample::live_at_a_start = (std::max)(Sample::live_at_a_start, Sample::live);
    return pds_test::Square_traits::initial_fragments(out);
  }
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const
  {
    const auto s = pds_test::Square_traits::random_sample(f, rng);
    return s ? std::optional<Sample>(Sample(s->point)) : std::nullopt;
  }
  const Point& point(const Sample& s) const { return s.point; }
};

// number_of_points keeps the samples of one run at a time, each once: no run starts while an earlier
// run's samples are alive (the search kept those of the complete run closest to the target, though it
// returns only the run that meets it: 20,000 points at seed 2 take two runs), and a run holds its
// samples and the darts of a batch, at most 256, and no more (a vector grown by doubling held its old
// and new arrays while it moved: 33,025 samples alive at once for 20,131 at seed 0, in one run).
TEST(Engine, CountModeKeepsOneCopyOfItsSamples)
{
  for(std::uint64_t seed : {0, 2}) {
    Counted_square::Sample::reset();
    std::size_t n = 0;
    PDS::Sampling_statistics stats;
    PDS::sample_surface(Counted_square(),
                        boost::make_function_output_iterator([&](const Counted_square::Sample&) { ++n; }),
                        PDS::parameters::number_of_points(20000).random_seed(seed).statistics(std::ref(stats)));
    EXPECT_NEAR(double(n), 20000, 200);
    EXPECT_EQ(Counted_square::Sample::live, 0);
    EXPECT_EQ(Counted_square::Sample::live_at_a_start, 0) << "seed " << seed;
    if(seed == 0) {
      // one run (what the bound below assumes): its samples, a batch's darts and the one being copied
      ASSERT_EQ(stats.number_of_runs, 1u);
      EXPECT_LE(Counted_square::Sample::peak, long(n) + 256 + 1);
    } else {
      ASSERT_GE(stats.number_of_runs, 2u) << "the case of a search of several runs";
    }
  }
}

using pds_test::Square_traits;

// the point of a root triangle fragment at parameters (u, v), through the model's own operations:
// the reference point (centroid) of a tiny fragment whose corner is (u, v)
PDS::Triangle_fragment_traits_3::Point point_at(const PDS::Triangle_fragment_traits_3& traits,
                                                PDS::Triangle_fragment_traits_3::Fragment f, double u, double v)
{
  f.u = u;
  f.v = v;
  f.level = 60;
  return traits.reference_point(f);
}

std::vector<std::array<double, 3>> sample_square(const Square_traits& traits, double d, unsigned seed)
{
  std::vector<Square_traits::Sample> samples;
  PDS::sample_surface(traits, std::back_inserter(samples), PDS::parameters::minimum_distance(d).random_seed(seed));
  std::vector<std::array<double, 3>> points;
  for(const auto& s : samples) points.push_back(s.point);
  return points;
}

// the certificate of a user's model, as a user calls it, on the model's points; the same answer on
// CGAL's points, and for a set not maximal a gap, away from every point
bool certified_maximal(const Square_traits& traits, const std::vector<std::array<double, 3>>& points, double d)
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> cgal_points;
  for(const auto& p : points) cgal_points.emplace_back(p[0], p[1], p[2]);
  const auto check = PDS::is_maximal_on_surface(traits, points, d);
  EXPECT_EQ(bool(check), bool(PDS::is_maximal_on_surface(traits, cgal_points, d)));
  if(check.uncovered_point)
    for(const auto& p : points) {
      const auto& g = *check.uncovered_point;
      EXPECT_GT((g[0] - p[0]) * (g[0] - p[0]) + (g[1] - p[1]) * (g[1] - p[1]) + (g[2] - p[2]) * (g[2] - p[2]), d * d);
    }
  return bool(check);
}

TEST(Engine, SamplesAUserModel)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 P;
  for(bool refuse_half : {false, true}) {
    const Square_traits traits(refuse_half);
    const auto points = sample_square(traits, 0.02, 3);
    std::vector<P> cgal_points;
    for(const auto& p : points) cgal_points.emplace_back(p[0], p[1], p[2]);
    EXPECT_TRUE(PDS::is_poisson_disk_set(cgal_points, 0.02));
    EXPECT_TRUE(certified_maximal(traits, points, 0.02));
    // the jamming density of the plane, with the square's border adding a little
    EXPECT_NEAR(double(points.size()) * 0.02 * 0.02, 0.6965 * 1.04, 0.03) << refuse_half;
    EXPECT_FALSE(certified_maximal(traits, std::vector<std::array<double, 3>>(points.begin() + 1, points.end()), 0.02) &&
                 certified_maximal(traits, std::vector<std::array<double, 3>>(points.begin(), points.end() - 1), 0.02))
        << "removing a sample should usually open a gap";
  }
}

// A model without refine(), whose random_sample() refuses half of its darts: on TBB's threads
// (concurrency(CGAL::Parallel_tag())) the engine gives the sequential run's samples.
TEST(Engine, ThreadsGiveTheSamePointsOnAUserModel)
{
  for(bool refuse_half : {false, true}) {
    const Square_traits traits(refuse_half);
    std::vector<Square_traits::Sample> sequential, parallel;
    PDS::sample_surface(traits, std::back_inserter(sequential),
                        PDS::parameters::minimum_distance(0.005).random_seed(4));
    PDS::sample_surface(traits, std::back_inserter(parallel),
                        PDS::parameters::minimum_distance(0.005).random_seed(4).concurrency(CGAL::Parallel_tag()));
    ASSERT_EQ(parallel.size(), sequential.size()) << refuse_half;
    EXPECT_GT(sequential.size(), 20000u);
    for(std::size_t i = 0; i < sequential.size(); ++i) ASSERT_EQ(parallel[i].point, sequential[i].point) << i;
  }
}

// The square cut into 64 x 64 roots, whose operations fail on every fragment, naming it: in
// random_sample(), or in its refine(), which throws on half of them and gives the others a child of
// negative area (refused by the engine as it pushes the children: after every dart's refine() on
// threads, before the next dart's refine() in a sequential run). Each failure on the calling thread
// waits first, so that on TBB's threads another dart's exception is thrown first.
class Failing_square : public Square_traits
{
public:
  enum Where { in_random_sample, in_refine };
  explicit Failing_square(Where where) : where_(where), caller_(std::this_thread::get_id()) {}

  template <class Out> Out initial_fragments(Out out) const
  {
    for(int i = 0; i < 64; ++i)
      for(int j = 0; j < 64; ++j) *out++ = Fragment{i / 64., j / 64., 1 / 64.};
    return out;
  }
  double area(const Fragment& f) const { return f.size < 0 ? f.size : f.size * f.size; }
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const
  {
    if(where_ == in_random_sample) fail("random_sample() on fragment " + std::to_string(index(f)));
    return Square_traits::random_sample(f, rng);
  }
  template <class PointRange, class OutputIterator>
  bool refine(const Fragment& f, const PointRange&, const PointRange&, double, OutputIterator children) const
  {
    if(index(f) % 2 == 0) fail("refine() on fragment " + std::to_string(index(f)));
    wait();
    *children++ = Fragment{f.x, f.y, -double(index(f))};
    return false;
  }

private:
  static long index(const Fragment& f) { return 1 + std::lround(f.x * 64) * 64 + std::lround(f.y * 64); }
  void wait() const
  {
    if(std::this_thread::get_id() == caller_) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  [[noreturn]] void fail(const std::string& what) const
  {
    wait();
    throw std::runtime_error(what);
  }
  Where where_;
  std::thread::id caller_;
};

// On TBB's threads, the exception from a model is the one of the sequential run: the first in the
// order of its darts and stages, not the first to be thrown on some thread.
TEST(Engine, ThreadsThrowTheSequentialRunsException)
{
  for(Failing_square::Where where : {Failing_square::in_random_sample, Failing_square::in_refine}) {
    const Failing_square traits(where);
    auto failure = [&](auto tag) {
      std::vector<Square_traits::Sample> samples;
      try {
        PDS::sample_surface(traits, std::back_inserter(samples),
                            PDS::parameters::minimum_distance(0.005).random_seed(4).concurrency(tag));
      } catch(const std::exception& e) {
        return std::string(e.what());
      }
      return std::string("no exception");
    };
    const std::string sequential = failure(CGAL::Sequential_tag());
    EXPECT_NE(sequential.find(" fragment"), std::string::npos) << sequential;
    for(int run = 0; run < 3; ++run) EXPECT_EQ(failure(CGAL::Parallel_tag()), sequential) << where;
  }
}

// set_first_sample_stop(): the run returns after its first sample where the check says that sample
// holds the surface, and that sample is the one a full run accepts first for the same seed; where the
// check says no, the run is the full run (sample_sphere() uses it from the diameter up). In parallel
// mode too.
TEST(Engine, FirstSampleStopKeepsTheFullRunsSamples)
{
  const Square_traits square(true); // refusing half of its darts: the first sample may come from a later one
  for(std::uint64_t seed : {0, 1, 2, 3, 4}) {
    std::vector<Square_traits::Point> full, first;
    PDS::internal::Dart_throwing_engine<Square_traits> whole(square, 0.05, seed, 10000);
    whole.run(pds_test::Point_collector{&full});
    ASSERT_GT(full.size(), 100u);
    for(bool parallel : {false, true})
      for(bool holds : {true, false}) {
        first.clear();
        PDS::internal::Dart_throwing_engine<Square_traits> engine(square, 0.05, seed, 10000);
        int checks = 0;
        engine.set_first_sample_stop([&](const Square_traits::Sample& s) {
          ++checks;
          EXPECT_EQ(s.point, full.at(0));
          return holds;
        });
        engine.set_parallel(parallel);
        const auto statistics = engine.run(pds_test::Point_collector{&first});
        EXPECT_EQ(checks, 1) << seed; // the first sample only
        EXPECT_FALSE(statistics.stopped);
        if(holds) {
          ASSERT_EQ(first.size(), 1u) << seed;
          EXPECT_EQ(statistics.samples, 1u);
          EXPECT_EQ(first[0], full.at(0)) << seed << " " << parallel;
        } else {
          EXPECT_EQ(first, full) << seed << " " << parallel;
        }
      }
  }
}

// The engine's members depend on CGAL_LINKED_WITH_TBB and CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES.
// engine_variant.cpp, linked into this program, is compiled with neither TBB nor this unit's lack
// of stage times, and runs the engine's run() for the same model and output type: each unit must
// run its own (with one definition for both, one of them runs the other's, and the times say so).
TEST(Engine, UnitsCompiledWithOtherMacrosEachRunTheirOwnEngine)
{
#ifdef CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
  FAIL() << "test_engine.cpp is compiled without CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES";
#endif
  const Square_traits square;
  PDS::internal::Dart_throwing_engine<Square_traits> engine(square, 0.05, 9, 10000);
  engine.set_parallel(true);
  pds_test::Variant_run here;
  const auto statistics = engine.run(pds_test::Point_collector{&here.points});
  for(double seconds : statistics.stage_seconds) here.stage_seconds += seconds;
  const pds_test::Variant_run there = pds_test::run_in_variant_unit(9);
  EXPECT_EQ(here.stage_seconds, 0.) << "this unit's engine read the clock";
  EXPECT_GT(there.stage_seconds, 0.) << "engine_variant.cpp's engine did not read the clock";
  EXPECT_GT(here.points.size(), 200u);
  EXPECT_EQ(here.points, there.points) << "the two units' engines gave different samples";
}

// A model may write its roots as any output iterator allows, here by assigning the iterator that
// std::copy returns (output iterators are copy-assignable): the engine's and the certificate's
// iterators take it, in both forms of initial_fragments, and the four quarters are sampled as the
// whole square is.
struct Quarters_traits : Square_traits
{
  template <class Out> Out initial_fragments(Out out) const
  {
    const std::array<Fragment, 4> q{{{0, 0, 0.5}, {0.5, 0, 0.5}, {0, 0.5, 0.5}, {0.5, 0.5, 0.5}}};
    out = std::copy(q.begin(), q.end(), out);
    return out;
  }
  template <class Out> Out initial_fragments(Out out, double) const { return initial_fragments(out); }
};

// A model whose roots for the distance far outnumber its roots without it (here 4096 squares instead
// of one) is refused before they are stored when they exceed four per point of the bound plus six per
// root without the distance, with a message that says so; under a larger bound it is sampled.
struct Many_roots_traits : Square_traits
{
  template <class Out> Out initial_fragments(Out out) const { return Square_traits::initial_fragments(out); }
  template <class Out> Out initial_fragments(Out out, double) const
  {
    for(int i = 0; i < 64; ++i)
      for(int j = 0; j < 64; ++j) *out++ = Fragment{i / 64., j / 64., 1 / 64.};
    return out;
  }
};

TEST(Engine, RootsForTheDistanceCountAgainstTheBound)
{
  const Many_roots_traits traits;
  std::vector<Square_traits::Sample> samples;
  try {
    PDS::sample_surface(traits, std::back_inserter(samples),
                        PDS::parameters::minimum_distance(0.05).maximum_number_of_points(1000));
    ADD_FAILURE() << "not refused";
  } catch(const PDS::Point_limit_exceeded& e) {
    EXPECT_NE(std::string(e.what()).find("pieces would outnumber its faces by 4095"), std::string::npos) << e.what();
    EXPECT_TRUE(samples.empty());
  }
  PDS::sample_surface(traits, std::back_inserter(samples),
                      PDS::parameters::minimum_distance(0.05).maximum_number_of_points(1100));
  EXPECT_GT(samples.size(), 250u);
}

// Models that break the concept in ways a model's author may: each gets an error that says what is
// wrong, not a crash, a hang, a silent gap, a biased set or memory filled to the last byte.
// - areas that are not numbers, or negative: NaN children were dropped unsaid (a gap of 10 D), a
//   negative root skipped unsaid, a NaN root read as "no part of positive area";
struct Nan_children : Square_traits
{
  double area(const Fragment& f) const { return f.size < 1 ? std::nan("") : f.size * f.size; }
};
struct Negative_second_root : Square_traits
{
  template <class Out> Out initial_fragments(Out out) const
  {
    *out++ = Fragment{0, 0, 1};
    *out++ = Fragment{2, 0, 1};
    return out;
  }
  double area(const Fragment& f) const { return f.x >= 2 ? -1 : f.size * f.size; }
};
// - a refine() that writes a child of area 0 (skipped, as split()'s are) or NaN: the pool stopped at
//   its precondition, or, built without assertions, never returned;
struct Refines_badly : Square_traits
{
  double bad_size;
  explicit Refines_badly(double bad_size) : bad_size(bad_size) {}
  template <class PointRange, class Out>
  bool refine(const Fragment& f, const PointRange& near, const PointRange&, double radius, Out children) const
  {
    for(const Point& c : near)
      if(is_covered(f, c, radius)) return true;
    std::vector<Fragment> kids;
    split(f, std::back_inserter(kids));
    for(const Fragment& k : kids) {
      bool covered = false;
      for(const Point& c : near) covered = covered || is_covered(k, c, radius);
      if(!covered) *children++ = k;
    }
    if(f.size < 1) *children++ = Fragment{f.x, f.y, bad_size};
    return false;
  }
};
// - a model that samples with rejection and bounds its children's areas above its root's: the pool
//   drew them as if their bound were the root's area, and the set was biased (with bounds 8 times
//   the area, the second sample landed on the rejecting half 0.75 of the time instead of 0.58);
struct Loose_bounds : Square_traits
{
  double factor;
  explicit Loose_bounds(double factor) : factor(factor) {}
  double area(const Fragment& f) const { return f.size < 1 ? factor * f.size * f.size : f.size * f.size; }
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const
  {
    if(f.size < 1 && rng.uniform() * factor >= 1) return std::nullopt;
    return Square_traits::random_sample(f, rng);
  }
};
// - an area that is not the same on every call (a model whose area() rounds differently where it is
//   inlined, say): drawn in proportion to the area it was stored with, silently in a build without
//   assertions, or stopped at the pool's precondition, which is no documented exception;
struct Unsteady_area : Square_traits
{
  mutable std::atomic<unsigned> calls{0};
  double area(const Fragment& f) const { return (calls++ % 2 == 0 ? 1 : 4) * f.size * f.size; }
};
// (and one that grows in the bin of the largest fragments, whose upper bound was not checked)
struct Growing_root_area : Square_traits
{
  mutable std::atomic<unsigned> calls{0};
  double area(const Fragment& f) const { return (calls++ < 2 ? 1 : 1.5) * f.size * f.size; }
};
// - coverage tests that never succeed: the fragments grew four times a level down to the depth floor;
struct Never_covered : Square_traits
{
  bool is_covered(const Fragment&, const Point&, double) const { return false; }
};
// - a random_sample() that refuses every dart: the engine drew for ever.
struct Refuses_every_dart : Square_traits
{
  template <class Rng> std::optional<Sample> random_sample(const Fragment&, Rng&) const { return std::nullopt; }
};

// - points at 10^18 with a position_error() of 10^-15, far below their rounding: the neighbour
//   buckets widen their reach by 10^-15 of the coordinates, and each sample went into thousands of
//   them (3.8 GB for 228 samples, on a square 2,000 wide at D = 1).
struct Far_square : Square_traits
{
  static constexpr double offset = 1e18;
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const
  {
    std::optional<Sample> s = Square_traits::random_sample(f, rng);
    if(s) s->point[0] += offset;
    return s;
  }
  Point reference_point(const Fragment& f) const
  {
    Point p = Square_traits::reference_point(f);
    p[0] += offset;
    return p;
  }
  bool is_covered(const Fragment& f, const Point& c, double radius) const
  {
    Point q = c;
    q[0] -= offset;
    return Square_traits::is_covered(f, q, radius);
  }
};

TEST(Engine, ModelsThatBreakTheConceptAreRefused)
{
  auto what = [](auto&& traits, auto exception) -> std::string {
    std::vector<Square_traits::Sample> samples;
    try {
      PDS::sample_surface(traits, std::back_inserter(samples), PDS::parameters::minimum_distance(0.1));
    } catch(const decltype(exception)& e) {
      return e.what();
    }
    return "no exception, " + std::to_string(samples.size()) + " samples";
  };
  EXPECT_NE(what(Nan_children(), PDS::Invalid_input("")).find("a fragment of area nan"), std::string::npos);
  EXPECT_NE(what(Negative_second_root(), PDS::Invalid_input("")).find("a fragment of area -1"), std::string::npos);
  EXPECT_NE(what(Refines_badly(std::nan("")), PDS::Invalid_input("")).find("a fragment of area nan"),
            std::string::npos);
  // a child of area 0 holds nothing to sample: skipped, and the square is sampled as without it
  const std::string zero = what(Refines_badly(0), PDS::Invalid_input(""));
  EXPECT_EQ(zero.find("no exception, "), 0u) << zero;
  EXPECT_EQ(zero, "no exception, " + std::to_string(sample_square(Square_traits(), 0.1, 0).size()) + " samples");
  EXPECT_NE(what(Loose_bounds(8), PDS::Invalid_input("")).find("above the largest initial fragment's"),
            std::string::npos);
  // bounds twice the area stay below the root's (1/2 for the first children): sampled
  EXPECT_EQ(what(Loose_bounds(2), PDS::Invalid_input("")).find("no exception, "), 0u);
  EXPECT_NE(what(Unsteady_area(), PDS::Invalid_input("")).find("must return the same double"), std::string::npos);
  EXPECT_NE(what(Growing_root_area(), PDS::Invalid_input("")).find("must return the same double"), std::string::npos);
  EXPECT_NE(what(Never_covered(), PDS::Point_limit_exceeded("")).find("exceed 64 times the samples"),
            std::string::npos);
  // in count mode too, not as a run that overshot maximum_number_of_points
  try {
    std::vector<Square_traits::Sample> samples;
    PDS::sample_surface(Never_covered(), std::back_inserter(samples), PDS::parameters::number_of_points(100));
    ADD_FAILURE() << "no exception";
  } catch(const PDS::Point_limit_exceeded& e) {
    EXPECT_NE(std::string(e.what()).find("exceed 64 times the samples"), std::string::npos) << e.what();
  }
  // The certificate refuses them alike: a root of negative area was skipped (a set that left it
  // without a sample was certified), and a negative position error made the margin of its gaps
  // negative (a maximal set had a witness).
  const std::vector<std::array<double, 3>> square_samples = sample_square(Square_traits(), 0.1, 0);
  auto invalid = [](auto&& call) -> std::string {
    try {
      call();
    } catch(const PDS::Invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(invalid([&] { PDS::is_maximal_on_surface(Negative_second_root(), square_samples, 0.1); })
                .find("a fragment of area -1"),
            std::string::npos);
  struct Negative_position_error : Square_traits
  {
    double position_error() const { return -1e-3; }
  };
  ASSERT_TRUE(PDS::is_maximal_on_surface(Square_traits(), square_samples, 0.1));
  const std::string certified =
      invalid([&] { PDS::is_maximal_on_surface(Negative_position_error(), square_samples, 0.1); });
  const std::string sampled = what(Negative_position_error(), PDS::Invalid_input(""));
  for(const std::string& message : {certified, sampled})
    EXPECT_NE(message.find("position_error() must be a finite number, not negative"), std::string::npos) << message;
  EXPECT_NE(what(Far_square(), PDS::Invalid_input("")).find("more than 10^15 times the minimum distance"),
            std::string::npos);
  // by default after 2^30 draws (13 to 22 s); here after 100,000
  const Refuses_every_dart refuses;
  PDS::internal::Dart_throwing_engine<Refuses_every_dart> engine(refuses, 0.1, 0, 1000);
  engine.set_refusal_limit(100000);
  try {
    engine.run([](const Square_traits::Sample&) {});
    ADD_FAILURE() << "no exception";
  } catch(const PDS::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("darts in a row"), std::string::npos) << e.what();
  }
}

TEST(Engine, ModelMayAssignItsOutputIterator)
{
  const Quarters_traits traits;
  const double d = 0.05;
  std::vector<Square_traits::Sample> samples;
  PDS::sample_surface(traits, std::back_inserter(samples), PDS::parameters::minimum_distance(d).random_seed(2));
  ASSERT_GT(samples.size(), 100u);
  std::vector<double> xyz;
  for(const auto& s : samples) xyz.insert(xyz.end(), s.point.begin(), s.point.end());
  const PDS::internal::Point_hash_grid grid(2 * d * (1 + 0x1.0p-10), xyz.data(), samples.size());
  EXPECT_TRUE(PDS::internal::certify_coverage(traits, grid, d).maximal);
  EXPECT_FALSE(PDS::internal::certify_coverage(traits, grid, d / 2).maximal);
}

// A model that proves nothing covered, which the concept allows (is_covered() is conservative), and
// counts its live fragments. Every piece of the square is split down to the deferral size, D^2 / 2^24,
// and waits there undecided: a million of them at D = 4. The certificate keeps at most a quarter of
// its budget waiting, counts the others as not proven covered, and answers `false` with no witness
// (the only sample covers every reference point). It used to keep them all: on a cap 10^-12 wide and
// 1.7 million D long, with 1.27 million samples, `is_maximal()` ran out of memory at 4 GB.
struct Covers_nothing
{
  static inline long live = 0, peak = 0;
  struct Fragment
  {
    Square_traits::Fragment f;
    explicit Fragment(const Square_traits::Fragment& f) : f(f) { count(); }
    Fragment(const Fragment& o) : f(o.f) { count(); }
    Fragment& operator=(const Fragment& o) = default;
    ~Fragment() { --live; }
    static void count() { peak = (std::max)(peak, ++live); }
  };
  typedef Square_traits::Point Point;
  Square_traits square;
  template <class Out> Out initial_fragments(Out out) const { *out++ = Fragment({0, 0, 1}); return out; }
  double area(const Fragment& f) const { return square.area(f.f); }
  Point reference_point(const Fragment& f) const { return square.reference_point(f.f); }
  bool is_covered(const Fragment&, const Point&, double) const { return false; }
  template <class Out> Out split(const Fragment& f, Out out) const
  {
    std::vector<Square_traits::Fragment> children;
    square.split(f.f, std::back_inserter(children));
    for(const auto& c : children) *out++ = Fragment(c);
    return out;
  }
  double position_error() const { return 1e-15; }
};

TEST(Certificate, PiecesWaitingAreBounded)
{
  const double d = 4, xyz[3] = {0.5, 0.5, 0};
  const PDS::internal::Point_hash_grid grid(2 * d, xyz, 1);
  const std::size_t budget = 100000;
  Covers_nothing::peak = 0;
  const PDS::internal::Certificate c = PDS::internal::certify_coverage(Covers_nothing(), grid, d, 48, budget);
  EXPECT_FALSE(c.maximal);
  EXPECT_FALSE(c.has_witness);
  EXPECT_NEAR(c.uncovered_area, 1, 1e-12) << "every piece counts as not proven covered";
  EXPECT_EQ(Covers_nothing::live, 0);
  // the pieces waiting, in one queue, and those of the first phase's stack and a piece's children, a
  // few dozen (the pieces of the round being refined and of the next were once two lists of that size
  // each, which grew by doubling: 335 MB at most)
  EXPECT_LE(Covers_nothing::peak, long(budget / 4 + 64));
}

// The square, counting the coverage tests the certificate asks of it.
struct Counting_square : Square_traits
{
  static inline std::size_t tests = 0;
  bool is_covered(const Fragment& f, const Point& c, double radius) const
  {
    ++tests;
    return Square_traits::is_covered(f, c, radius);
  }
};

// is_maximal() tests each sample where it reaches: copies of a sample add no test (10,000 copies of one
// point on 20 copies of a face took 22 s, a test of each copy for each piece near it), and a cluster of
// samples counts in the work it is allowed (the cluster's samples are each tested on every piece near
// them, and the pieces along the boundary of its balls are many).
TEST(Certificate, CopiesAndClustersOfSamplesAreBounded)
{
  const double d = 0.6; // one sample at the middle of the square leaves its corners uncovered
  const std::vector<std::array<double, 3>> one{{{0.5, 0.5, 0}}};
  Counting_square::tests = 0;
  const auto alone = PDS::is_maximal_on_surface(Counting_square(), one, d);
  const std::size_t tests_alone = Counting_square::tests;
  ASSERT_TRUE(alone.uncovered_point);
  const std::vector<std::array<double, 3>> copies(1000, one.front());
  Counting_square::tests = 0;
  const auto with_copies = PDS::is_maximal_on_surface(Counting_square(), copies, d);
  EXPECT_EQ(Counting_square::tests, tests_alone);
  EXPECT_EQ(with_copies.uncovered_point, alone.uncovered_point);
  EXPECT_EQ(with_copies.uncovered_area, alone.uncovered_area);

  // 1,000 samples within 10^-6 of each other: after the gap is proven, the area estimate stops
  // refining once it has done a quarter of the budget's work, each test a sixteenth of a decision
  std::vector<double> xyz;
  for(int i = 0; i < 1000; ++i) xyz.insert(xyz.end(), {0.5 + 1e-9 * i, 0.5, 0});
  const PDS::internal::Point_hash_grid grid = PDS::internal::grid_of(xyz, d);
  const std::size_t budget = 40000;
  Counting_square::tests = 0;
  const PDS::internal::Certificate c = PDS::internal::certify_coverage(Counting_square(), grid, d, 48, budget);
  EXPECT_TRUE(c.has_witness);
  // the four corners outside the disk of radius d: 1 - (pi d^2 - 4 segments beyond the sides), 0.04911
  const double h = 0.5, segment = d * d * std::acos(h / d) - h * std::sqrt(d * d - h * h);
  EXPECT_GE(c.uncovered_area, 1 - (3.14159265358979 * d * d - 4 * segment)) << "an upper bound";
  // a quarter of the budget after the gap (found on the fourth piece), 16 tests a decision, and the
  // 85 pieces above the leaf size, d^2 / 64, which are split whatever the work (900,000 tests before)
  EXPECT_LE(Counting_square::tests, 16 * (budget / 4 + 4) + 1000 * 85);
}

// A model of two patches, each of whose darts lands on one point: (0, 0, 0) and q. Its single-ball test
// is exact (rationals): a fragment is covered where its point is closer than the radius to the centre.
class Two_points
{
public:
  typedef std::array<double, 3> Point;
  struct Fragment { int id, level; };
  struct Sample { Point point; };

  explicit Two_points(const Point& q) : q_(q) {}

  template <class Out> Out initial_fragments(Out out) const
  {
    *out++ = Fragment{0, 0};
    *out++ = Fragment{1, 0};
    return out;
  }
  double area(const Fragment& f) const { return std::ldexp(1., -2 * f.level); }
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const
  {
    rng.uniform();
    return Sample{at(f.id)};
  }
  const Point& point(const Sample& s) const { return s.point; }
  Point reference_point(const Fragment& f) const { return at(f.id); }
  bool is_covered(const Fragment& f, const Point& c, double radius) const
  {
    typedef CGAL::Exact_rational Q;
    const Point p = at(f.id);
    Q squared = 0;
    for(int i = 0; i < 3; ++i) squared += (Q(p[i]) - Q(c[i])) * (Q(p[i]) - Q(c[i]));
    return squared < Q(radius) * Q(radius);
  }
  template <class Out> Out split(const Fragment& f, Out out) const
  {
    for(int i = 0; i < 4; ++i) *out++ = Fragment{f.id, f.level + 1};
    return out;
  }
  double position_error() const { return 0; }

private:
  Point at(int id) const { return id == 0 ? Point{{0, 0, 0}} : q_; }
  Point q_;
};

// The engine decides |dart - sample| >= D exactly, where the squares of the doubles round to the wrong
// side of D^2: a dart exactly D from a sample is accepted, one closer by less than the rounding is
// refused (and its fragment found covered), whatever order the engine sums the squares in.
TEST(Engine, DecidesTheMinimumDistanceExactly)
{
  typedef CGAL::Exact_rational Q;
  struct Case { double x, y, d; std::size_t samples; };
  // exactly D apart, the doubles' sum of squares below D^2; and closer than D, x^2 + y^2 below D^2 by
  // 1.5e-16 (2.2e-17 of D^2), the doubles' sum of squares above it
  for(const Case& c : {Case{3.090883054775892, 4.121177406367856, 5.15147175795982, 2},
                       Case{1.516743225676319, 2.0814110690092744, 2.575418810762501, 1}}) {
    const Q exact = Q(c.x) * Q(c.x) + Q(c.y) * Q(c.y) - Q(c.d) * Q(c.d);
    ASSERT_TRUE(c.samples == 2 ? exact == 0 && c.x * c.x + c.y * c.y < c.d * c.d
                               : exact < 0 && c.x * c.x + c.y * c.y > c.d * c.d && c.y * c.y + c.x * c.x > c.d * c.d);
    for(std::uint64_t seed : {0u, 1u, 2u, 3u}) {
      std::vector<Two_points::Sample> out;
      PDS::Sampling_statistics stats;
      EXPECT_NO_THROW(PDS::sample_surface(Two_points(Two_points::Point{{c.x, c.y, 0.}}), std::back_inserter(out),
                                          PDS::parameters::minimum_distance(c.d).random_seed(seed)
                                              .statistics(std::ref(stats))));
      EXPECT_EQ(out.size(), c.samples) << c.x << " " << seed;
      EXPECT_EQ(stats.dropped_fragments, 0u);
    }
  }
}

// Darts land uniformly on the free area: the first sample of each run is uniform on the square, so its
// x coordinate over many seeds is uniform on [0, 1] (a Kolmogorov-Smirnov bound at the 0.1% level).
TEST(Engine, FirstDartIsUniform)
{
  const Square_traits traits;
  std::vector<double> xs;
  for(unsigned seed = 0; seed < 400; ++seed) xs.push_back(sample_square(traits, 0.5, seed).front()[0]);
  EXPECT_LT(one_sample_ks_distance(xs, [](double x) { return x; }), 1.95 / std::sqrt(double(xs.size())));
}

// Darts thrown in batches are the same process as darts thrown one by one: the k-th sample's distance
// to the samples before it has the same distribution as in plain sequential dart throwing on the square
// (uniform darts, each kept if free), here with k = 70 of about 110, late enough that the free area is
// in many pieces and the engine throws batches of dozens of darts. Two-sample Kolmogorov-Smirnov bound
// at the 0.1% level. (Choosing the pool's bins uniformly instead of by area fails it.)
TEST(Engine, BatchesFollowSequentialDartThrowing)
{
  const double d = 0.08;
  const std::size_t k = 70, runs = 600;
  auto nearest_before = [&](const std::vector<std::array<double, 3>>& points) {
    double best = 10;
    for(std::size_t i = 0; i + 1 < k; ++i)
      best = std::min(best, std::hypot(points[i][0] - points[k - 1][0], points[i][1] - points[k - 1][1]));
    return best;
  };
  const Square_traits traits;
  std::vector<double> engine, reference;
  for(unsigned seed = 0; seed < runs; ++seed) engine.push_back(nearest_before(sample_square(traits, d, seed)));
  Random rng(12345);
  for(std::size_t run = 0; run < runs; ++run) {
    std::vector<std::array<double, 3>> points;
    while(points.size() < k) {
      const std::array<double, 3> p{{rng.uniform(), rng.uniform(), 0.}};
      bool free = true;
      for(const auto& q : points) free = free && std::hypot(p[0] - q[0], p[1] - q[1]) >= d;
      if(free) points.push_back(p);
    }
    reference.push_back(nearest_before(points));
  }
  std::sort(engine.begin(), engine.end());
  std::sort(reference.begin(), reference.end());
  double ks = 0;
  for(std::size_t i = 0, j = 0; i < runs || j < runs;) {
    const double x = std::min(i < runs ? engine[i] : 10., j < runs ? reference[j] : 10.);
    while(i < runs && engine[i] <= x) ++i;
    while(j < runs && reference[j] <= x) ++j;
    ks = std::max(ks, std::abs(double(i) - double(j)) / double(runs));
  }
  EXPECT_LT(ks, 1.95 * std::sqrt(2. / double(runs)));
}

// The union-of-balls test of triangles: whenever it says covered, a dense evaluation of the triangle
// finds no point farther than the radius from every centre; and it says covered for most triangles
// that are covered with some room to spare, including many that no single ball covers.
TEST(TriangleFragments, UnionCoverageIsConservativeAndUseful)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  Random rng(17);
  int covered_with_room = 0, said_covered = 0, union_only = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    Traits traits;
    auto rnd = [&](double s) { return Traits::Point{{s * rng.uniform(), s * rng.uniform(), 0.3 * s * rng.uniform()}}; };
    traits.add_triangle(rnd(1), rnd(1), rnd(1));
    std::vector<Traits::Fragment> roots;
    traits.initial_fragments(std::back_inserter(roots));
    if(roots.empty()) continue;
    const Traits::Fragment f = roots.front();
    std::vector<std::array<double, 3>> centers;
    const int k = 2 + int(rng.uniform_index(5));
    for(int i = 0; i < k; ++i) {
      auto c = rnd(1.4);
      for(double& x : c) x -= 0.2;
      centers.push_back(c);
    }
    const double radius = 0.35 + 0.4 * rng.uniform();
    // the farthest any point of the triangle is from its nearest centre, on a dense barycentric grid
    double worst = 0;
    const int n = 120;
    for(int i = 0; i <= n; ++i)
      for(int j = 0; i + j <= n; ++j) {
        const double u = double(i) / n, v = double(j) / n;
        double best = 1e300;
        const Traits::Point p = point_at(traits, f, u, v);
        for(const auto& c : centers)
          best = std::min(best, std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) +
                                          (p[2] - c[2]) * (p[2] - c[2])));
        worst = std::max(worst, best);
      }
    const bool says = traits.is_covered_by_union(f, centers, radius);
    if(says) {
      ++said_covered;
      EXPECT_LE(worst, radius) << "trial " << trial;
      bool single = false;
      for(const auto& c : centers) single = single || traits.is_covered(f, c, radius);
      if(!single) ++union_only;
    }
    if(worst < radius * 0.97) ++covered_with_room;
  }
  ASSERT_GT(covered_with_room, 100);
  EXPECT_GT(said_covered, 0.9 * covered_with_room);
  EXPECT_GT(union_only, 50);
}

// Three balls whose spheres pass at distance R (1 + delta) from a point O of a small triangle around
// it: O is uncovered for every delta > 0, however small, so the answer must be false; rounding in
// double alone would call the near misses covered. Slightly inside (delta < 0) it must say covered.
// Far from the origin, with the centres off the triangle's plane, in several orientations.
TEST(TriangleFragments, UnionCoverageIsExactAtAHoleOfAnySize)
{
  typedef PDS::internal::Triangle_in_ball_union Test;
  typedef Test::Point P;
  const double R = 0.75;
  int holes = 0;
  for(double offset : {0., 1000.}) {
    for(double tilt : {0., 0.3, 1.1}) {
      // an orthonormal frame (x, y) of a tilted plane, and its normal z
      const P x{{std::cos(tilt), 0., std::sin(tilt)}}, y{{0., 1., 0.}}, z{{-std::sin(tilt), 0., std::cos(tilt)}};
      const P origin{{offset + 0.1, offset - 0.2, offset + 0.3}};
      auto at = [&](double a, double b, double c) {
        return P{{origin[0] + a * x[0] + b * y[0] + c * z[0], origin[1] + a * x[1] + b * y[1] + c * z[1],
                  origin[2] + a * x[2] + b * y[2] + c * z[2]}};
      };
      // a triangle of size 0.1, and one of size 2e-9 around the hole: a proof that leaves a slack of
      // about size^2 = 4e-18 (one by the convexity of the squared distances, say) would be below the
      // depth of every hole, so that only its rounding bound would keep it from claiming coverage;
      // and the covered triangles of that size (delta < 0) are beyond what the rounding bounds of the
      // candidate-point test can decide, so they need the proof by convexity
      for(double size : {1., 2e-8}) {
      const P corner[3] = {at(-0.05 * size, -0.04 * size, 0), at(0.06 * size, -0.03 * size, 0),
                           at(-0.01 * size, 0.07 * size, 0)};
      for(double delta : {-1e-3, 1e-3, 1e-6, 1e-9, 1e-12, 1e-14, 1e-15, 4e-16, 2e-16, 1e-16}) {
       for(int turn = 0; turn < 8; ++turn) {
        const double height = 0.2, reach = R * (1 + delta), planar = std::sqrt(reach * reach - height * height);
        std::vector<P> centers;
        for(int i = 0; i < 3; ++i) {
          const double angle = 0.4 + 0.7 * turn + 2.0943951023931957 * i;
          centers.push_back(at(planar * std::cos(angle), planar * std::sin(angle), i == 1 ? -height : height));
        }
        const bool says = Test::covers(corner, centers, R, 0.);
        if(delta < 0) {
          EXPECT_TRUE(says) << "offset " << offset << ", tilt " << tilt << ", size " << size << ", turn " << turn;
          continue;
        }
        // The truth, on the stored doubles (rounding far from the origin can close a tiny hole): the
        // point of the triangle's plane equidistant from the three centres, computed exactly.
        typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
        auto ek = [](const P& q) { return EK::Point_3(q[0], q[1], q[2]); };
        const EK::Plane_3 plane(ek(corner[0]), ek(corner[1]), ek(corner[2]));
        const auto o = CGAL::intersection(plane, CGAL::bisector(ek(centers[0]), ek(centers[1])),
                                          CGAL::bisector(ek(centers[0]), ek(centers[2])));
        const EK::Point_3* hole = o ? boost::get<EK::Point_3>(&*o) : nullptr;
        ASSERT_NE(hole, nullptr);
        const EK::Triangle_3 triangle(ek(corner[0]), ek(corner[1]), ek(corner[2]));
        if(size == 1.) ASSERT_TRUE(triangle.has_on(*hole));
        if(!triangle.has_on(*hole)) continue; // the rounding of the centres moved it off the tiny one
        if(CGAL::squared_distance(*hole, ek(centers[0])) <= EK::FT(R * R)) {
          continue; // no hole left in the stored doubles: any answer is right
        }
        ++holes;
        EXPECT_FALSE(says) << "a hole at relative depth " << delta << " (offset " << offset << ", tilt "
                           << tilt << ", size " << size << ")";
       }
      }
      }
    }
  }
  EXPECT_GE(holes, 400); // most survive the rounding of the centres
}

// Near-tangent and near-degenerate configurations at random: a claim of coverage is checked on a
// dense grid of the triangle against the exact distance, and must never be wrong.
TEST(TriangleFragments, UnionCoverageNeverClaimsAnUncoveredPoint)
{
  typedef PDS::internal::Triangle_in_ball_union Test;
  typedef Test::Point P;
  typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
  Random rng(23);
  int claims = 0;
  for(int trial = 0; trial < 4000; ++trial) {
    const double R = 1;
    // a small triangle near the origin, and balls whose spheres pass close to its corners or to each other
    P corner[3];
    for(P& c : corner) c = P{{0.2 * rng.uniform(), 0.2 * rng.uniform(), 0.02 * rng.uniform()}};
    std::vector<P> centers;
    const int k = 2 + int(rng.uniform_index(4));
    for(int i = 0; i < k; ++i) {
      const P& target = corner[rng.uniform_index(3)];
      const double t = 6.283185307179586 * rng.uniform(), h = 0.6 * (rng.uniform() - 0.5);
      const double reach = R * (1 + (rng.uniform() < 0.5 ? 1e-13 : 1e-3) * (rng.uniform() - 0.5));
      const double planar = std::sqrt(reach * reach - h * h);
      centers.push_back(P{{target[0] + planar * std::cos(t), target[1] + planar * std::sin(t), target[2] + h}});
    }
    if(!Test::covers(corner, centers, R, 0.)) continue;
    ++claims;
    const int n = 60;
    for(int i = 0; i <= n; ++i)
      for(int j = 0; i + j <= n; ++j) {
        const EK::FT u(double(i) / n), v(double(j) / n);
        EK::Point_3 p[3];
        for(int m = 0; m < 3; ++m) p[m] = EK::Point_3(corner[m][0], corner[m][1], corner[m][2]);
        const EK::Point_3 q = p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
        bool in = false;
        for(const P& c : centers) in = in || CGAL::squared_distance(q, EK::Point_3(c[0], c[1], c[2])) <= EK::FT(R * R);
        ASSERT_TRUE(in) << "trial " << trial << ": claimed covered, but a point is outside every ball";
      }
  }
  EXPECT_GT(claims, 200); // the test has teeth only if coverage is claimed often
}

// The triangle model's refine() is a faster form of the engine's generic step: its answers must be
// those of is_covered(), split() and is_covered_by_union() called one by one, on fragments of every
// level and orientation, near the origin and far from it, with balls that cover a fragment, some of
// its children, or none.
// The parameters of corner j of a triangle fragment, from its public members
std::array<double, 2> corner_parameters(const PDS::Triangle_fragment_traits_3::Fragment& f, int j)
{
  if(j == 0) return {{f.u, f.v}};
  const int l = -int(f.level);
  return {{f.u + std::ldexp(double(f.e[j - 1][0]), l), f.v + std::ldexp(double(f.e[j - 1][1]), l)}};
}

typedef PDS::Triangle_fragment_traits_3 Triangles;
std::array<Triangles::Point, 3> fragment_corners(const Triangles& traits, const Triangles::Fragment& f)
{
  std::array<Triangles::Point, 3> c;
  for(int j = 0; j < 3; ++j) {
    const std::array<double, 2> q = corner_parameters(f, j);
    c[j] = point_at(traits, f, q[0], q[1]);
  }
  return c;
}

// barycentric coordinates of x with respect to triangle t, in a parameter plane
std::array<double, 3> barycentric(const std::array<std::array<double, 2>, 3>& t, const std::array<double, 2>& x)
{
  auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  const double area = cross(t[0], t[1], t[2]);
  return {{cross(x, t[1], t[2]) / area, cross(t[0], x, t[2]) / area, cross(t[0], t[1], x) / area}};
}

// The triangle model's step for a fragment that got a dart: returns whether one ball of `near` covers
// it (as is_covered() decides), and otherwise writes fragments, of positive area, inside it, that
// overlap nowhere and hold every point of it that no ball covers; where it splits, they are the
// children that split() makes and the single-ball and union tests keep, in the same order. Random
// fragments, whole or pieces of long thin faces, some of them pieces that the step cut off before
// (down to ten steps deep), with 0 to 6 balls; 64 random points of each are located in the pieces.
// Both ways of the step (children and pieces cut along a chord) are taken often.
TEST(TriangleFragments, RefineKeepsEveryUncoveredPointInExactlyOnePiece)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Fragment Fragment;
  typedef Traits::Point P;
  Random rng(29);
  Refine_counts counts;
  int cut = 0, deep = 0, blocks = 0, halves_dropped = 0;
  auto same = [](const Fragment& a, const Fragment& b) {
    return a.u == b.u && a.v == b.v && a.face == b.face && a.level == b.level && a.piece == b.piece &&
           a.e[0][0] == b.e[0][0] && a.e[0][1] == b.e[0][1] && a.e[1][0] == b.e[1][0] && a.e[1][1] == b.e[1][1];
  };
  for(int trial = 0; trial < 4000; ++trial) {
    Traits traits;
    const double offset = trial % 2 ? 0. : 500.;
    auto rnd = [&]() { return P{{offset + rng.uniform(), offset + rng.uniform(), offset + 0.3 * rng.uniform()}}; };
    // every other trial, a long thin triangle (a needle or a cap) cut into pieces for a distance
    const bool thin = trial % 4 >= 2;
    auto rnd_thin = [&]() {
      return P{{offset + 4 * rng.uniform(), offset + 0.05 * rng.uniform(), offset + 0.01 * rng.uniform()}};
    };
    if(thin) traits.add_triangle(rnd_thin(), rnd_thin(), rnd_thin());
    else traits.add_triangle(rnd(), rnd(), rnd());
    std::vector<Fragment> roots;
    if(thin) traits.initial_fragments(std::back_inserter(roots), 0.01 + 0.3 * rng.uniform());
    else traits.initial_fragments(std::back_inserter(roots));
    if(roots.empty()) continue;
    Fragment f = random_descendant(traits, roots[rng.uniform_index(roots.size())], int(rng.uniform_index(8)), rng);

    // balls around f's centroid, of a radius of the order of f's size (from a few of its points)
    auto balls = [&](const Fragment& g0, std::vector<P>& near, std::vector<P>& around, double& radius) {
      const P g = traits.reference_point(g0);
      double size = 0;
      for(int i = 0; i < 8; ++i) {
        const P q = traits.random_sample(g0, rng)->point;
        size = std::max(size, 2 * std::hypot(q[0] - g[0], q[1] - g[1], q[2] - g[2]));
      }
      radius = size * (0.2 + 0.8 * rng.uniform());
      near.clear();
      around.clear();
      const int k = int(rng.uniform_index(7));
      for(int i = 0; i < k; ++i) {
        P c;
        for(int j = 0; j < 3; ++j) c[j] = g[j] + 1.6 * radius * (rng.uniform() - 0.5);
        around.push_back(c);
        if(rng.uniform() < 0.6) near.push_back(c);
      }
    };
    std::vector<P> near, around;
    double radius;
    // a third of the time, a piece that earlier steps left, up to ten of them
    if(trial % 3 == 0)
      for(int step = 0; step < 10; ++step) {
        balls(f, near, around, radius);
        std::vector<Fragment> kept;
        if(traits.refine(f, near, around, radius, std::back_inserter(kept)) || kept.empty()) break;
        f = kept[rng.uniform_index(kept.size())];
        deep += step == 9;
      }
    balls(f, near, around, radius);

    if(Traits::is_block(f)) { // its halves that no single ball covers (no union test: they are long)
      std::vector<Fragment> got, halves, expected;
      traits.split(f, std::back_inserter(halves));
      const bool covered = traits.refine(f, near, around, radius, std::back_inserter(got));
      bool one = false;
      for(const P& c : near) one = one || traits.is_covered(f, c, radius);
      ASSERT_EQ(covered, one) << "trial " << trial;
      if(!covered) {
        for(const Fragment& h : halves) {
          bool single = false;
          for(const P& c : near) single = single || traits.is_covered(h, c, radius);
          if(!single) expected.push_back(h);
        }
      }
      ASSERT_EQ(got.size(), expected.size()) << "trial " << trial;
      for(std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], expected[i])) << "trial " << trial;
      blocks += !got.empty();
      halves_dropped += !covered && got.size() < halves.size();
      continue;
    }

    std::vector<Fragment> expected; // what splitting keeps
    const bool expected_covered = step_by_operations(traits, f, near, around, radius, expected, counts);
    std::vector<Fragment> got;
    const bool covered = traits.refine(f, near, around, radius, std::back_inserter(got));
    ASSERT_EQ(covered, expected_covered) << "trial " << trial;
    counts.parent_covered += covered;
    if(covered) {
      EXPECT_TRUE(got.empty());
      continue;
    }
    std::vector<Fragment> children;
    traits.split(f, std::back_inserter(children));
    const bool split = std::all_of(got.begin(), got.end(), [&](const Fragment& g) {
      return std::any_of(children.begin(), children.end(), [&](const Fragment& c) { return same(g, c); });
    });
    if(split && !got.empty()) { // the same as the operations it replaces
      ++counts.child_kept;
      ASSERT_EQ(got.size(), expected.size()) << "trial " << trial;
      for(std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], expected[i])) << "trial " << trial;
    }
    cut += !split;

    // in the piece's parameters, relative to f's first corner (exact for the corners, on a lattice)
    typedef std::array<double, 2> Q;
    const Q o = corner_parameters(f, 0);
    auto rel = [&](const Q& q) { return Q{{q[0] - o[0], q[1] - o[1]}}; };
    const std::array<Q, 3> tf = {
        {rel(corner_parameters(f, 0)), rel(corner_parameters(f, 1)), rel(corner_parameters(f, 2))}};
    std::vector<std::array<Q, 3>> tg;
    for(const Fragment& g : got) {
      EXPECT_GT(traits.area(g), 0) << "trial " << trial;
      EXPECT_GE(traits.level(g), traits.level(f)) << "trial " << trial;
      tg.push_back({{rel(corner_parameters(g, 0)), rel(corner_parameters(g, 1)), rel(corner_parameters(g, 2))}});
      for(const Q& c : tg.back())
        for(double l : barycentric(tf, c)) EXPECT_GE(l, 0.) << "trial " << trial; // inside f
    }
    for(int i = 0; i < 64; ++i) {
      double a = rng.uniform(), b = rng.uniform();
      if(a + b > 1) a = 1 - a, b = 1 - b;
      const Q x{{a * tf[1][0] + b * tf[2][0], a * tf[1][1] + b * tf[2][1]}};
      const P px = point_at(traits, f, o[0] + x[0], o[1] + x[1]);
      double nearest = std::numeric_limits<double>::infinity();
      for(const P& c : around) nearest = std::min(nearest, std::hypot(px[0] - c[0], px[1] - c[1], px[2] - c[2]));
      int in = 0, strictly_in = 0;
      for(const auto& t : tg) {
        const std::array<double, 3> l = barycentric(t, x);
        in += l[0] >= -1e-9 && l[1] >= -1e-9 && l[2] >= -1e-9;
        strictly_in += l[0] > 1e-9 && l[1] > 1e-9 && l[2] > 1e-9;
      }
      EXPECT_LE(strictly_in, 1) << "trial " << trial; // the pieces overlap nowhere
      if(in == 0) EXPECT_LE(nearest, radius * (1 + 1e-9)) << "trial " << trial; // left out: covered
    }
  }
  EXPECT_GT(counts.parent_covered, 200);
  EXPECT_GT(counts.child_kept, 500);
  EXPECT_GT(cut, 300);
  EXPECT_GT(deep, 20);
  EXPECT_GT(blocks, 100);
  EXPECT_GT(halves_dropped, 50);
}

// The point off the plane of the triangle q, above its circumcentre, at distance `reach` from its
// corners (as computed in doubles); nothing where the circumradius is not below sqrt(0.9) D (obtuse
// triangles among them), or `reach` below it.
std::optional<std::array<double, 3>> centre_above_circumcentre(const std::array<double, 3> (&q)[3], double D,
                                                               double reach)
{
  double a[3], b[3];
  for(int i = 0; i < 3; ++i) a[i] = q[1][i] - q[0][i], b[i] = q[2][i] - q[0][i];
  const double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2], bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2], det = 2 * (aa * bb - ab * ab);
  const double s = bb * (aa - ab) / det, t = aa * (bb - ab) / det; // circumcentre q0 + s a + t b
  const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double cc[3], R2 = 0;
  for(int i = 0; i < 3; ++i) cc[i] = s * a[i] + t * b[i], R2 += cc[i] * cc[i];
  if(!(R2 < 0.9 * D * D) || !(R2 < reach * reach)) return std::nullopt;
  const double h = std::sqrt(reach * reach - R2);
  std::array<double, 3> centre;
  for(int i = 0; i < 3; ++i) centre[i] = q[0][i] + (cc[i] + h * n[i] / nn);
  return centre;
}

// A random face added to `traits`, its corners in q: q0 = o, and q1, q2 within `size` / 2 of it in each
// coordinate. Returns the face's root fragment, or nothing where it has none (a face of area 0) or
// several (a long thin face, cut into pieces).
std::optional<PDS::Triangle_fragment_traits_3::Fragment> random_face(const std::array<double, 3>& o, double size,
                                                                     Random& rng,
                                                                     PDS::Triangle_fragment_traits_3& traits,
                                                                     std::array<double, 3> (&q)[3])
{
  for(int j = 0; j < 3; ++j) q[j] = o;
  for(int j = 1; j < 3; ++j)
    for(int i = 0; i < 3; ++i) q[j][i] += size * (rng.uniform() - 0.5);
  traits.add_triangle(q[0], q[1], q[2]);
  std::vector<PDS::Triangle_fragment_traits_3::Fragment> roots;
  traits.initial_fragments(std::back_inserter(roots));
  if(roots.size() != 1) return std::nullopt;
  return roots[0];
}

// the largest squared distance from `centre` to a corner of q, exactly
CGAL::Exact_rational farthest_squared(const std::array<double, 3> (&q)[3], const std::array<double, 3>& centre)
{
  typedef CGAL::Exact_rational ET;
  ET farthest(0);
  for(const std::array<double, 3>& c : q) {
    ET d2(0);
    for(int i = 0; i < 3; ++i) d2 += (ET(c[i]) - ET(centre[i])) * (ET(c[i]) - ET(centre[i]));
    farthest = (std::max)(farthest, d2);
  }
  return farthest;
}

// Far from the origin, a ball covers a fragment unless a corner is farther from its centre than the
// radius less a margin relative to the face's size and the radius, not to the coordinates. With the
// coordinates' rounding, position_error(), as the margin, the balls' boundaries carried a band about
// 10^-7 D wide here that no test decided, and fragments where three boundaries met inside it were split
// down to the depth floor and dropped (MeshSampling.FarFromTheOriginNothingIsDropped).
TEST(TriangleFragments, CoverageMarginIsRelativeToTheFaceNotTheOrigin)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Point P;
  typedef CGAL::Exact_rational ET;
  Random rng(37);
  int in_band = 0;
  for(int trial = 0; trial < 200; ++trial) {
    const P o{{2e6 * (1 + rng.uniform()), -6e5 * (1 + rng.uniform()), 4e4 * (1 + rng.uniform())}};
    P q[3];
    Traits traits;
    const std::optional<Traits::Fragment> root = random_face(o, 0.01, rng, traits, q);
    if(!root) continue;
    const double D = 0.013;
    ASSERT_GT(D, 0x1.0p20 * traits.position_error()); // a distance the samplers accept
    // a centre off the plane above the circumcentre, at D (1 + delta) from the corners: delta below
    // -1e-7 is well inside the ball (more than the rounding of the centre's coordinates), delta above
    // 1e-7 outside; position_error() is 1.4e-7 D to 2.7e-7 D here, and the margin it gave the
    // single-ball test, four times that, kept every delta below -1e-7 from being proven covered
    const double delta = (rng.uniform() < 0.5 ? -1 : 1) * (1e-7 + 2e-7 * rng.uniform());
    const std::optional<P> above = centre_above_circumcentre(q, D, D * (1 + delta));
    if(!above) continue;
    const P centre = *above;
    // the exact distances of the face's corners (the input points) from the centre as rounded
    const ET farthest = farthest_squared(q, centre);
    const ET D2 = ET(D) * ET(D);
    if(delta < 0) {
      ASSERT_LT(farthest, D2 * ET(1 - 5e-8)) << "trial " << trial; // inside by more than 5e-8 D^2
      ++in_band;
      const std::vector<P> one{centre};
      EXPECT_TRUE(traits.is_covered(*root, centre, D)) << "trial " << trial;
      EXPECT_TRUE(traits.is_covered_by_union(*root, one, D)) << "trial " << trial;
      std::vector<Traits::Fragment> children;
      EXPECT_TRUE(traits.refine(*root, one, one, D, std::back_inserter(children))) << "trial " << trial;
    } else {
      ASSERT_GT(farthest, D2) << "trial " << trial;
      const std::vector<P> one{centre};
      EXPECT_FALSE(traits.is_covered(*root, centre, D)) << "trial " << trial;
      EXPECT_FALSE(traits.is_covered_by_union(*root, one, D)) << "trial " << trial;
    }
  }
  EXPECT_GT(in_band, 50);
}

// The single-ball test never claims a face that a ball misses by less than the rounding: balls
// whose boundary passes within a few units in the last place of the farthest corner (the face's
// corners are the input points, so the exact distances decide), near the origin and far from it.
// Without its margin the test claimed 1,441 of these faces, whose farthest corner lies outside the
// ball by less than two units in the last place of the radius. A ball larger by 10^-9 of its radius is
// proven to cover the face.
TEST(TriangleFragments, SingleBallTestIsConservativeAtTheBoundary)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Point P;
  typedef CGAL::Exact_rational ET;
  Random rng(41);
  int outside = 0, covered_near = 0;
  for(int trial = 0; trial < 4000; ++trial) {
    const double far = trial % 2 == 0 ? 1 : 1e6;
    const P o{{far * (1 + rng.uniform()), -far * (1 + rng.uniform()), far * (0.5 + rng.uniform())}};
    P q[3];
    Traits traits;
    const std::optional<Traits::Fragment> root = random_face(o, 0.1, rng, traits, q);
    if(!root) continue;
    // a centre off the plane above the circumcentre, the corners at about D from it
    const double D = 0.2;
    const std::optional<P> above = centre_above_circumcentre(q, D, D);
    if(!above || !(D > 0x1.0p20 * traits.position_error())) continue;
    const P centre = *above;
    const ET farthest = farthest_squared(q, centre);
    // radii from 8 units in the last place below the farthest corner's distance to 8 above
    const double r0 = std::sqrt(CGAL::to_double(farthest));
    for(int k = -8; k <= 8; ++k) {
      double r = r0;
      for(int step = 0; step < (k < 0 ? -k : k); ++step) r = std::nextafter(r, k < 0 ? 0. : 1.);
      if(ET(r) * ET(r) < farthest) {
        ++outside;
        EXPECT_FALSE(traits.is_covered(*root, centre, r)) << "trial " << trial << ", " << k << " ulps";
      }
    }
    if(traits.is_covered(*root, centre, r0 * (1 + 1e-9))) ++covered_near;
  }
  EXPECT_GT(outside, 10000);
  EXPECT_GT(covered_near, 1000);
}

// level() is the depth by size: a fragment's area is at most 4^-level() of its root's and more than
// 4^-(level() + 1) of it, for the pieces that chord cuts leave as for the children of midpoint
// subdivision; and a fragment above the engine's floor (depth 40) leaves its lattice room to be split
// down to it with corners of at most 52 bits. A cut puts its pieces on a finer lattice than their
// size needs; when the lattice's level counted as depth, chains of cuts reached the floor while their
// pieces were still 2^-28 of their face, and the sampler dropped them with gaps left (the test
// DepthFloor/MeshSampling.IsMaximalPoissonDiskSet). Chains of steps with one ball that holds
// a corner of the fragment, whole random triangles near the origin and far from it, down to the floor.
TEST(TriangleFragments, LevelIsTheDepthBySizeAndCutsLeaveRoomForIt)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Fragment Fragment;
  typedef Traits::Point P;
  Random rng(31);
  int cuts = 0, at_floor = 0;
  for(int trial = 0; trial < 1000; ++trial) {
    Traits traits;
    const double offset = trial % 2 ? 0. : 500.;
    auto rnd = [&]() { return P{{offset + rng.uniform(), offset + rng.uniform(), offset + 0.3 * rng.uniform()}}; };
    traits.add_triangle(rnd(), rnd(), rnd());
    std::vector<Fragment> roots;
    traits.initial_fragments(std::back_inserter(roots));
    if(roots.empty()) continue;
    const double root_area = traits.area(roots[0]);
    Fragment f = roots[0];
    for(int step = 0; step < 1000 && traits.level(f) < 40; ++step) {
      const std::array<P, 3> c = fragment_corners(traits, f);
      double size = 0;
      for(int j = 0; j < 3; ++j)
        size = std::max(size, std::hypot(c[j][0] - c[(j + 1) % 3][0], c[j][1] - c[(j + 1) % 3][1],
                                         c[j][2] - c[(j + 1) % 3][2]));
      // a ball near corner j, of a radius between 0.3 and 0.8 times the longest edge
      const int j = int(rng.uniform_index(3));
      const double radius = size * (0.3 + 0.5 * rng.uniform());
      P centre;
      for(int i = 0; i < 3; ++i) centre[i] = c[j][i] + 0.1 * ((c[0][i] + c[1][i] + c[2][i]) / 3 - c[j][i]);
      const std::vector<P> balls{centre};
      std::vector<Fragment> kept;
      if(traits.refine(f, balls, balls, radius, std::back_inserter(kept)) || kept.empty()) break;
      cuts += kept.size() <= 2 && kept[0].level != f.level + 1u; // pieces of a cut, not children
      for(const Fragment& g : kept) {
        const int l = traits.level(g);
        const double ratio = traits.area(g) / root_area;
        EXPECT_GE(l, traits.level(f)) << "trial " << trial;
        EXPECT_LE(ratio, std::ldexp(1., -2 * l) * (1 + 1e-12)) << "trial " << trial << ", level " << l;
        EXPECT_GT(ratio, std::ldexp(1., -2 * (l + 1)) * (1 - 1e-12)) << "trial " << trial << ", level " << l;
        if(l < 40) EXPECT_LE(int(g.level) + 40 - l, 52) << "trial " << trial << ", level " << l;
      }
      f = kept[rng.uniform_index(kept.size())];
    }
    at_floor += traits.level(f) >= 40;
  }
  EXPECT_GT(cuts, 2000);
  EXPECT_GT(at_floor, 400);
}

// The pieces of a long thin triangle (for a minimum distance D): one or two blocks of rows, whose
// halves, split down to the rows' triangles, tile it: their areas add up to the block's, and every
// point of the triangle lies in exactly one row triangle (or on the boundary between them). The rows'
// triangles are few (fewer than 2 L / max(D, width) for a face L long), no longer than four times
// max(D, shortest edge), nor than 4 L 2^-depth (the depth the engine's floor counts). A block's
// random points and reference point lie in its rows' triangles, and a ball holds it (is_covered())
// if it holds their corners with a little room, not if one of them is outside. Needles and caps
// (corners nearly in line), of aspect ratios up to 10^4, with D from L down to L / 30,000.
// Clusters of small faces: on a wavy grid of 115,200 faces given in a shuffled order, with two large
// faces beside it, at a distance where the faces' mean area is below D^2 / 64. The roots are far fewer
// than the faces; the clusters split down to every face of positive area exactly once, each split's
// children share their parent's area; a ball that is said to hold a cluster holds every corner of
// its faces; a dart on a cluster falls on one of its faces, in proportion to their areas; and the
// sampler's set is a maximal Poisson-disk set, as the certificate (on the same roots) finds it.
TEST(TriangleFragments, ClustersOfSmallFacesTileThemAndBoundThem)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Fragment Fragment;
  typedef Traits::Point P;
  Random rng(41);
  const int n = 240;
  auto height = [](double x, double y) { return 0.1 * std::sin(7 * x) * std::cos(5 * y); };
  std::vector<std::array<P, 3>> triangles;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      P c[4];
      for(int k = 0; k < 4; ++k) {
        const double x = double(i + k % 2) / n, y = double(j + k / 2) / n;
        c[k] = P{{x, y, height(x, y)}};
      }
      triangles.push_back({{c[0], c[1], c[3]}});
      triangles.push_back({{c[0], c[3], c[2]}});
    }
  for(std::size_t i = triangles.size(); i > 1; --i) std::swap(triangles[i - 1], triangles[rng.uniform_index(i)]);
  triangles.push_back({{P{{2, 0, 0}}, P{{3, 0, 0}}, P{{2, 1, 0}}}});
  triangles.push_back({{P{{3, 0, 0}}, P{{3, 1, 0}}, P{{2, 1, 0}}}});
  Traits traits;
  for(const auto& t : triangles) traits.add_triangle(t[0], t[1], t[2]);
  const double d = 0.05;

  std::vector<Fragment> roots;
  traits.initial_fragments(std::back_inserter(roots), d);
  std::size_t clusters = 0;
  for(const Fragment& r : roots) clusters += Traits::is_cluster(r);
  EXPECT_GT(clusters, 100u);
  EXPECT_LT(roots.size(), triangles.size() / 4);

  // each cluster down to its faces; the faces of every cluster met on the way, for the checks below
  std::vector<int> seen(triangles.size(), 0);
  std::vector<std::pair<Fragment, std::vector<std::uint32_t>>> expanded;
  std::function<void(const Fragment&, std::vector<std::uint32_t>&)> expand = [&](const Fragment& f,
                                                                                  std::vector<std::uint32_t>& faces) {
    if(!Traits::is_cluster(f)) {
      EXPECT_EQ(f.piece, 0u);
      EXPECT_EQ(traits.area(f), traits.triangle_area(f.face));
      ++seen[f.face];
      faces.push_back(f.face);
      return;
    }
    EXPECT_EQ(traits.level(f), 0);
    std::vector<Fragment> children;
    traits.split(f, std::back_inserter(children));
    EXPECT_GE(children.size(), 2u);
    double sum = 0;
    std::vector<std::uint32_t> mine;
    for(const Fragment& c : children) {
      sum += traits.area(c);
      EXPECT_LE(traits.area(c), traits.area(f));
      expand(c, mine);
    }
    EXPECT_NEAR(sum, traits.area(f), 1e-6 * traits.area(f));
    faces.insert(faces.end(), mine.begin(), mine.end());
    expanded.emplace_back(f, mine);
  };
  double total = 0;
  for(const Fragment& r : roots) {
    std::vector<std::uint32_t> faces;
    expand(r, faces);
    total += traits.area(r);
  }
  double area = 0;
  for(std::size_t i = 0; i < triangles.size(); ++i) {
    area += traits.triangle_area(std::uint32_t(i));
    EXPECT_EQ(seen[i], 1) << "face " << i;
  }
  EXPECT_NEAR(total, area, 1e-9 * area);
  ASSERT_GT(expanded.size(), clusters);

  // balls around points near a cluster: one that is said to hold it holds every corner of its faces
  int covered = 0, tested = 0;
  for(const auto& e : expanded) {
    const Fragment& f = e.first;
    const P ref = traits.reference_point(f);
    for(int k = 0; k < 4; ++k, ++tested) {
      P c;
      for(int j = 0; j < 3; ++j) c[j] = ref[j] + d * (rng.uniform() - 0.5);
      if(!traits.is_covered(f, c, d)) continue;
      ++covered;
      for(std::uint32_t face : e.second)
        for(const P& q : triangles[face])
          ASSERT_LE(std::hypot(q[0] - c[0], q[1] - c[1], q[2] - c[2]), d) << "a corner outside the ball";
    }
  }
  EXPECT_GT(covered, tested / 10);
  EXPECT_LT(covered, tested);

  // darts on the largest cluster's faces, in proportion to their areas (within 5 standard deviations)
  const auto largest = std::max_element(expanded.begin(), expanded.end(), [](const auto& a, const auto& b) {
    return a.second.size() < b.second.size();
  });
  ASSERT_GE(largest->second.size(), 8u);
  std::map<std::uint32_t, int> hits;
  const int darts = 40000;
  PDS::internal::Stream stream(7);
  for(int k = 0; k < darts; ++k) {
    const auto s = traits.random_sample(largest->first, stream);
    ASSERT_TRUE(s);
    ++hits[s->face];
  }
  double cluster_area = 0;
  for(std::uint32_t face : largest->second) cluster_area += traits.triangle_area(face);
  for(const auto& h : hits)
    ASSERT_TRUE(std::find(largest->second.begin(), largest->second.end(), h.first) != largest->second.end());
  for(std::uint32_t face : largest->second) {
    const double p = traits.triangle_area(face) / cluster_area, expected = darts * p;
    EXPECT_NEAR(hits[face], expected, 5 * std::sqrt(expected * (1 - p)) + 1) << "face " << face;
  }

  // the sampler on these roots, certified on the same roots
  std::vector<Traits::Sample> samples;
  PDS::Sampling_statistics stats;
  PDS::sample_surface(traits, std::back_inserter(samples), PDS::parameters::minimum_distance(d).statistics(std::ref(stats)));
  std::vector<P> points;
  std::vector<CGAL::Simple_cartesian<double>::Point_3> cgal_points;
  for(const auto& s : samples) {
    points.push_back(s.point);
    cgal_points.emplace_back(s.point[0], s.point[1], s.point[2]);
  }
  EXPECT_TRUE(PDS::is_poisson_disk_set(cgal_points, d));
  EXPECT_TRUE(PDS::is_maximal_on_surface(traits, points, d));
  EXPECT_EQ(stats.dropped_fragments, 0u);
  EXPECT_GT(double(samples.size()), 0.6 * area / (d * d));
}

// Long thin faces of small area (strips 1 long and 1e-6 wide) have a mean area far below D^2 / 64 but
// reach far beyond D / 4: none can be clustered, so the model does not make the index for them, and
// its roots are the faces' own, in face order (the index would give them in the order of its curve,
// which the shuffled strips make another)
TEST(TriangleFragments, LongThinFacesOfSmallAreaAreNotClustered)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Fragment Fragment;
  typedef Traits::Point P;
  Random rng(43);
  const int n = 400;
  std::vector<int> row(n);
  for(int i = 0; i < n; ++i) row[i] = i;
  for(int i = n; i > 1; --i) std::swap(row[i - 1], row[rng.uniform_index(i)]);
  Traits traits;
  for(int i = 0; i < n; ++i) {
    const double y = 0.01 * row[i], w = 1e-6;
    traits.add_triangle(P{{0, y, 0}}, P{{1, y, 0}}, P{{1, y + w, 0}});
    traits.add_triangle(P{{0, y, 0}}, P{{1, y + w, 0}}, P{{0, y + w, 0}});
  }
  const double d = 0.05;
  ASSERT_LE(2 * n * 0.5e-6, d * d / 64 * 2 * n); // the mean area alone would cluster them
  std::vector<Fragment> roots;
  traits.initial_fragments(std::back_inserter(roots), d);
  ASSERT_GE(roots.size(), std::size_t(2 * n));
  for(std::size_t i = 0; i < roots.size(); ++i) {
    EXPECT_FALSE(Traits::is_cluster(roots[i]));
    if(i > 0) EXPECT_LE(roots[i - 1].face, roots[i].face) << "root " << i;
  }
  std::vector<int> seen(2 * n, 0);
  for(const Fragment& r : roots) seen[r.face] = 1;
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 2 * n);
}

TEST(TriangleFragments, PiecesOfLongThinFacesTileThem)
{
  typedef PDS::Triangle_fragment_traits_3 Traits;
  typedef Traits::Fragment Fragment;
  typedef Traits::Point P;
  Random rng(37);
  auto sub = [](const P& a, const P& b) { return P{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; };
  auto cross = [](const P& a, const P& b) {
    return P{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  };
  auto dot = [](const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto norm = [&](const P& a) { return std::sqrt(dot(a, a)); };
  int cut = 0, caps_cut = 0, most_rows = 0, blocks_checked = 0, uniform_checked = 0;
  for(int trial = 0; trial < 400; ++trial) {
    P q[3];
    const double thinness = std::pow(10., -4 * rng.uniform());
    const bool cap = trial % 2 == 1;
    for(P& c : q) {
      // a cap: corners spread along a line; a needle: two corners close together, one far
      const double x = cap ? rng.uniform() : (&c == &q[0] ? 1. : 0.05 * rng.uniform());
      c = P{{3 + 10 * x, 2 + thinness * rng.uniform(), -1 + thinness * rng.uniform()}};
    }
    Traits traits;
    traits.add_triangle(q[0], q[1], q[2]);
    const double area = traits.triangle_area(0);
    if(!(area > 0)) continue;
    const double edges[3] = {norm(sub(q[1], q[0])), norm(sub(q[2], q[1])), norm(sub(q[0], q[2]))};
    const double L = std::max({edges[0], edges[1], edges[2]}), shortest = std::min({edges[0], edges[1], edges[2]});
    const double width = 2 * area / L;
    const double d = L * std::pow(10., -4.5 * rng.uniform()); // down to L / 30,000: up to 2^12 rows
    std::vector<Fragment> roots;
    traits.initial_fragments(std::back_inserter(roots), d);
    ASSERT_FALSE(roots.empty());
    EXPECT_LE(roots.size(), 2u) << "trial " << trial;
    // the blocks split down to the rows' triangles, each block's halves checked on the way
    std::vector<Fragment> pieces;
    std::function<void(const Fragment&, std::vector<Fragment>&)> expand = [&](const Fragment& f,
                                                                              std::vector<Fragment>& leaves) {
      if(!Traits::is_block(f)) {
        leaves.push_back(f);
        return;
      }
      std::vector<Fragment> halves;
      traits.split(f, std::back_inserter(halves));
      double sum = 0;
      for(const Fragment& h : halves) {
        sum += traits.area(h);
        EXPECT_EQ(traits.level(h), traits.level(f) + 1) << "trial " << trial;
        expand(h, leaves);
      }
      EXPECT_NEAR(sum, traits.area(f), 1e-12 * traits.area(f)) << "trial " << trial;
    };
    for(const Fragment& r : roots) expand(r, pieces);
    EXPECT_LE(double(pieces.size()), 2 * L / std::max(d, width) + 1) << "trial " << trial;
    if(pieces.size() > 1) {
      ++cut;
      caps_cut += cap;
    }
    most_rows += traits.level(pieces.front()) == 12; // k = 12, the most

    double total = 0;
    std::vector<std::array<P, 3>> corners;
    for(const Fragment& f : pieces) {
      EXPECT_EQ(f.level, 0u);
      EXPECT_LE(traits.level(f), 12);
      EXPECT_GT(traits.area(f), 0);
      total += traits.area(f);
      corners.push_back(fragment_corners(traits, f));
      {
        // its area is the area of its corners' triangle
        const auto& c = corners.back();
        EXPECT_NEAR(traits.area(f), 0.5 * norm(cross(sub(c[1], c[0]), sub(c[2], c[0]))), 1e-6 * traits.area(f))
            << "trial " << trial;
      }
      if(pieces.size() > 1) {
        const auto& c = corners.back();
        const double diameter = std::max({norm(sub(c[1], c[0])), norm(sub(c[2], c[1])), norm(sub(c[0], c[2]))});
        EXPECT_LE(diameter, 4 * std::max(d, shortest)) << "trial " << trial;
        // the depth the engine's floor counts is that of a fragment of the face this long
        EXPECT_LE(diameter, 4 * std::ldexp(L, -traits.level(f))) << "trial " << trial;
      }
    }
    EXPECT_NEAR(total, area, 1e-12 * area) << "trial " << trial;

    // random points of the triangle, located in the pieces by barycentric coordinates (relative
    // tolerance 1e-7: a point that close to a piece's edge may be in either piece)
    const P normal = cross(sub(q[1], q[0]), sub(q[2], q[0]));
    for(int i = 0; i < 200; ++i) {
      double a = rng.uniform(), b = rng.uniform();
      if(a + b > 1) a = 1 - a, b = 1 - b;
      P x;
      for(int j = 0; j < 3; ++j) x[j] = q[0][j] + a * (q[1][j] - q[0][j]) + b * (q[2][j] - q[0][j]);
      int inside = 0, near_edge = 0;
      for(const auto& c : corners) {
        const double whole = dot(cross(sub(c[1], c[0]), sub(c[2], c[0])), normal);
        double lowest = 1;
        for(int j = 0; j < 3; ++j)
          lowest = std::min(lowest, dot(cross(sub(c[(j + 1) % 3], x), sub(c[(j + 2) % 3], x)), normal) / whole);
        inside += lowest > 1e-7;
        near_edge += std::abs(lowest) <= 1e-7;
      }
      ASSERT_LE(inside, 1) << "trial " << trial << ": pieces overlap";
      ASSERT_GE(inside + near_edge, 1) << "trial " << trial << ": a point of the face is in no piece";
    }

    // a few blocks: their points against their rows' triangles
    for(int b = 0; b < 4 && Traits::is_block(roots[0]); ++b) {
      Fragment block = roots[0];
      for(int depth = int(rng.uniform_index(4)); depth > 0; --depth) {
        std::vector<Fragment> halves;
        traits.split(block, std::back_inserter(halves));
        const Fragment& h = halves[rng.uniform_index(halves.size())];
        if(!Traits::is_block(h)) break;
        block = h;
      }
      std::vector<Fragment> leaves;
      expand(block, leaves);
      std::vector<std::array<P, 3>> rows;
      for(const Fragment& f : leaves) rows.push_back(fragment_corners(traits, f));
      auto in_rows = [&](const P& x) {
        for(const auto& c : rows) {
          const double whole = dot(cross(sub(c[1], c[0]), sub(c[2], c[0])), normal);
          double lowest = 1;
          for(int j = 0; j < 3; ++j)
            lowest = std::min(lowest, dot(cross(sub(c[(j + 1) % 3], x), sub(c[(j + 2) % 3], x)), normal) / whole);
          if(lowest >= -1e-7) return true;
        }
        return false;
      };
      for(int i = 0; i < 50; ++i) EXPECT_TRUE(in_rows(traits.random_sample(block, rng)->point)) << "trial " << trial;
      const P g = traits.reference_point(block);
      EXPECT_TRUE(in_rows(g)) << "trial " << trial;
      double farthest = 0;
      for(const auto& c : rows)
        for(const P& x : c) farthest = std::max(farthest, norm(sub(x, g)));
      EXPECT_TRUE(traits.is_covered(block, g, 1.01 * farthest)) << "trial " << trial;
      EXPECT_FALSE(traits.is_covered(block, g, 0.99 * farthest)) << "trial " << trial;
      ++blocks_checked;
      // uniform: its first half (or row triangle) gets its share of the random points (within 5 sigma)
      if(leaves.size() <= 32) {
        std::vector<Fragment> halves, first;
        traits.split(block, std::back_inserter(halves));
        expand(halves[0], first);
        const double share = traits.area(halves[0]) / traits.area(block);
        rows.clear();
        for(const Fragment& f : first) rows.push_back(fragment_corners(traits, f));
        int hits = 0;
        const int n = 1000;
        for(int i = 0; i < n; ++i) hits += in_rows(traits.random_sample(block, rng)->point);
        EXPECT_NEAR(double(hits) / n, share, 5 * std::sqrt(share * (1 - share) / n) + 1e-3) << "trial " << trial;
        ++uniform_checked;
      }
    }
  }
  EXPECT_GT(cut, 200); // most faces are cut, caps included, some into the most rows
  EXPECT_GT(caps_cut, 100);
  EXPECT_GT(most_rows, 10);
  EXPECT_GT(blocks_checked, 500);
  EXPECT_GT(uniform_checked, 100);
}

// grid_cell() is the floor of the scaled coordinate, on both sides of zero and at integers.
TEST(CellHashTable, GridCellIsTheFloor)
{
  using PDS::internal::grid_cell;
  for(double x : {0., -0., 0.5, 1., 1.5, -0.5, -1., -1.5, 1e-300, -1e-300, 3e15 + 0.5, -3e15 - 0.5, 0x1.0p61, -0x1.0p61})
    EXPECT_EQ(double(grid_cell(x, 1.)), std::floor(x)) << x;
  Random rng(31);
  for(int i = 0; i < 10000; ++i) {
    const double x = (rng.uniform() - 0.5) * std::ldexp(1., int(rng.uniform_index(60)));
    EXPECT_EQ(double(grid_cell(x, 1.)), std::floor(x)) << x;
  }
  EXPECT_THROW(grid_cell(0x1.0p62, 1.), PDS::Invalid_input);
  EXPECT_THROW(grid_cell(std::nan(""), 1.), PDS::Invalid_input);
}

// The table against std::map, with cells near one another, then cells 2^31 and more apart on an axis
// (whose coordinates relative to the first cell agree in their low 32 bits with cells already in),
// inserted while the table grows; from tables sized for no cell (16 slots, then powers of two) and
// for 37 and 1,000 cells (74 and 2,000 slots, whose probes wrap around from the last slot to the first).
TEST(CellHashTable, FindsWhatWasInsertedNearAndFar)
{
  using PDS::internal::Cell_hash_table;
  typedef std::array<std::int64_t, 3> C;
  Random rng(41);
  for(int run = 0; run < 6; ++run) {
    const int far_from = run % 2;
    const std::size_t expected_cells[3] = {0, 37, 1000};
    Cell_hash_table table(expected_cells[run / 2]);
    std::map<C, std::uint32_t> reference;
    auto random_cell = [&](bool far) {
      C c;
      for(std::int64_t& x : c) x = -3 + std::int64_t(rng.uniform_index(7));
      if(far) c[rng.uniform_index(3)] += (std::int64_t(1) << (31 + rng.uniform_index(31))) * (rng.uniform() < 0.5 ? 1 : -1);
      return c;
    };
    for(int i = 0; i < 3000; ++i) {
      // the first half near the origin; the second half far or near, after the first far one
      const C c = random_cell(i >= 1500 && (far_from || i == 1500 || rng.uniform() < 0.5));
      const std::uint32_t value = std::uint32_t(reference.size());
      const std::uint32_t got = table.find_or_insert(c[0], c[1], c[2], value);
      const auto it = reference.emplace(c, value).first;
      ASSERT_EQ(got, it->second) << i;
      const C q = random_cell(rng.uniform() < 0.5);
      const auto r = reference.find(q);
      ASSERT_EQ(table.find(q[0], q[1], q[2]), r == reference.end() ? Cell_hash_table::none : r->second) << i;
      // a cell that agrees with c in the low 32 bits of each coordinate
      const std::int64_t shift = std::int64_t(1) << 32;
      const C alias{{c[0] + shift, c[1], c[2] - shift}};
      const auto a = reference.find(alias);
      ASSERT_EQ(table.find(alias[0], alias[1], alias[2]), a == reference.end() ? Cell_hash_table::none : a->second);
    }
    EXPECT_EQ(table.size(), reference.size());
    for(const auto& [c, value] : reference) EXPECT_EQ(table.find(c[0], c[1], c[2]), value);
  }
}

// Cells that a hash linear in the cell sends to one slot: the combinations of three short vectors
// whose sums of products with the old hash's constants are 0 modulo 2^64 (found by lattice
// reduction). 4,096 of them made one probe chain, 2,048 slots read a lookup on average; here about
// as many as for cells at random.
TEST(CellHashTable, CellsOnALatticeDoNotShareAProbeChain)
{
  using PDS::internal::Cell_hash_table;
  const std::int64_t v[3][3] = {
      {-852863, -1285698, -183727}, {-2155039, 2521007, -1723558}, {372242, -551297, -3425731}};
  Cell_hash_table table(4096);
  std::vector<std::array<std::int64_t, 3>> cells;
  for(int i = 0; i < 16; ++i)
    for(int j = 0; j < 16; ++j)
      for(int k = 0; k < 16; ++k) {
        std::array<std::int64_t, 3> c;
        for(int a = 0; a < 3; ++a) c[a] = i * v[0][a] + j * v[1][a] + k * v[2][a];
        cells.push_back(c);
        table.find_or_insert(c[0], c[1], c[2], std::uint32_t(cells.size() - 1));
      }
  std::size_t probes = 0;
  for(std::size_t n = 0; n < cells.size(); ++n) {
    const auto& c = cells[n];
    ASSERT_EQ(table.find(c[0], c[1], c[2]), n);
    probes += table.probes(c[0], c[1], c[2]);
  }
  EXPECT_LT(double(probes) / double(cells.size()), 4.);
}

// Every sample within reach of a point is in that point's bucket, whatever the cell size.
TEST(NeighborBuckets, BucketHoldsEveryNeighbor)
{
  Random rng(5);
  for(double factor : {2., 4., 7.}) {
    const double reach = 0.05;
    PDS::internal::Neighbor_buckets buckets(reach, factor, 100);
    std::vector<std::array<double, 3>> points;
    for(int i = 0; i < 3000; ++i) {
      // on a sphere of radius 1 around (10, -3, 2), so cells far from the origin and of all signs
      const double z = 2 * rng.uniform() - 1, t = 6.283185307179586 * rng.uniform(), s = std::sqrt(1 - z * z);
      points.push_back({{10 + s * std::cos(t), -3 + s * std::sin(t), 2 + z}});
      buckets.insert(points.back());
    }
    EXPECT_EQ(buckets.size(), points.size());
    for(int trial = 0; trial < 2000; ++trial) {
      // queries exactly at distance reach from a sample too
      std::array<double, 3> p = points[rng.uniform_index(points.size())];
      if(trial % 2) p[0] += reach;
      else for(double& c : p) c += reach * (rng.uniform() - 0.5);
      const std::vector<std::array<double, 3>>* bucket = buckets.bucket(p);
      for(const auto& q : points) {
        const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
        if(d2 > reach * reach) continue;
        ASSERT_NE(bucket, nullptr);
        EXPECT_NE(std::find(bucket->begin(), bucket->end(), q), bucket->end()) << "factor " << factor;
      }
    }
  }
}

// A bucket has room for as many copies as it holds while it holds one or two: where samples lie far
// apart, most buckets hold one copy, and room for four took four times the memory.
TEST(NeighborBuckets, SmallBucketsHaveNoFreeRoom)
{
  const double reach = 0.05;
  PDS::internal::Neighbor_buckets buckets(reach, 4, 10);
  // in the middle of the cell [0, 0.2)^3 (side 4 reach), so each point is copied into that cell alone
  const std::array<double, 3> a{{0.1, 0.1, 0.1}}, b{{0.11, 0.1, 0.1}}, c{{0.1, 0.11, 0.1}};
  buckets.insert(a);
  ASSERT_NE(buckets.bucket(a), nullptr);
  EXPECT_EQ(buckets.bucket(a)->size(), 1u);
  EXPECT_EQ(buckets.bucket(a)->capacity(), 1u);
  buckets.insert(b);
  EXPECT_EQ(buckets.bucket(a)->capacity(), 2u);
  buckets.insert(c);
  EXPECT_EQ(buckets.bucket(a)->size(), 3u);
  EXPECT_EQ(buckets.bucket(a)->capacity(), 4u);
}

// Inserting points in batches makes the same buckets, in the same order, as inserting them one by one.
TEST(NeighborBuckets, BatchInsertionIsOneByOne)
{
  Random rng(8);
  const double reach = 0.05;
  PDS::internal::Neighbor_buckets one_by_one(reach, 4, 10), in_batches(reach, 4, 10);
  std::vector<std::array<double, 3>> points;
  for(int i = 0; i < 5000; ++i) {
    const double z = 2 * rng.uniform() - 1, t = 6.283185307179586 * rng.uniform(), s = std::sqrt(1 - z * z);
    points.push_back({{-4 + s * std::cos(t), 7 + s * std::sin(t), z}});
    one_by_one.insert(points.back());
  }
  // batches of 0 to 40 points; the tables grow during the batches
  for(std::size_t i = 0; i < points.size();) {
    const std::size_t n = (std::min)(points.size() - i, std::size_t(rng.uniform_index(41)));
    in_batches.insert(points.data() + i, points.data() + i + n);
    i += n;
  }
  EXPECT_EQ(in_batches.size(), one_by_one.size());
  std::size_t compared = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    std::array<double, 3> p = points[rng.uniform_index(points.size())];
    for(double& c : p) c += 4 * reach * (rng.uniform() - 0.5);
    const std::vector<std::array<double, 3>>* a = one_by_one.bucket(p);
    const std::vector<std::array<double, 3>>* b = in_batches.bucket(p);
    ASSERT_EQ(a == nullptr, b == nullptr);
    if(!a) continue;
    EXPECT_EQ(*a, *b);
    compared += a->size();
  }
  EXPECT_GT(compared, std::size_t(10000));
}

} // namespace
