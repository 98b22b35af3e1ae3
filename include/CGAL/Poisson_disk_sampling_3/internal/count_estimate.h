// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COUNT_ESTIMATE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COUNT_ESTIMATE_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Point_hash_grid.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>
#include <CGAL/Poisson_disk_sampling_3/internal/optional_operations.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// `m` points drawn uniformly by area on the surface of `traits` (the sum of the areas of its
/// `initial_fragments(out)`, `area`), as x, y, z in a row: the roots are made once, not stored, and
/// the points fall in them in the order of `m` sorted uniform positions along the roots' areas. A
/// point whose `random_sample()` refuses 64 darts in a row is left out.
template <class Traits>
std::vector<double> random_surface_points(const Traits& traits, double area, std::size_t m, std::uint64_t seed)
{
  Random rng(seed);
  std::vector<double> at(m);
  for(double& u : at) u = rng.uniform() * area;
  std::sort(at.begin(), at.end());
  std::vector<double> xyz;
  xyz.reserve(3 * m);
  std::size_t next = 0;
  double sum = 0;
  auto visit = [&](const typename Traits::Fragment& f) {
    sum += checked_area(traits, f);
    for(; next < m && at[next] < sum; ++next)
      for(int attempt = 0; attempt < 64; ++attempt)
        if(const auto s = traits.random_sample(f, rng)) {
          const std::array<double, 3>& p = traits.point(*s);
          xyz.insert(xyz.end(), p.begin(), p.end());
          break;
        }
  };
  traits.initial_fragments(Calling_output<decltype(visit)>(&visit));
  return xyz;
}

/// the pairs of the points `xyz` (x, y, z in a row) within distance `d` of each other, counted up to
/// `limit` (the count stops at the first pair above it)
/// \throws Invalid_input (from `Point_hash_grid`) if a coordinate is 2^62 times `d` or more
inline std::size_t close_pairs(const std::vector<double>& xyz, double d, std::size_t limit)
{
  const Point_hash_grid grid(d, xyz.data(), xyz.size() / 3);
  std::size_t pairs = 0;
  grid.for_each_pair_near(d, [&](std::size_t k, Point_hash_grid::Index, const double* q) {
    const double* p = grid.point(k);
    const double x = q[0] - p[0], y = q[1] - p[1], z = q[2] - p[2];
    return x * x + y * y + z * z <= d * d && ++pairs > limit;
  });
  return pairs;
}

