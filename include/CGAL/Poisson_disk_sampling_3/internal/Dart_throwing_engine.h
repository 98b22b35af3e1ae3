// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_DART_THROWING_ENGINE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_DART_THROWING_ENGINE_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Active_fragment_pool.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Neighbor_buckets.h>
#include <CGAL/Poisson_disk_sampling_3/internal/optional_operations.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>
#include <CGAL/Poisson_disk_sampling_3/internal/exact_distance.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <mutex>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

typedef std::array<double, 3> Point_d;

/// The refusal of a model's pieces: its roots for the distance, where they outnumber its whole roots
/// far, or its fragments in wait, where they outnumber its samples far (`Point_limit_exceeded`, so
/// that callers need not know it).
class Pieces_limit_exceeded : public Point_limit_exceeded
{
public:
  using Point_limit_exceeded::Point_limit_exceeded;
};

/// the stages of a batch, in order, as `Engine_statistics::stage_seconds` counts them
enum Engine_stage {
  draw_stage,     // the pool's draws; starts loading the pool entries
  fragment_stage, // reads the entries; starts loading what random_sample() reads
  sample_stage,   // the pool's rejection step, random_sample(), the cell; starts loading hash slots
  bucket_stage,   // the hash probes; starts loading the bucket headers
  points_stage,   // starts loading the buckets' points (every cache line, up to 16)
  scan_stage,     // the bucket scans and the exact test of each dart
  accept_stage,   // the darts judged in order
  insert_stage,   // the batch's samples copied into their buckets
  refine_stage,   // refine() or its fallback, and the pushes of the children
  end_stage,      // the pool's removal of the fragments taken
  number_of_stages
};

/// names of the stages, for reports
inline const char* engine_stage_name(int stage)
{
  static const char* const names[number_of_stages] = {"draw", "fragment", "sample", "bucket", "points",
                                                       "scan", "accept", "insert", "refine", "end"};
  return names[stage];
}

// Stage_clock's members and the engine's depend on two macros, CGAL_LINKED_WITH_TBB (the threads'
// scratch) and CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES (the clock). Each combination has an inline
// namespace of its own, so that translation units compiled with different ones and linked into one
// program each keep their own classes (one definition rule): a library built without TBB and a
// program built with it, say. With one name for both layouts, the linker would keep one copy of each
// member function, and code compiled for one layout would run on objects of the other.
#ifdef CGAL_LINKED_WITH_TBB
#ifdef CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
#define CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT engine_with_tbb_timed
#else
#define CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT engine_with_tbb
#endif
#else
#ifdef CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
#define CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT engine_sequential_timed
#else
#define CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT engine_sequential
#endif
#endif

