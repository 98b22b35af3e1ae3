// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_SURFACE_H
#define CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_SURFACE_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/parameters.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Dart_throwing_engine.h>
#include <CGAL/Poisson_disk_sampling_3/internal/count_estimate.h>
#include <CGAL/Poisson_disk_sampling_3/internal/exact_distance.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/representation_tags.h>
#include <CGAL/tags.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {

// CGAL's exact binary floating-point number types, named by number_holds_doubles() below (declared
// only: their headers need not be included)
class MP_Float;
class Gmpzf;
struct Mpzf;

namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Ref
/// What a sampling call did; filled when passed as `statistics(std::ref(s))`. Each call first sets
/// it to zero: after an exception thrown before a run starts (bad input, a request refused up front),
/// it stays zero. After an exception thrown by a run (`Point_limit_exceeded` while sampling,
/// `Invalid_input` for a model that breaks the concept's rules, or in a radius request for a surface
/// with no area), `minimum_distance`, `random_seed` and `number_of_runs` are those of the run that
/// threw, `stopped_runs` those stopped before it, and the other members those of the run before it
/// in a `number_of_points` search (zero otherwise); after an exception for a later distance of the
/// search (`Invalid_input`, `Point_limit_exceeded`), those of its last run; after
/// `Target_not_reached`, those of the search's last run, with `number_of_runs` and `stopped_runs`
/// counting all its runs.
struct Sampling_statistics
{
  double minimum_distance = 0;       ///< the minimum distance used (the one found, for `number_of_points`)
  /// the seed of the run whose points were written: `random_seed`, or for a `number_of_points`
  /// search whose last runs drew their darts from seeds derived from it (small targets), that run's;
  /// the radius mode at `minimum_distance` with this seed gives the same points
  std::uint64_t random_seed = 0;
  /// dart-throwing runs: 1, or the search's runs for `number_of_points`, among which `stopped_runs`
  std::size_t number_of_runs = 0;
  /// runs of a `number_of_points` search for N points stopped at 2N + 64 samples, or at
  /// `maximum_number_of_points` if lower (a run at a distance far too small): each costs about as much
  /// as a run of 2N points
  std::size_t stopped_runs = 0;
  std::size_t darts = 0;             ///< darts thrown by the last run
  std::size_t dropped_fragments = 0; ///< fragments dropped uncovered at the depth floor by the last run (normally 0)
  /// darts of the last run that landed on a fragment found entirely covered, by samples accepted
  /// after the fragment was made: a dart is how the engine finds out (about half of all darts)
  std::size_t darts_on_covered_fragments = 0;
  /// the most fragments active at the start of a batch of darts in the last run: about what the
  /// engine's pool of fragments holds at its largest (for triangles, 32 bytes each), which a batch
  /// exceeds by the children of its darts (at most 256 darts; four children a dart at most for a piece
  /// of a triangle, one a cell one level down for a cluster of small faces, or one a face where its
  /// faces' centroids share one cell of the finest level), until the fragments they came from leave
  /// the pool
  std::size_t peak_active_fragments = 0;
};