/// The model of a maximal set's count as a function of d that a `number_of_points` search for `n`
/// points starts from: random points on the surface, and their pairs within a distance.
///
/// `first_distance(d0)`: the first distance of the search. `d0`, the distance at which a
/// maximal set in the plane has `n` points on the surface's area (about 0.6965 area / d0^2 points),
/// unless random points on the surface say that it is far too small. A maximal set at distance d in
/// the plane has about 0.6965 pi area / A_d points, where A_d = pi d^2 is the area within d of a
/// point; on strips far narrower than d, A_d is far below pi d^2, and the plane's distance gives a
/// hundred to a thousand times the target. The points' pairs within d estimate the mean of A_d: 2
/// pairs / (m (m - 1)) is about A_d / area for m points. Where the count that estimate gives at
/// `d0` is more than 2 n, the distance whose estimated count is `n` is returned instead, to a
/// factor of 2^(1/1024) (at most 2^60 `d0`), with the constant of the plane, 0.6965 pi. Where the
/// surface is a line at that scale (strips far narrower than d and farther apart than it), the
/// constant is that of a line, 2 / 1.3376 (a maximal set on a line has about 1 / 1.3376 d points a
/// unit of length, and A_d is 2 d times the strips' width), and the distance smaller by their
/// ratio: the exponent of the ratio of the pairs within 2 d and within d, 2 on a plane and 1 on a
/// line, interpolates between the two (see the code).
///
/// The estimate only raises the distance. Its count follows the mean of A_d over the surface, where
/// a maximal set's follows the mean of 1 / A_d, region by region, which is larger: on a surface
/// made of parts of different kinds (copies of a face that overlap, and strips far narrower than
/// d), its count is below the set's, and lowering the distance by it made runs stop at 2n + 64
/// points, one for each factor of about 2: on 1,000 copies of a square 5.3 10^-6 wide and 10 strips
/// 100 long and 2.8 10^-11 wide, 1,000 points at seed 1 ended in `Target_not_reached` after 24
/// runs, 20 of them stopped, where the search from the plane's distance takes 19. Where the plane's
/// distance is too large (faces that overlap), its runs are complete, with fewer points than the
/// target, and the search's steps correct it. Nor is the estimate exact where the surface is
/// neither a plane nor a line at the scale of d: on 500 strips 0.01 apart, a run at its distance
/// for 3,000 points (about 3.5 times their spacing) has 12% too few to 30% too many at seeds 0 to
/// 7; on strips 10 and 1 apart, lines at that scale, 10% too few to 8% too many at seeds 0 to 2 (a
/// third too few with the plane's constant alone). Test `MeshSampling.FirstCountDistanceFromRandomPoints`
/// checks the 10 strips 10 apart within 15% at seeds 0 to 2, and the 500 strips within 20% at 1,000 and
/// 3,000 points at seeds 0 and 1. The points number 20 sqrt(n), at least 1,000
/// and at most 200,000: from 2,500 to 10^8 points, about 440 of their pairs lie within the distance
/// sought, a spread of about 5% (more pairs below, fewer above).
///
/// `slope(d, got, n)`: after a complete run at `d` that gave `got` points, the slope of log(count) over
/// log(d) that the model gives from `d` to the distance where its count is n (the pairs within it are
/// those within `d` times got / n), where it differs from the plane's, -2, by more than three times its
/// spread (the pairs between the two distances vary at least as their square root; at twice, the steps
/// on two meshes of CGAL's data set took slopes near -1.4 where their counts went as d^-2, and a run
/// more: `benchmark/survey_count_mode`, change 54), clamped to [-4, -1]; otherwise -2, and -2 where the
/// pairs within `d` are beyond eight times the ones counted for the first distance, or the pairs sought
/// or those between the two distances fewer than 16 (with about 440 pairs within the distance of the
/// target, a run within about 4% of it). The search takes it until two complete runs measure a slope
/// (for its first step, and for the step after a complete run that follows stopped ones); it keeps the
/// model's points, 24 bytes each, until then. On 20 sheets 0.01 apart, where d is a few times their
/// spacing, a ball holds parts of several sheets and the count goes about as d^-3; on tubes about as
/// wide as d, where a sample goes from holding part of a ring to holding all of it, it falls faster
/// (`count_mode/sheets` and `count_mode/tubes` in benchmark/README.md, change 54; test
/// `MeshSampling.FirstStepTakesTheSlopeOfTheRandomPoints`). The model's slope is not exact either (its
/// count follows the mean of A_d, see above), and where the first run is far off the step can still
/// miss the target by more than 1%: the search takes three runs on the sheets at every seed measured,
/// two or three on the tubes (with the plane's step, four on the sheets at 10,000 points, three at
/// 100,000, three or four on the tubes). On a surface that is about a plane at the scale of d the
/// model's slope is the plane's within its spread, and the step is the plane's.
///
/// The model is empty (`first_distance(d0)` is `d0`, `slope()` is -2) where `random_sample()` refused
/// most darts, and a distance that the grid of the points cannot hold leaves both their defaults.
/// `first_count_distance()` is `d0` below 100 points, where runs are cheap, and where `d0` is below
/// `lowest`, the smallest distance the search may take, which raises `d0` to it or refuses it (near
/// the coordinates' precision, the grid of the points would scan boxes of cells far wider than `d0`:
/// 17 s for 10^6 points on a triangle 10^-13 wide at (1, 1, 1)); the search makes no model then.
class Count_model
{
public:
  /// an empty model
  Count_model() = default;

  /// draws the random points: 20 sqrt(n), at least 1,000 and at most 200,000
  template <class Traits>
  Count_model(const Traits& traits, double area, std::size_t n, std::uint64_t seed)
  {
    const double points = (std::min)(200000., (std::max)(1000., 20 * std::sqrt(double(n))));
    xyz_ = random_surface_points(traits, area, std::size_t(points), seed);
    const double m = double(xyz_.size() / 3);
    if(m < 500) { // (a model whose random_sample() refuses most darts)
      xyz_.clear();
      return;
    }
    // the pairs within d that make the estimated count n with the plane's constant
    target_ = plane * (m * (m - 1) / 2) / double(n);
    limit_ = std::size_t(8 * target_) + 16;
  }