inline namespace CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT {

/// Times each stage of the batches, with the clock read between stages, when the macro
/// `CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES` is defined before this header is included (as the
/// profile `benchmark/Poisson_disk_sampling_3/bench_stages.cpp` does); otherwise it is empty and
/// costs nothing. Translation units compiled with and without it may be linked together (see above).
class Stage_clock
{
public:
#ifdef CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
  void start() { last_ = std::chrono::steady_clock::now(); }
  void lap(double& seconds)
  {
    const auto now = std::chrono::steady_clock::now();
    seconds += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

private:
  std::chrono::steady_clock::time_point last_;
#else
  void start() {}
  void lap(double&) {}
#endif
};

/// what a run did, for tests and benchmarks
struct Engine_statistics
{
  std::size_t darts = 0;              // fragments picked and given a dart
  std::size_t samples = 0;            // darts accepted
  std::size_t dropped_at_max_depth = 0; // uncovered fragments dropped at the depth floor
  std::size_t darts_on_covered = 0;     // rejected darts whose fragment proved entirely covered
  std::size_t peak_active = 0;          // the most fragments in the pool at the start of a batch
  bool stopped = false;                 // the run stopped at the sample limit of set_sample_stop()
  std::array<double, number_of_stages> stage_seconds{}; // see Stage_clock: zeros unless it is on
};

/// area / (pi r^2), r = d / 2: how many disks of radius r the area holds, the estimate of a run's count
/// that the bounds on points are checked against (a maximal set in the plane has about 0.55 times as
/// many points)
inline double disk_count(double area, double d)
{
  const double r = 0.5 * d;
  return area / (3.14159265358979323846 * r * r);
}

/// Checks a surface's total area against the point bound, before anything large is allocated.
inline void check_expected_count(double total_area, double minimum_distance, std::size_t max_points)
{
  const double expected = disk_count(total_area, minimum_distance);
  if(expected <= double(max_points)) return;
  std::string count;
  if(!(expected < 1e18)) {
    count = number_text(expected);
  } else if(std::uint64_t(expected) > max_points) {
    count = std::to_string(std::uint64_t(expected));
  } else {
    // above the bound by less than one point (4.43 for a bound of 4): the digits that show it
    char text[32];
    for(int digits = 3; digits <= 17; ++digits) {
      std::snprintf(text, sizeof(text), "%.*g", digits, expected);
      if(std::strtod(text, nullptr) > double(max_points)) break;
    }
    count = text;
  }
  throw Point_limit_exceeded("the expected number of points (about " + count +
                             ", area / (pi r^2)) exceeds maximum_number_of_points (" + std::to_string(max_points) +
                             "); use a larger radius or raise the bound");
}

/// The loop of the paper's Section 3.1 over any model of SurfaceFragmentTraits_3.
/// See doc/Poisson_disk_sampling_3/design.md for why it is shaped this way.
template <class Traits>
class Dart_throwing_engine
{
public:
  typedef typename Traits::Fragment Fragment;
  typedef typename Traits::Sample Sample;

  Dart_throwing_engine(const Traits& traits, double minimum_distance, std::uint64_t seed,
                       std::size_t max_points, int max_depth = 40)
    : traits_(traits), d_(minimum_distance), seed_(seed), max_points_(max_points), max_depth_(max_depth)
  {
    if(!(d_ > 0) || !std::isfinite(d_))
      throw Invalid_input("the minimum distance must be positive and finite");
    check_distance_range(d_);
    check_distance_precision(d_, traits_.position_error());
    // where widened_reach(D, c) reaches 2 D: at most 27 buckets a sample
    coordinate_limit_ = 1e15 * (1 - 1e-9) * d_;
  }

  /// Whether `run()` first refuses a surface whose area / (pi r^2) exceeds the point bound (by
  /// default, yes). A `number_of_points` search compares its target with the bound instead, and the
  /// estimate with four times the bound: the distance it tries for n points has area / (pi r^2) near
  /// 1.8 n. The bound on the samples accepted holds either way.
  void set_expected_count_check(bool check) { check_expected_count_ = check; }

  /// Whether `run()` throws each batch's darts and refines their fragments on TBB's threads (only where
  /// CGAL_LINKED_WITH_TBB is defined; by default, no). The samples are the same either way: each dart
  /// draws from a generator of its own, seeded in order from the run's, and the darts are judged and
  /// their children pushed in order on this thread (design.md, "Threads").
  void set_parallel(bool parallel) { parallel_ = parallel; }

  /// How many draws in a row may pass without a dart thrown before `run()` gives up on the model
  /// (by default 2^30: 13 to 22 s of draws, with 10,000 fragments or one, measured with a model that
  /// refuses everything): a model whose `random_sample()` refuses every dart would otherwise never
  /// end. The pool's own rejection step passes at least half of its draws, so only a model that
  /// refuses almost everything reaches the limit.
  void set_refusal_limit(std::uint64_t draws) { refusal_limit_ = draws; }

  /// Makes `run()` return, with `stopped` set in its statistics, instead of accepting a sample beyond
  /// the first `samples` (by default, never): the samples written are then not a maximal set. A count
  /// search uses it to cut short a run that makes far more samples than it looks for.
  void set_sample_stop(std::size_t samples) { sample_stop_ = samples; }

  /// Makes `run()` return once it has accepted its first sample if `holds_surface(sample)` is true
  /// (by default, never): for a distance at which one sample may cover the whole surface, where the
  /// coverage tests cannot always prove it (on a sphere at its diameter or more, the antipode is
  /// about 2R away: see sample_sphere.h). Where it is false, the run goes on. Either way the samples
  /// are those a full run accepts for the same seed, as far as the run goes.
  void set_first_sample_stop(std::function<bool(const Sample&)> holds_surface)
  {
    first_sample_stop_ = std::move(holds_surface);
  }

  /// Throws darts until the surface is covered; calls `output(sample)` for each accepted sample.
  template <class SampleOutput>
  Engine_statistics run(SampleOutput&& output)
  {
    // The roots are made twice and never stored together: a first pass counts them and sums their
    // areas, so that the checks below refuse a request before anything large is allocated; a second
    // pushes them into the pool. (A list of the roots beside the pool took a fragment's bytes a root at
    // the start, 24 then: 80 MB on the 3.3M-face mesh of the benchmarks, the peak when it is sampled
    // sparsely.)
    std::size_t roots = 0;
    double total_area = 0, max_area = 0;
    auto measure = [&](const Fragment& f) {
      ++roots;
      const double a = checked_area(f);
      total_area += a;
      if(a > max_area) max_area = a;
    };
    root_fragments(traits_, d_, Calling_output(&measure));
    // The roots a model writes for the distance beyond those it writes without it (pieces of its
    // faces; the triangle model writes at most two per face, see its "Long thin triangles"): each takes
    // a pool entry and its share of a chunk, and four per point of the bound and six per face leave
    // room in the memory budget, 200 bytes a sample and 300 a face. With fewer roots than four per
    // point of the bound there is nothing to refuse, and the faces need not be counted.
    if(double(roots) > 4 * double(max_points_)) {
      std::size_t faces = 0;
      traits_.initial_fragments(Counting_output{&faces}); // the roots without the distance: no pieces
      const std::size_t pieces = roots > faces ? roots - faces : 0;
      if(double(pieces) > 4 * double(max_points_) + 6 * double(faces))
        throw Pieces_limit_exceeded("at the minimum distance " + number_text(d_) +
                                    ", the surface's pieces would outnumber its faces by " +
                                    std::to_string(pieces) + ", more than four times maximum_number_of_points (" +
                                    std::to_string(max_points_) + ") plus six per face (" + std::to_string(faces) +
                                    "); use a larger distance or raise the bound");
    }
    check_surface_area(total_area, "sample");
    if(check_expected_count_) check_expected_count(total_area, d_, max_points_);

    Active_fragment_pool<Item> pool(max_area);
    // The pool files a fragment by its area relative to the largest root's: a larger one would be
    // drawn as if its area were that one, less often than its area says. A model's children may
    // exceed it by rounding (a part of the largest root whose area rounds up), not more.
    max_child_area_ = max_area * (1 + 0x1.0p-20);
    auto push = [&](const Fragment& f) {
      const double a = traits_.area(f);
      if(!(a <= max_child_area_))
        throw Invalid_input("the surface model gave an initial fragment the area " + number_text(a) +
                            ", above the largest it gave them when they were counted (" + number_text(max_area) +
                            "): area() must return the same double for the same fragment on every call");
      if(a > 0) pool.push(make_item(f, 0), a);
    };
    root_fragments(traits_, d_, Calling_output(&push));

    // (converted only below half the largest size_t: where the bound was raised that far, the
    // estimate may exceed the largest, whose conversion to an integer is undefined)
    const double estimate = disk_count(total_area, d_);
    const std::size_t half = (std::numeric_limits<std::size_t>::max)() / 2;
    const std::size_t expected = estimate < double(half) ? std::size_t(estimate) + 1 : half;
    // cells of side 4D: a sample is copied into 3.4 buckets on average, a query scans about 30
    // samples; 2D copies each sample 8 times, 6D to 8D scan twice as many for no measured gain. The
    // hash table is sized for the points expected, at most the bound, the run's stop and 2^23 (32 MB
    // of slots), and grows from there: the estimate follows the area, which surfaces that overlap
    // themselves count many times over (2,000 copies of a triangle, 9 10^7 points expected for
    // 25,000 made, were given 360 MB of slots for 84,000 cells).
    const std::size_t table_points = (std::min)({expected, max_points_, sample_stop_, std::size_t(1) << 23});
    Neighbor_buckets buckets(d_, 4, table_points);
    Random rng(seed_);
    Engine_statistics stats;
    std::uint64_t refused_in_a_row = 0; // draws since the last dart thrown
    Stage_clock clock;
    std::vector<Dart> darts;
    darts.reserve(max_batch);
    std::vector<Point_d> accepted; // the samples accepted in the current batch
    // for the k-th dart of a batch: the samples within D of it (the only possible single coverers of
    // its fragment F), and within 2D (they may cover F together); kept from batch to batch, so that
    // their storage is reused
    std::vector<std::vector<Point_d>> near(max_batch), around(max_batch);
    std::vector<std::vector<Fragment>> children(max_batch);

    // A bound on the fragments in wait, far above what the models make, so that a model whose
    // coverage tests never succeed, or whose samples lie off their fragments, stops with an error
    // instead of filling the memory four times over at each level down to the depth floor. It grows
    // with the samples accepted: on strips much narrower than D a sample covers far less than
    // pi r^2, and the samples, with the fragments, outnumber `expected` a hundredfold (500 strips
    // 1e-4 wide, 0.01 apart, at D = 0.02: 875,000 samples for 8,000 expected). The triangle model
    // keeps at most 1.5 times the expected points plus the roots on the triangle meshes of CGAL's data
    // set at 100 and 3,000 points; without its cuts of long faces, 33 times on a cylinder of 128
    // needles.
    const double fixed_active = 64 * (double(expected) + double(roots)) + 1048576;
    while(!pool.empty()) {
      if(pool.size() > stats.peak_active) stats.peak_active = pool.size();
      if(double(pool.size()) > fixed_active + 64 * double(stats.samples))
        throw Pieces_limit_exceeded("the surface model's fragments in wait (" + std::to_string(pool.size()) +
                                    ") exceed 64 times the samples, the expected points and the initial "
                                    "fragments: are its coverage tests conservative but able to succeed, and "
                                    "its samples on their fragments?");
      // A batch throws n independent darts at the pool as it stands, then processes them in order:
      // the same process as throwing them one by one, because fragments are only ever a cover of the
      // free area, and a dart on a covered spot is rejected either way (design.md, "Batches").
      // Each stage below starts the memory accesses of the next one for all darts of the batch, so
      // that their cache misses overlap instead of following each other.
      clock.start();
      pool.begin_batch();
      std::size_t n = pool.size() / 8;
      n = n < 1 ? 1 : (n > max_batch ? max_batch : n);
      darts.resize(n);
      for(Dart& d : darts) {
        d.handle = pool.draw(rng);
        d.u = rng.uniform();
        d.stream = rng.next();
        pool.prefetch(d.handle);
      }
      clock.lap(stats.stage_seconds[draw_stage]);
      // Each dart draws its point from a generator of its own, seeded above: what it draws does not
      // depend on which thread throws it, or in which order.
      auto throw_darts = [&](std::size_t first, std::size_t last, Scratch& scratch, bool timed) {
        auto lap = [&](Engine_stage stage) {
          scratch.stage = int(stage) + 1;
          if(timed) clock.lap(stats.stage_seconds[stage]);
        };
        for(std::size_t k = first; k < last; ++k) {
          darts[k].item = pool.item(darts[k].handle);
          prefetch_fragment(darts[k].item.fragment);
        }
        lap(fragment_stage);
        // the batch's fragments and faces overflow the first-level cache too: asked for again a few
        // darts ahead. The darts thrown are moved to the front of the range, in order (the compaction
        // writes only to places already read); the others are marked not thrown.
        std::size_t thrown = first;
        for(std::size_t k = first; k < last; ++k) {
          if(k + lookahead < last) prefetch_fragment(darts[k + lookahead].item.fragment);
          Dart& d = darts[k];
          // the pool's rejection step: a refused draw is no dart; nor is a dart that a rejection step in
          // the model refuses
          const double area = traits_.area(d.item.fragment);
          if(!pool.is_filed_with(d.handle, area) || area > max_child_area_)
            refuse_changed_area(area, pool.bin_range(d.handle));
          if(!pool.accepts(d.handle, area, d.u)) continue;
          Stream stream(d.stream);
          d.sample = traits_.random_sample(d.item.fragment, stream);
          if(!d.sample) continue;
          d.point = traits_.point(*d.sample);
          if(!(std::abs(d.point[0]) <= coordinate_limit_ && std::abs(d.point[1]) <= coordinate_limit_ &&
               std::abs(d.point[2]) <= coordinate_limit_))
            refuse_sample_at(d.point);
          d.cell = buckets.cell(d.point);
          buckets.prefetch_slot(d.cell);
          d.thrown = true;
          darts[thrown++] = d;
        }
        for(std::size_t k = thrown; k < last; ++k) darts[k].thrown = false;
        last = thrown;
        lap(sample_stage);
        for(std::size_t k = first; k < last; ++k) {
          Dart& d = darts[k];
          d.bucket = buckets.bucket(d.cell);
          Neighbor_buckets::prefetch_header(d.bucket);
        }
        lap(bucket_stage);
        // The batch's buckets (8 cache lines each on average) do not all fit in the first-level cache:
        // asked for there, they evicted each other and what the stages read in the meantime. They are
        // asked for into the second level, and the scan asks again for the bucket a few darts ahead,
        // which then comes from there into the first.
        for(std::size_t k = first; k < last; ++k)
          Neighbor_buckets::prefetch_points_to_second_level(darts[k].bucket);
        lap(points_stage);
        // one scan of each bucket finds both whether the dart is free and the samples that may cover
        // its fragment, which the refinement below needs
        for(std::size_t k = first; k < last; ++k) {
          Dart& d = darts[k];
          if(k + lookahead < last) Neighbor_buckets::prefetch_points(darts[k + lookahead].bucket);
          near[k].clear();
          around[k].clear();
          if(d.bucket) gather_near(*d.bucket, d.point, near[k], around[k], scratch.hits);
          d.free = true;
          for(std::size_t i = 0; i < near[k].size() && d.free; ++i)
            d.free = compare_distance_exact(d.point.data(), near[k][i].data(), d_) != CGAL::SMALLER;
        }
        lap(scan_stage);
      };
      for_each_dart(darts.size(), throw_darts).rethrow();
      // (on threads, the stages from `fragment` to `scan` are not timed apart: all of it as `scan`)
      if(in_parallel(darts.size())) clock.lap(stats.stage_seconds[scan_stage]);
      std::size_t thrown = 0;
      for(const Dart& d : darts) thrown += d.thrown;
      stats.darts += thrown;
      refused_in_a_row = thrown > 0 ? 0 : refused_in_a_row + darts.size();
      if(refused_in_a_row > refusal_limit_)
        throw Invalid_input("the surface model refused " + std::to_string(refused_in_a_row) +
                            " darts in a row: its random_sample() must accept a dart with positive probability");
      accepted.clear();
      for(Dart& d : darts) {
        d.accepted = false;
        d.batch_coverer = none;
        if(!d.thrown || !d.free) continue;
        d.batch_coverer = first_conflict(accepted, d.point);
        if(d.batch_coverer != none) continue;
        if(buckets.size() + accepted.size() >= sample_stop_) {
          stats.stopped = true;
          return stats;
        }
        if(buckets.size() + accepted.size() >= max_points_)
          throw Point_limit_exceeded("more than maximum_number_of_points (" + std::to_string(max_points_) +
                                     ") samples; use a larger radius or raise the bound");
        d.batch_coverer = accepted.size();
        accepted.push_back(d.point);
        d.accepted = true;
        ++stats.samples;
        output(*d.sample);
        if(stats.samples == 1 && first_sample_stop_ && first_sample_stop_(*d.sample)) return stats;
      }
      // nothing reads the buckets again before the next batch: the batch's samples go in together
      clock.lap(stats.stage_seconds[accept_stage]);
      buckets.insert(accepted.data(), accepted.data() + accepted.size());
      clock.lap(stats.stage_seconds[insert_stage]);

      // Each fragment that got a dart leaves the pool; what of it is not covered comes back as
      // children. A fragment drawn twice is handled once.
      auto take = [&](std::size_t k) {
        Dart& d = darts[k];
        d.taken = d.thrown && pool.take(d.handle);
        // The samples that may cover F: the ones near the dart before the batch, and the dart's own
        // sample or the sample of the batch that refused it. (The batch's other samples are rarely
        // near: leaving them out costs 0.7% more darts, and scanning them for every dart more time.)
        if(d.taken && d.batch_coverer != none) {
          near[k].push_back(accepted[d.batch_coverer]);
          around[k].push_back(accepted[d.batch_coverer]);
        }
      };
      // F itself gets the single-ball test only: it is rarely covered by the union when no single
      // ball covers it, and if it is, its children are, and the union test on them drops them (at
      // the depth floor, where it has no children, it gets the union test too)
      auto refine_dart = [&](std::size_t k, std::vector<Fragment>& kids) {
        Dart& d = darts[k];
        kids.clear();
        if(d.taken) d.covered = refine(d.item.fragment, depth_of(d.item), near[k], around[k], kids);
      };
      auto push_children = [&](std::size_t k, const std::vector<Fragment>& kids) {
        const Dart& d = darts[k];
        if(!d.taken) return;
        if(d.covered) {
          stats.darts_on_covered += !d.accepted;
          return;
        }
        const int depth = depth_of(d.item);
        if(depth >= max_depth_) {
          ++stats.dropped_at_max_depth;
          return;
        }
        for(const Fragment& c : kids) {
          const double a = checked_child_area(c);
          if(a > 0) pool.push(make_item(c, depth + 1), a);
        }
        stats.darts_on_covered += !d.accepted && kids.empty();
      };
      if(in_parallel(darts.size())) {
        // the same calls in the same order, but for refine(), which reads only the dart's own data; an
        // exception is the one a sequential run meets first: the children of the darts before the
        // first refine() that threw are pushed, which may throw before it
        for(std::size_t k = 0; k < darts.size(); ++k) take(k);
        const First_error error = for_each_dart(darts.size(), [&](std::size_t first, std::size_t last,
                                                                  Scratch& scratch, bool) {
          for(std::size_t k = first; k < last; ++k) {
            scratch.dart = k;
            refine_dart(k, children[k]);
          }
        });
        const std::size_t pushed = error.exception ? error.dart : darts.size();
        for(std::size_t k = 0; k < pushed; ++k) push_children(k, children[k]);
        error.rethrow();
      } else {
        for(std::size_t k = 0; k < darts.size(); ++k) {
          take(k);
          refine_dart(k, children[0]);
          push_children(k, children[0]);
        }
      }
      clock.lap(stats.stage_seconds[refine_stage]);
      pool.end_batch();
      clock.lap(stats.stage_seconds[end_stage]);
    }
    return stats;
  }

private:
  // a fragment and its number of splits from its root, unless the model keeps that number itself
  template <bool model_keeps_level, class = void>
  struct Item_t
  {
    Fragment fragment;
    unsigned char depth;
  };
  template <class Dummy>
  struct Item_t<true, Dummy>
  {
    Fragment fragment;
  };
  typedef Item_t<Has_level<Traits>::value> Item;

  Item make_item(const Fragment& f, int depth) const
  {
    if constexpr(Has_level<Traits>::value) return Item{f};
    else return Item{f, static_cast<unsigned char>(depth)};
  }
  int depth_of(const Item& item) const
  {
    if constexpr(Has_level<Traits>::value) return int(traits_.level(item.fragment));
    else return item.depth;
  }

  typedef Active_fragment_pool<Item> Pool;

  // the state of a dart through the stages of a batch
  // Every stage sets what the next one reads, but the darts that pass the rejection steps are moved
  // to the front of the batch whole, fields not yet set included: each field has a value from the
  // start (copying an indeterminate bool is undefined, and where `Sample` is not trivially copyable
  // the copy reads each field; resize() constructs darts only when a batch is larger than the last).
  struct Dart
  {
    typename Pool::Handle handle{};
    double u = 0;                   // for the pool's rejection step
    std::uint64_t stream = 0;       // the seed of the dart's own generator
    bool thrown = false;            // passed the rejection steps: a dart
    Item item{};
    std::optional<Sample> sample;
    Point_d point{};
    Neighbor_buckets::Cell cell{};
    const std::vector<Point_d>* bucket = nullptr;
    bool free = false;              // at distance >= D from the samples before the batch
    std::size_t batch_coverer = 0;  // in `accepted`: its own sample or the first within D, else none
    bool accepted = false;
    bool taken = false;             // the first dart of the batch on its fragment
    bool covered = false;           // refine() found its fragment covered
  };

  // Darts per batch, at most. Large enough that a batch's cache misses overlap, small enough that what
  // the batch reads stays in the second-level cache until its last stage.
  static constexpr std::size_t max_batch = 256;

  // How many darts ahead the stages `sample` and `scan` ask again for what the stage before them
  // prefetched for the whole batch. 3 and 6 measured the same for the scan, 12 a little slower;
  // without it, the scan stage takes twice as long, the sample stage a third longer (bench_stages).
  static constexpr std::size_t lookahead = 6;

  void prefetch_fragment(const Fragment& f) const
  {
    if constexpr(Has_prefetch<Traits>::value) traits_.prefetch(f);
    else (void)f;
  }

  static constexpr std::size_t none = std::size_t(-1);

  // What a body of for_each_dart() works with: the scan's scratch (its thread's), and where the body
  // is in the order of a sequential run (its stage, and its first dart or the dart it is at), for
  // the exception that such a run would meet first. Made for each range, on the stack: a thread that
  // waits in a model's own TBB loop may run another range of the engine's meanwhile, which must not
  // overwrite where this one is.
  struct Scratch
  {
    std::vector<std::uint32_t>& hits;
    int stage;
    std::size_t dart;
  };

  // The exception of a parallel loop that comes first in the order of a sequential run, if any
  struct First_error
  {
    std::exception_ptr exception;
    int stage = 0;
    std::size_t dart = 0;
    void rethrow() const
    {
      if(exception) std::rethrow_exception(exception);
    }
  };

  // Calls body(first, last, scratch, timed) on ranges that cover [0, n): the whole of it on this
  // thread, with `timed` true (the stage clock may be read), or, in parallel mode, ranges of at most
  // `grain` darts on TBB's threads, each thread with its own scratch, `timed` false. What the body
  // throws on this thread reaches the caller; on threads, it is returned (see below).
  template <class Body>
  First_error for_each_dart(std::size_t n, Body&& body)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(in_parallel(n)) {
      // In a context of its own, not the caller's: in a context that is cancelled (the caller's
      // tbb::task_group, once another of its tasks has thrown or called cancel()), parallel_for
      // returns at once, without running its body and without throwing, and the batch went on with
      // the darts of the one before (the same samples accepted again and again, for minutes).
      // Each range catches what it throws, and the others go on: the exception returned is the one
      // of the earliest stage, then of the earliest dart, the one a sequential run would throw (the
      // first to be thrown, which TBB would pass on, depends on the threads' timing). Within a
      // range, a stage goes through its darts in order, so that the range's first dart stands for
      // the one that threw, unless the body says which one it is at (`scratch.dart`).
      tbb::task_group_context context(tbb::task_group_context::isolated);
      First_error first;
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, n, grain),
          [&](const tbb::blocked_range<std::size_t>& r) {
            Scratch scratch{scratch_.local(), 0, r.begin()};
            try {
              body(r.begin(), r.end(), scratch, false);
            } catch(...) {
              const std::lock_guard<std::mutex> lock(error_mutex_);
              const auto at = std::make_pair(scratch.stage, scratch.dart);
              if(!first.exception || at < std::make_pair(first.stage, first.dart))
                first = First_error{std::current_exception(), scratch.stage, scratch.dart};
            }
          },
          context);
      return first;
    }
#endif
    Scratch scratch{hits_, 0, 0};
    body(0, n, scratch, true);
    return First_error();
  }
  static constexpr std::size_t grain = 32;

  // whether for_each_dart(n, ...) runs on several threads
  bool in_parallel(std::size_t n) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    return parallel_ && n >= 2 * grain;