namespace internal {

/// the size of a request: a minimum distance, or a number of points to reach
struct Size_request
{
  double minimum_distance = 0; // > 0 when the distance is given
  std::size_t number_of_points = 0; // > 0 when a count is given
  double count_given = 0; // the count as given, which may exceed the largest size_t
};

/// Whether a number type holds every double exactly: a field no narrower than double (double, or
/// exact rationals as in `Epeck`), or one of CGAL's exact binary floating-point types.
template <class NT>
constexpr bool number_holds_doubles()
{
  return (std::is_convertible<typename CGAL::Algebraic_structure_traits<NT>::Algebraic_category,
                              CGAL::Field_tag>::value &&
          !(std::is_floating_point<NT>::value && sizeof(NT) < sizeof(double))) ||
         std::is_same<NT, CGAL::MP_Float>::value || std::is_same<NT, CGAL::Gmpzf>::value ||
         std::is_same<NT, CGAL::Mpzf>::value;
}

template <class Kernel, class = void>
struct Is_homogeneous : std::false_type
{};
template <class Kernel>
struct Is_homogeneous<Kernel, std::void_t<typename Kernel::Kernel_tag>>
    : std::is_same<typename Kernel::Kernel_tag, CGAL::Homogeneous_tag>
{};

/// Whether the points and numbers of `Kernel` hold the samples' doubles exactly. The samples are
/// computed and checked in double; narrower coordinates (`float`) would round them, and integers
/// (`int`, `Gmpz`, or a homogeneous kernel on them, whose points are made from integers) truncate
/// them, silently: two samples could end up closer than the minimum distance, off the surface. Such
/// kernels are refused when the program is compiled. A homogeneous kernel is tested on its `RT`,
/// from which points are made (w = 1), a Cartesian one on its `FT`.
template <class Kernel>
constexpr bool holds_doubles()
{
  if constexpr(Is_homogeneous<Kernel>::value) return number_holds_doubles<typename Kernel::RT>();
  else return number_holds_doubles<typename Kernel::FT>();
}

/// A sample's point as the caller's point type (see `holds_doubles()`).
template <class Point_3>
Point_3 output_point(const std::array<double, 3>& p)
{
  static_assert(holds_doubles<typename CGAL::Kernel_traits<Point_3>::Kernel>(),
                "Poisson_disk_sampling_3: the samples are doubles; a point type on float would round them, "
                "and one on integers (int, Gmpz, a homogeneous kernel on them) truncate them, and break the "
                "minimum distance: use a kernel on double or exact rationals (Epick, Epeck)");
  return Point_3(p[0], p[1], p[2]);
}

/// a count given as a double >= 1, as a size_t: values from the largest size_t up (which rounds up
/// to 2^64 as a double, where the conversion is undefined) become the largest size_t
inline std::size_t to_size(double n)
{
  const std::size_t largest = (std::numeric_limits<std::size_t>::max)();
  return n < double(largest) ? std::size_t(n) : largest;
}

/// how many times a chain of named parameters gives the parameter of tag `Query`
template <class NamedParameters, class Query>
struct Times_given : std::integral_constant<int, 0>
{};
template <class T, class Tag, class Base, class Query>
struct Times_given<CGAL::Named_function_parameters<T, Tag, Base>, Query>
  : std::integral_constant<int, int(std::is_same<Tag, Query>::value) + Times_given<Base, Query>::value>
{};
template <class T, class Tag, class Base, class Query>
struct Times_given<parameters::Named_parameters<T, Tag, Base>, Query>
  : Times_given<CGAL::Named_function_parameters<T, Tag, Base>, Query>
{};

/// refuses a chain that gives the parameter of tag `Tag`, called `name`, more than once
template <class NamedParameters, class Tag>
void check_once(const char* name)
{
  if(Times_given<NamedParameters, Tag>::value > 1) throw Invalid_input(std::string(name) + " is given more than once");
}

/// Refuses a chain that gives one of the parameters the samplers read more than once
/// (`radius(0.1).radius(0.05)`): CGAL would read one of the two and drop the other unsaid.
template <class NamedParameters>
void check_given_once()
{
  check_once<NamedParameters, internal_np::radius_t>("radius");
  check_once<NamedParameters, internal_np::minimum_distance_t>("minimum_distance");
  check_once<NamedParameters, internal_np::number_of_points_t>("number_of_points");
  check_once<NamedParameters, internal_np::maximum_number_of_points_t>("maximum_number_of_points");
  check_once<NamedParameters, internal_np::statistics_t>("statistics");
  check_once<NamedParameters, internal_np::concurrency_t>("concurrency");
  check_once<NamedParameters, CGAL::internal_np::random_seed_t>("random_seed");
  check_once<NamedParameters, CGAL::internal_np::vertex_point_t>("vertex_point_map");
  check_once<NamedParameters, CGAL::internal_np::geom_traits_t>("geom_traits");
}

template <class NamedParameters>
Size_request read_size(const NamedParameters& np)
{
  check_given_once<NamedParameters>();
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  constexpr bool has_r = !is_default_parameter<NamedParameters, internal_np::radius_t>::value;
  constexpr bool has_d = !is_default_parameter<NamedParameters, internal_np::minimum_distance_t>::value;
  constexpr bool has_n = !is_default_parameter<NamedParameters, internal_np::number_of_points_t>::value;
  if(int(has_r) + int(has_d) + int(has_n) != 1)
    throw Invalid_input("give exactly one of radius(r), minimum_distance(2r) and number_of_points(n)");
  Size_request s;
  if(has_r || has_d) {
    const double r = choose_parameter(get_parameter(np, internal_np::radius), 0.);
    const double d = has_r ? 2 * r : double(choose_parameter(get_parameter(np, internal_np::minimum_distance), 0.));
    if(has_r && r > 0 && std::isfinite(r) && !std::isfinite(d))
      throw Invalid_input("the radius " + number_text(r) + " is too large: the minimum distance 2r overflows");
    if(!(d > 0) || !std::isfinite(d))
      throw Invalid_input(std::string(has_r ? "the radius" : "the minimum distance") + " must be positive and finite");
    s.minimum_distance = d;
  } else {
    const double n = double(choose_parameter(get_parameter(np, internal_np::number_of_points), 0));
    if(!(n >= 1)) throw Invalid_input("number_of_points must be at least 1");
    if(!std::isfinite(n)) throw Invalid_input("number_of_points must be finite");
    if(n != std::floor(n)) throw Invalid_input("number_of_points must be a whole number");
    s.number_of_points = to_size(n);
    s.count_given = n;
  }
  return s;
}

/// the `random_seed` parameter: an integer from 0 to 2^64 - 1 (a negative one is refused: converted,
/// -1 would be the same seed as 2^64 - 1; a floating-point one does not compile, rather than lose its
/// fraction)
template <class NamedParameters>
std::uint64_t read_seed(const NamedParameters& np)
{
  const auto seed = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::random_seed), 0u);
  typedef std::decay_t<decltype(seed)> Seed;
  static_assert(std::is_integral<Seed>::value && !std::is_same<Seed, bool>::value,
                "random_seed takes an integer from 0 to 2^64 - 1");
  if constexpr(std::is_signed<Seed>::value)
    if(seed < 0) throw Invalid_input("random_seed must not be negative (" + std::to_string(seed) + ")");
  return std::uint64_t(seed);
}