  double first_distance(double d0) const
  {
    if(xyz_.empty()) return d0;
    try {
      if(pairs(d0, limit_) >= target_ / 2) return d0;
      const double d = distance_for_pairs(d0, target_);
      if(d == 0) return d0;
      // The plane's constant holds where the surface is two-dimensional at the scale of d. Where it
      // is a line (strips far narrower than d and farther apart than it), the pairs within 2 d are
      // twice those within d, not four times, and the constant is the line's; in between, it is
      // interpolated by the exponent D of that ratio, and the distance follows the pairs as d^D:
      // fewer pairs by the constant's ratio, c / plane, at a distance smaller by (c / plane)^(1 / D).
      // (A search for those pairs goes farther where part of them do not follow d^D: with strips and
      // a part much smaller than d that holds 0.4 of the pairs, whose pairs stay, the strips' count
      // reckoned at the distance it finds is 2.4 n, at the step's 1.7 n.)
      const double dimension =
          (std::min)(2., (std::max)(1., std::log2(pairs(2 * d, limit_) / pairs(d, limit_))));
      const double c = line + (dimension - 1) * (plane - line);
      return (std::max)(d0, d * std::pow(c / plane, 1 / dimension));
    } catch(const Invalid_input&) {
      return d0; // a distance too small for the grid of the points: the search's own checks tell
    }
  }

  double slope(double d, double got, double n) const
  {
    if(xyz_.empty() || !(got > 0) || got == n) return -2;
    try {
      // (counted up to eight times the limit: a run far from the target, on a surface where the
      // first distance was kept, can have more pairs than the limit within its distance)
      const double at = pairs(d, 8 * limit_), want = at * got / n;
      if(at > double(8 * limit_) || !(want >= 16) || want > double(4 * limit_)) return -2;
      const double to = distance_for_pairs(d, want);
      if(to == 0 || to == d) return -2;
      const double between = std::abs(pairs(to, 8 * limit_) - at);
      const double s = std::log(n / got) / std::log(to / d);
      if(!(between >= 16) || !(std::abs(s + 2) > 3 * std::abs(s) / std::sqrt(between))) return -2;
      return (std::min)(-1., (std::max)(-4., s));
    } catch(const Invalid_input&) {
      return -2;
    }
  }

private:
  // the density constants of the plane (0.6965 pi) and of a line (2 / 1.3376)
  static constexpr double plane = 0.6965 * 3.141592653589793, line = 2 / 1.3376;

  double pairs(double d, std::size_t limit) const { return double(close_pairs(xyz_, d, limit)); }

  // The distance, to a factor of 2^(1/1024), from which `want` pairs or more lie within it, searched
  // from `d` by factors of 2 (at most 2^60) and then by bisection in log d; 0 where none was found.
  // `want` is at most half of the limit the pairs are counted to.
  double distance_for_pairs(double d, double want) const
  {
    const std::size_t limit = std::size_t(2 * want) + 16;
    double lo = d, hi = d;
    const bool up = pairs(d, limit) < want;
    for(int k = 0;; ++k) {
      if(k == 60) return 0;
      if(up) {
        hi = 2 * lo;
        if(pairs(hi, limit) >= want) break;
        lo = hi;
      } else {
        lo = hi / 2;
        if(pairs(lo, limit) < want) break;
        hi = lo;
      }
    }
    for(int k = 0; k < 10; ++k) {
      const double mid = std::sqrt(lo) * std::sqrt(hi);
      if(pairs(mid, limit) < want) lo = mid;
      else hi = mid;
    }
    return std::sqrt(lo) * std::sqrt(hi);
  }

  std::vector<double> xyz_; // x, y, z in a row
  double target_ = 0;
  std::size_t limit_ = 0;
};

/// the model of a search for `n` points whose plane's distance is `d0`: empty below 100 points and
/// where `d0` is below `lowest` (see `Count_model`)
template <class Traits>
Count_model count_model(const Traits& traits, double area, std::size_t n, double d0, double lowest,
                        std::uint64_t seed)
{
  if(n < 100 || !(d0 >= lowest)) return Count_model();
  return Count_model(traits, area, n, seed);
}

/// the first distance of a search (the search keeps its model for its first step; the tests call this)
template <class Traits>
double first_count_distance(const Traits& traits, double area, std::size_t n, double d0, double lowest,
                            std::uint64_t seed)
{
  return count_model(traits, area, n, d0, lowest, seed).first_distance(d0);
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COUNT_ESTIMATE_H