#else
    (void)n;
    return false;
#endif
  }

  // the first point of `points` at distance < D from p, decided exactly; `none` if p is free
  std::size_t first_conflict(const std::vector<Point_d>& points, const Point_d& p) const
  {
    const double d2_near = d_ * d_ * (1 + 1e-9);
    for(std::size_t i = 0; i < points.size(); ++i) {
      const Point_d& q = points[i];
      const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
      if(dx * dx + dy * dy + dz * dz <= d2_near && compare_distance_exact(p.data(), q.data(), d_) == CGAL::SMALLER)
        return i;
    }
    return none;
  }

  // appends to `near` and `around` the samples of `bucket` within D (and a few just outside) and
  // within 2D of p. The scan has no branches (which samples are within 2D of a dart is a coin toss
  // for the branch predictor) and writes only the positions of the samples it finds; they are
  // copied after.
  void gather_near(const std::vector<Point_d>& bucket, const Point_d& p, std::vector<Point_d>& near,
                   std::vector<Point_d>& around, std::vector<std::uint32_t>& hits) const
  {
    const std::size_t size = bucket.size();
    if(hits.size() < 2 * size) hits.resize(2 * size);
    std::uint32_t* hit_near = hits.data();
    std::uint32_t* hit_around = hits.data() + size;
    const double d2_near = d_ * d_ * (1 + 1e-9), d2_around = 4 * d2_near;
    std::size_t hn = 0, ha = 0;
    for(std::size_t i = 0; i < size; ++i) {
      const Point_d& q = bucket[i];
      const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      hit_near[hn] = std::uint32_t(i);
      hn += d2 <= d2_near;
      hit_around[ha] = std::uint32_t(i);
      ha += d2 <= d2_around;
    }
    // room for exactly these and the one sample take() may add: the vectors are kept from batch to
    // batch, and grown by doubling they took a tenth of the sampler's memory at 10,000 points
    if(near.capacity() < near.size() + hn + 1) near.reserve(near.size() + hn + 1);
    if(around.capacity() < around.size() + ha + 1) around.reserve(around.size() + ha + 1);
    for(std::size_t i = 0; i < hn; ++i) near.push_back(bucket[hit_near[i]]);
    for(std::size_t i = 0; i < ha; ++i) around.push_back(bucket[hit_around[i]]);
  }

  // True if one point of `near` covers f. Otherwise, unless f is at the depth floor, writes the
  // children of f that neither one point of `near` nor the union of the balls around `around` covers.
  bool refine(const Fragment& f, int depth, const std::vector<Point_d>& near, const std::vector<Point_d>& around,
              std::vector<Fragment>& children) const
  {
    if constexpr(Has_refine<Traits>::value) {
      if(depth < max_depth_) return traits_.refine(f, near, around, d_, std::back_inserter(children));
    }
    if(is_covered_by_any(f, near)) return true;
    // at the floor, the union test too: a fragment is counted as dropped only if no test proves it
    // covered (its children would get the union test; it has none)
    if(depth >= max_depth_) return is_covered_by_union(f, around);
    traits_.split(f, std::back_inserter(children));
    std::size_t kept = 0;
    for(const Fragment& c : children)
      if(checked_child_area(c) > 0 && !is_covered_by_any(c, near) && !is_covered_by_union(c, around))
        children[kept++] = c;
    children.erase(children.begin() + std::ptrdiff_t(kept), children.end());
    return false;
  }

  // The area of a fragment of the model, refused unless it is a number and not negative: a NaN was
  // dropped unsaid (a gap), or read as "no part of positive area", and a child of area 0 or less
  // from refine() stopped the pool at its precondition, or, without assertions, never returned.
  double checked_area(const Fragment& f) const { return internal::checked_area(traits_, f); }

  // A fragment is filed by its area when it is pushed, and drawn in proportion to the bounds of its
  // bin: an area that has left them since would be drawn as often as one it no longer is.
  [[noreturn]] void refuse_changed_area(double area, std::pair<double, double> range) const
  {
    const std::string upper = number_text(std::isinf(range.second) ? max_child_area_ : range.second) + "]";
    throw Invalid_input("the surface model gave a fragment of area " + number_text(area) +
                        " when it was drawn, outside the range (" + number_text(range.first) + ", " + upper +
                        " of the area it gave when the fragment was stored: area() must return the same "
                        "double for the same fragment on every call");
  }

  // A sample that is not finite, or so far from the origin that doubles there are coarser than about a
  // thousandth of D: the neighbour buckets widen their reach by 10^-15 of the coordinates, beyond D
  // here, and each sample went into thousands of buckets (a square at 10^18 whose position_error()
  // said 10^-15, at D = 1: 3.8 GB for 228 samples). A model whose position_error() bounds its points'
  // rounding (at least 2^-53 of their coordinates) never gets here: the distance is refused first,
  // below 2^20 of it.
  [[noreturn]] void refuse_sample_at(const Point_d& p) const
  {
    const std::string sample = "the surface model gave a sample at (" + number_text(p[0]) + ", " +
                               number_text(p[1]) + ", " + number_text(p[2]) + ")";
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Invalid_input(sample + ": its coordinates must be finite numbers");
    throw Invalid_input(sample + ", more than 10^15 times the minimum distance (" +
                        number_text(d_) + ") from the origin, where doubles are too coarse for it: its "
                        "position_error() (" + number_text(traits_.position_error()) +
                        ") must bound the rounding of its points");
  }

  // checked_area(), and at most the largest root's area (up to rounding): see run()
  double checked_child_area(const Fragment& f) const
  {
    const double a = checked_area(f);
    if(a > max_child_area_)
      throw Invalid_input("the surface model gave a child fragment of area " + number_text(a) +
                          ", above the largest initial fragment's (" + number_text(max_child_area_) +
                          "); a model that samples with rejection must keep its areas' bounds below it");
    return a;
  }

  bool is_covered_by_any(const Fragment& f, const std::vector<Point_d>& centers) const
  {
    for(const Point_d& c : centers)
      if(traits_.is_covered(f, c, d_)) return true;
    return false;
  }

  bool is_covered_by_union(const Fragment& f, const std::vector<Point_d>& centers) const
  {
    if constexpr(Has_union_coverage<Traits>::value) return traits_.is_covered_by_union(f, centers, d_);
    else return false;
  }

  const Traits& traits_;
  std::vector<std::uint32_t> hits_; // scratch of gather_near() on this thread
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<std::vector<std::uint32_t>> scratch_; // on TBB's threads
  std::mutex error_mutex_;
#endif
  bool parallel_ = false;
  double d_;
  std::uint64_t seed_;
  std::size_t max_points_;
  int max_depth_;
  bool check_expected_count_ = true;
  double max_child_area_ = 0; // set by run()
  double coordinate_limit_;    // of a sample's coordinates, see refuse_sample_at()
  std::uint64_t refusal_limit_ = std::uint64_t(1) << 30;
  std::size_t sample_stop_ = std::size_t(-1);
  std::function<bool(const Sample&)> first_sample_stop_;
};

} // inline namespace CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT

#undef CGAL_POISSON_DISK_SAMPLING_3_ENGINE_VARIANT

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_DART_THROWING_ENGINE_H