template <class NamedParameters>
std::size_t read_max_points(const NamedParameters& np)
{
  const double m = double(CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::maximum_number_of_points), 100000000.));
  if(!(m >= 1)) throw Invalid_input("maximum_number_of_points must be at least 1");
  if(!std::isfinite(m)) throw Invalid_input("maximum_number_of_points must be finite");
  if(m != std::floor(m)) throw Invalid_input("maximum_number_of_points must be a whole number");
  return to_size(m);
}

/// whether the `concurrency` parameter asks for TBB's threads: `CGAL::Parallel_tag` (a compilation
/// error without TBB), `CGAL::Parallel_if_available_tag` (TBB's threads where CGAL is linked with it),
/// `CGAL::Sequential_tag` (the default)
template <class NamedParameters>
constexpr bool read_parallel()
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::concurrency_t, NamedParameters,
                                                              CGAL::Sequential_tag>::type Tag;
  static_assert(std::is_same<Tag, CGAL::Sequential_tag>::value || std::is_same<Tag, CGAL::Parallel_tag>::value,
                "concurrency takes CGAL::Sequential_tag, CGAL::Parallel_tag or CGAL::Parallel_if_available_tag");
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_same<Tag, CGAL::Parallel_tag>::value,
                "concurrency(CGAL::Parallel_tag()) needs TBB: link CGAL::TBB_support, or pass "
                "CGAL::Parallel_if_available_tag()");
#endif
  return std::is_same<Tag, CGAL::Parallel_tag>::value;
}

/// Whether one sample covers the whole surface at a minimum distance: `holds_surface(sample, d)`;
/// empty where no sample is ever taken to (the engine then proves coverage itself).
template <class Traits>
using Holds_surface = std::function<bool(const typename Traits::Sample&, double)>;

/// one dart-throwing run; `emit(sample)` is called for each sample as it is accepted. With
/// `check_expected_count` false, the run does not refuse the distance up front (see
/// `Dart_throwing_engine::set_expected_count_check()`). Returns false if the run stopped at
/// `sample_stop` samples, not maximal (see `Dart_throwing_engine::set_sample_stop()`). Where
/// `holds_surface(sample, d)` is true of its first sample, the run returns after it (see
/// `Dart_throwing_engine::set_first_sample_stop()`).
template <class Traits, class Emit>
bool run_engine(const Traits& traits, double d, std::uint64_t seed, std::size_t max_points, bool parallel,
                Sampling_statistics& stats, Emit&& emit, bool check_expected_count = true,
                std::size_t sample_stop = std::size_t(-1), const Holds_surface<Traits>& holds_surface = {})
{
  Dart_throwing_engine<Traits> engine(traits, d, seed, max_points);
  engine.set_expected_count_check(check_expected_count);
  engine.set_parallel(parallel);
  engine.set_sample_stop(sample_stop);
  if(holds_surface)
    engine.set_first_sample_stop([&holds_surface, d](const typename Traits::Sample& s) { return holds_surface(s, d); });
  // filled first: a run that throws (Point_limit_exceeded) leaves its distance and the runs counted
  stats.minimum_distance = d;
  stats.random_seed = seed;
  ++stats.number_of_runs;
  const Engine_statistics e = engine.run(emit);
  stats.darts = e.darts;
  stats.dropped_fragments = e.dropped_at_max_depth;
  stats.darts_on_covered_fragments = e.darts_on_covered;
  stats.peak_active_fragments = e.peak_active;
  return !e.stopped;
}

/// Finds a minimum distance whose maximal set has `n` points within max(1%, 1 point). A first run uses the jamming
/// density of maximal Poisson-disk sets in the plane (about 0.6965 area / d^2 points), unless random points on the
/// surface say that a ball holds far less than pi d^2 of it there (`Count_model::first_distance()`); later runs
/// correct d with the slope of log(count) over log(d) measured between runs (until two complete runs measure one,
/// the slope of the random points' model, `Count_model::slope()`), and bisect the bracket of distances that gave
/// too many and too few points when a step would leave it or the bracket stops shrinking. Once the bracket is
/// narrower than the count's spread from run to run (small targets), the runs draw their darts from other seeds,
/// derived from `seed`, at a distance that follows their mean count. One to three full runs, more for small targets
/// and where the first distance is far off (runs stopped at 2n + 64 points). Runs return after their first sample
/// where `holds_surface` says it covers the surface, as in `sample_request()`. Each run keeps its samples in a
/// deque, whose blocks hold about its samples and no more (a vector grown by doubling held up to three times as
/// many while it moved), and only the run that meets the target keeps them past its end (the closer runs before it
/// are counted, not kept).
template <class Traits>
std::deque<typename Traits::Sample> run_for_count(const Traits& traits, std::size_t n, std::uint64_t seed,
                                                  std::size_t max_points, bool parallel, Sampling_statistics& stats,
                                                  const Holds_surface<Traits>& holds_surface)
{
  CGAL_precondition(n <= max_points); // refused by sample_request()
  const double area = total_area(traits);
  check_surface_area(area, "sample");
  const double tolerance = (std::max)(1., 0.01 * double(n));
  // (the square roots apart, so that the area of a tiny surface does not underflow in the product)
  const double planar = std::sqrt(0.6965 / double(n)) * std::sqrt(area);
  double slope = -2, last_d = 0, last_n = 0;
  bool measured = false; // whether `slope` was measured between two complete runs
  const double infinity = std::numeric_limits<double>::infinity();
  // The smallest distance the runs may take: check_distance_range(), check_distance_precision(), and
  // the distance at which area / (pi r^2) is four times the bound, and 64. The runs are not refused
  // by that estimate, as a radius request is: on a flat surface it is about 1.8 times the count, and
  // a target at the bound would be refused. But beyond four times the bound, the surface's faces
  // overlap or lie closer than d to each other (copies, folds): each counts in the area, and a run
  // takes the time and memory of that many points (2,000 copies of a triangle held 900,000 fragments
  // in wait to give 1,000 points under a bound of 5,000).
  const double precise = (std::max)(smallest_minimum_distance,
                                    std::nextafter(0x1.0p20 * traits.position_error(), infinity));
  // (disk_count(area, d) is disk_count(1, 1) area / d^2)
  const double bounded = std::sqrt(area / (4 * double(max_points) + 64)) * std::sqrt(disk_count(1, 1));
  const double lowest = (std::max)(precise, bounded);
  // the plane's distance for n points on the surface's area, unless random points on the surface say
  // it is far too small (strips far narrower than it), and the slope of the first step: see
  // Count_model (none below 100 points, where runs are cheap, nor below the smallest distance)
  Count_model model = count_model(traits, area, n, planar, lowest, seed ^ 0x3b8f0e6d2a41c957ull);
  double d = model.first_distance(planar);
  double too_many = 0, too_few = infinity;
  std::size_t complete_runs = 0, closest = 0; // the count of the complete run closest to n
  // A run stops at `stop` samples, about twice the target, or at the bound: where the first distance
  // assumed that a sample covers about pi r^2 of the surface, as in the plane, on strips far
  // narrower than d, where it covers far less, the first run made 1,267 times the target (12.7
  // million points and 3.6 GB for 10,000 on 2,000 strips 10^-7 wide) and could exhaust the memory
  // or the bound where a larger distance reaches the target. The random points now see that, but
  // their estimate is not a bound (and below 100 points the plane's is kept).
  const std::size_t stop =
      n <= (std::numeric_limits<std::size_t>::max() - 64) / 2 ? (std::min)(max_points, 2 * n + 64) : max_points;
  std::size_t stopped_runs = 0;
  // the bracket's width (in log d) when it last halved, and the steps since (see below)
  double reference_width = infinity;
  int slow_steps = 0;
  // The count of a maximal set varies from one seed to the next by about 0.25 sqrt(n) (elephant.off
  // at 100, 1,000 and 10,000 points: benchmark/README.md, change 48), about 0.125 / sqrt(n) in log d
  // where the count goes as d^-2; below about 600 points that is more than the tolerance. A bracket
  // narrower than that no longer tells where the target lies: the count at one seed jumps between
  // a few values as d changes, and the bisection settled where it jumps over the target
  // (elephant.off, seeds 350 and 427 for 100 points). From then on, each run draws another seed
  // (from `reseeds`, derived from `seed`, so the result stays reproducible) at `noise_center`, moved
  // after each run towards the target by a step that shrinks as the runs accumulate (a running mean
  // of their counts).
  const double noise_width = 0.125 / std::sqrt(double(n));
  double noise_center = 0;
  int noise_runs = 0;
  Stream reseeds(seed ^ 0x6c8e9cf570932bd5ull);
  std::uint64_t run_seed = seed;
  // Up to 24 runs: near the target a run is a draw of a count that varies by a few points from one
  // distance to the next, and for 150 points only 149 to 151 are within tolerance. Large targets
  // take one to three runs (their tolerance is wide) where the first distance is about right;
  // small ones, that may need more, are cheap.
  for(int run = 0; run < 24; ++run) {
    // A distance below the smallest the runs may take is brought up to it, unless a run there already
    // gave too few or too many points: a count that the smallest distance gives is then reached (one
    // point on a triangle 10^-3 wide, 10^6 from the origin, whose estimate is below the precision).
    if(d < lowest && too_many < lowest && too_few > lowest) d = lowest;
    // Each distance is checked here, named as the search's: the engine would name it as if the user
    // had given it. Where a run gave too few points, the next one may need a distance below the
    // precision (two copies of a triangle far from the origin, each point counted twice).
    const std::string tried =
        run == 0 ? "about " + std::to_string(n) + " points on a surface of area " + number_text(area) +
                       " need a minimum distance of about " + number_text(d) + ", which"
                 : "the search for " + std::to_string(n) + " points needs a minimum distance of about " +
                       number_text(d) + ", which";
    check_distance_range(d, tried);
    check_distance_precision(d, traits.position_error(), tried);
    if(d < bounded) {
      const double expected = disk_count(area, d);
      throw Point_limit_exceeded(tried + " makes area / (pi r^2), about " + number_text(expected) +
                                 " points, exceed four times maximum_number_of_points (" +
                                 std::to_string(max_points) + "): faces that overlap, or lie closer to each other "
                                 "than that distance (copies, folds), each count in the area that a run's time "
                                 "and memory follow; raise the bound");
    }
    std::deque<typename Traits::Sample> samples;
    const bool complete = run_engine(
        traits, d, run_seed, max_points, parallel, stats,
        [&](const typename Traits::Sample& s) { samples.push_back(s); }, false, stop, holds_surface);
    // a stopped run made more than `stop` points, at least 5% more than n (`stop` is at least n; with
    // a bound at n, taking `stop` would leave the distance of the runs below where it is)
    const double got = complete ? double(samples.size()) : (std::max)(double(stop), 1.05 * double(n));
    if(complete) {
      if(complete_runs++ == 0 || std::abs(got - double(n)) < std::abs(double(closest) - double(n)))
        closest = samples.size();
      // within the tolerance: this run's samples; `stats` holds its statistics and counts the runs
      if(std::abs(got - double(n)) <= tolerance) return samples;
      // the bracket: the largest distance that gave too many points, the smallest that gave too few
      if(got > double(n)) too_many = (std::max)(too_many, d);
      else too_few = (std::min)(too_few, d);
      if(last_n > 0 && got != last_n && d != last_d) {
        const double s = (std::log(got) - std::log(last_n)) / (std::log(d) - std::log(last_d));
        // (within [-3, -1], as before the model's slope, which may reach -4, was taken for the first step)
        slope = (std::min)(-1., (std::max)(-3., s));
        if(!measured) model = Count_model(); // (its points are no longer needed)
        measured = true;
      } else if(!measured) {
        slope = model.slope(d, got, double(n)); // none measured yet: the model's
      }
      last_d = d;
      last_n = got;
      d *= std::pow(double(n) / got, 1 / slope);
    } else {
      // more than `stop` points, by a factor unknown: the step of the gentlest slope, -1, for `stop`
      // points (twice as large, or more, unless the bound stopped the run), and at least 5%
      ++stopped_runs;
      stats.stopped_runs = stopped_runs;
      too_many = (std::max)(too_many, d);
      last_n = 0;
      d *= (std::max)(double(stop) / double(n), 1.05);
    }
    if(noise_center > 0) {
      ++noise_runs;
      noise_center *= std::pow(got / double(n), 1 / (2. * noise_runs));
      d = noise_center;
      run_seed = reseeds.next();
    } else if(too_many > 0 && too_few < infinity) {
      // The count is not a monotone function of d (each d draws other darts): near the target,
      // steps from the slope can swing between counts on either side. Once the target is
      // bracketed, a step that leaves the bracket bisects it instead, and so does the step after
      // two that have not halved the bracket's width (as in Brent's method): a step that lands
      // near one end is often right, where that end is close to the target and the other one far
      // (a run stopped at a distance twice too small). The width is at most 0 where a larger
      // distance gave more points than a smaller one.
      const double width = std::log(too_few / too_many);
      if(width < 2 * noise_width) {
        noise_center = d = std::sqrt(too_many * too_few);
        run_seed = reseeds.next();
      } else {
        if(width <= 0.51 * reference_width) {
          slow_steps = 0;
          reference_width = width;
        } else {
          ++slow_steps;
        }
        const double t = std::log(d / too_many) / width;
        if(!(t > 0 && t < 1) || slow_steps >= 2) {
          d = std::sqrt(too_many * too_few);
          slow_steps = 0;
          reference_width = width;
        }
      }
    }
  }
  if(complete_runs == 0)
    throw Target_not_reached("no minimum distance gave " + std::to_string(n) + " points: every run of the search "
                             "made more than " + std::to_string(stop) + (stop == max_points ?
                             " (maximum_number_of_points)" : " (twice the target and 64)") + " and was stopped");
  throw Target_not_reached("no minimum distance gave " + std::to_string(n) + " points within " +
                           number_text(tolerance) + " (1% of them, at least one); the closest had " +
                           std::to_string(closest) + (stopped_runs > 0 ? "; runs stopped at " +
                           std::to_string(stop) + " points: " + std::to_string(stopped_runs) : std::string()) +
                           ". The count jumps by a few points from one distance to the next: another random_seed "
                           "may reach it");
}

/// Resets the `statistics` parameter and returns it, or `local` where it is not given. Each sampling
/// function does this first, so that an exception thrown before its first run leaves the caller's
/// object zero, not holding an earlier call's values.
template <class NamedParameters>
Sampling_statistics& clear_statistics(const NamedParameters& np, Sampling_statistics& local)
{
  Sampling_statistics& stats = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter_reference(np, internal_np::statistics), local);
  stats = Sampling_statistics();
  return stats;
}

/// Runs a size request and calls `emit(sample)` for each sample; fills `stats`, the `statistics`
/// parameter or a local object, which the caller has cleared (`clear_statistics()`). A radius request
/// streams the samples as they are accepted (no copy of the set is kept); a `number_of_points` request
/// keeps each run's samples until the run ends, and the last run's until they are emitted. A run
/// whose first sample `holds_surface(sample, d)` says covers the whole surface at its distance d
/// (where the coverage tests may not prove it: a sphere at its diameter or more) returns after it
/// (see `Dart_throwing_engine::set_first_sample_stop()`).
template <class Traits, class NamedParameters, class Emit>
void sample_request(const Traits& traits, const NamedParameters& np, Sampling_statistics& stats, Emit&& emit,
                    const Holds_surface<Traits>& holds_surface = {})
{
  const Size_request size = read_size(np);
  const std::uint64_t seed = read_seed(np);
  const std::size_t max_points = read_max_points(np);
  constexpr bool parallel = read_parallel<NamedParameters>();
  if(size.number_of_points > 0) {
    if(size.count_given > double(max_points)) // as given: it may be above the largest size_t
      throw Point_limit_exceeded("number_of_points (" + (size.count_given < 0x1.0p64 ?
                                 std::to_string(std::uint64_t(size.count_given)) : number_text(size.count_given)) +
                                 ") exceeds maximum_number_of_points (" + std::to_string(max_points) + ")");
    for(const auto& s : run_for_count(traits, size.number_of_points, seed, max_points, parallel, stats,
                                      holds_surface))
      emit(s);
    return;
  }
  run_engine(traits, size.minimum_distance, seed, max_points, parallel, stats, emit, true, std::size_t(-1),
             holds_surface);
}

} // namespace internal

/// \ingroup PkgPoissonDiskSampling3Ref
/// Generates a maximal Poisson-disk sample set on the surface described by `traits`, by the optimized
/// dart throwing of the paper's Section 3. Every other sampling function of the package is a facade
/// over this one (but `sample_sphere()` at a distance of its diameter or more stops after the first
/// sample where that sample's ball holds the sphere, where this function, with the sphere's model,
/// runs in full: see there).
///
/// @tparam SurfaceFragmentTraits a model of `SurfaceFragmentTraits_3`
/// @tparam SampleOutputIterator an output iterator accepting `SurfaceFragmentTraits::Sample`
/// @tparam NamedParameters a sequence of named parameters
///
/// @param traits the surface
/// @param out where the samples are written, in the order they were accepted
/// @param np the size of the request (exactly one of `radius`, `minimum_distance`, `number_of_points`)
///        and options, among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{radius}
///     \cgalParamDescription{the disk radius r: two samples are at least 2r apart, and every point of
///       the surface is within 2r of a sample; 2r from 2^-400 to 2^400}
///     \cgalParamType{double}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_distance}
///     \cgalParamDescription{the minimum distance 2r between two samples, the same request as `radius(r)`}
///     \cgalParamType{double}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_points}
///     \cgalParamDescription{a target count N: the function searches the minimum distance whose maximal set has
///       N points within 1% (at least one point). Its first run takes the plane's density (about 0.6965 area /
///       d^2 points) or, where random points on the surface say that a ball holds far less than pi r^2 of it
///       (strips much narrower than the distance), a distance from them, whose count was 12% too few to 30% too
///       many on the strips measured. The search takes one to three full runs where that distance is about
///       right, more for
///       small targets; two or three where the count does not go as d^-2 (sheets stacked closer than the
///       distance), whose first step takes the slope that the random points give. A run stops at 2N + 64 points or the
///       bound, so that the samples held stay at most 2N + 64 (one run's: no earlier run's are kept). The
///       runs' fragments, time and memory follow area / (pi r^2), as in a radius request: about 1.8 N on a flat
///       surface, far less on strips narrower than r, many times N where faces overlap or lie closer than r
///       (copies of a face each count). The search tries no distance at which it exceeds four times
///       `maximum_number_of_points`, and 64, and refuses a target that needs one}
///     \cgalParamType{std::size_t}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number_of_points}
///     \cgalParamDescription{refuse (throw `Point_limit_exceeded`) a radius request whose area / (pi r^2)
///       exceeds it, or a `number_of_points` above it, before any large allocation (and a
///       `number_of_points` target that needs a distance at which area / (pi r^2) exceeds four times
///       it, and 64); the number of samples accepted never exceeds it either. The roots a model writes
///       for the distance (its optional `initial_fragments(out, d)`) may outnumber its faces by at most
///       four times the bound plus six per face (`Triangle_fragment_traits_3` writes at most two per
///       face). A bound of 2^64 or more, given as a floating-point number, is taken as the largest
///       `std::size_t`. The bound is a guard against requests far beyond the machine, not a memory limit.}
///     \cgalParamType{std::size_t}
///     \cgalParamDefault{100 million}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives what the call did, among which the minimum distance it used}
///     \cgalParamType{`std::reference_wrapper<Sampling_statistics>` (pass `std::ref(s)`)}
///     \cgalParamDefault{not filled}
///   \cgalParamNEnd
///   \cgalParamNBegin{concurrency}
///     \cgalParamDescription{`CGAL::Parallel_tag()` throws each batch of darts and refines their fragments
///       on TBB's threads (the program links `CGAL::TBB_support`; without TBB, a compilation error);
///       `CGAL::Parallel_if_available_tag()` does so where CGAL is linked with TBB. The samples are the
///       sequential run's, in the same order, whatever the number of threads: each dart draws from a
///       generator of its own, and the darts are judged and their children stored in order.}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{the seed: the same seed and input give the same samples}
///     \cgalParamType{an integer type, from 0 to 2^64 - 1 (a negative value is refused)}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the output iterator past the last sample
/// \throws Invalid_input for a bad size (among which a minimum distance outside 2^-400 to 2^400), a
///         negative seed or a surface with no area, before any sample is written; and while sampling,
///         for a model that breaks the rules of `SurfaceFragmentTraits_3` the engine checks (an area
///         that is not a number or negative, a fragment larger than the largest initial one, an area
///         that changed between the calls of `area()`, more than 2^30 draws in a row without a
///         dart), after which `out` may have received some samples.
/// \throws Point_limit_exceeded when the bound is exceeded: before any sample is written for the
///         estimate, while sampling a radius request for the actual count (a surface that needs more
///         samples than its area predicts) and for a model whose fragments in wait outnumber the bound of
///         `SurfaceFragmentTraits_3`, after which `out` may have received some samples.
/// \throws Target_not_reached when `number_of_points` cannot be met (also when every run of its search
///         is stopped, at 2N + 64 points or at `maximum_number_of_points`); `statistics` then holds
///         the last run's
template <class SurfaceFragmentTraits, class SampleOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
SampleOutputIterator sample_surface(const SurfaceFragmentTraits& traits, SampleOutputIterator out,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  Sampling_statistics local; // (if not given)
  Sampling_statistics& stats = internal::clear_statistics(np, local);
  internal::sample_request(traits, np, stats, [&](const typename SurfaceFragmentTraits::Sample& s) { *out++ = s; });
  return out;
}

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_SURFACE_H
