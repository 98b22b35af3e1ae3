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
  for(std::size_t k = 0; k < grid.size() && pairs <= limit; ++k) {
    const double* p = grid.point(k);
    grid.for_each_near(p, d, [&](Point_hash_grid::Index, const double* q) {
      if(q <= p) return false;
      const double x = q[0] - p[0], y = q[1] - p[1], z = q[2] - p[2];
      return x * x + y * y + z * z <= d * d && ++pairs > limit;
    });
  }
  return pairs;
}

/// The first distance of a `number_of_points` search for `n` points: `d0`, the distance at which a
/// maximal set in the plane has `n` points on the surface's area (about 0.6965 area / d0^2 points),
/// unless random points on the surface say that it is far off. A maximal set at distance d in the
/// plane has about 0.6965 pi area / A_d points, where A_d = pi d^2 is the area within d of a point;
/// on strips far narrower than d, or faces that lie closer to each other than d, A_d is far from
/// pi d^2, and the points' pairs within d estimate its mean: 2 pairs / (m (m - 1)) is about A_d / area
/// for m points. Where the count that estimate gives at `d0` is off by more than a factor of 2, the
/// distance whose estimated count is `n` is returned instead, to a factor of 2^(1/1024) (at least
/// `lowest`, at most 2^60 `d0`). The points number 20 sqrt(n), at least 1,000 and at most 200,000,
/// so that about 440 of their pairs lie within the distance sought: the estimate's spread is about
/// 5%, and its bias that of the plane's density on the surface at hand (on strips far narrower than
/// d, a maximal set has about 1 / 1.34 d points per unit of length, the plane's estimate 1 / 0.91 d).
/// On a surface that is about a plane at the scale of `d0`, `d0` is returned; and so it is below 100
/// points, where the search has its own way (see `run_for_count()`), or where the grid of the points
/// cannot hold a distance.
template <class Traits>
double first_count_distance(const Traits& traits, double area, std::size_t n, double d0, double lowest,
                            std::uint64_t seed)
{
  if(n < 100) return d0;
  const double points = (std::min)(200000., (std::max)(1000., 20 * std::sqrt(double(n))));
  const std::vector<double> xyz = random_surface_points(traits, area, std::size_t(points), seed);
  const double m = double(xyz.size() / 3);
  if(m < 500) return d0; // (a model whose random_sample() refuses most darts)
  // the pairs within d of each other that make the estimated count n
  const double target = 0.6965 * 3.141592653589793 * (m * (m - 1) / 2) / double(n);
  const std::size_t limit = std::size_t(4 * target) + 16;
  try {
    auto pairs = [&](double d) { return double(close_pairs(xyz, d, limit)); };
    const double at_d0 = pairs(d0);
    if(at_d0 >= target / 2 && at_d0 <= 2 * target) return d0;
    // a bracket [lo, hi] with fewer pairs than the target at lo and as many or more at hi
    double lo = d0, hi = d0;
    if(at_d0 < target) {
      for(int k = 0;; ++k) {
        if(k == 60) return d0;
        hi = 2 * lo;
        if(pairs(hi) >= target) break;
        lo = hi;
      }
    } else {
      for(int k = 0;; ++k) {
        if(k == 60 || hi / 2 < lowest) return d0;
        lo = hi / 2;
        if(pairs(lo) < target) break;
        hi = lo;
      }
    }
    for(int k = 0; k < 10; ++k) {
      const double mid = std::sqrt(lo) * std::sqrt(hi);
      if(pairs(mid) < target) lo = mid;
      else hi = mid;
    }
    return std::sqrt(lo) * std::sqrt(hi);
  } catch(const Invalid_input&) {
    return d0; // a distance too small for the grid of the points: the search's own checks tell
  }
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COUNT_ESTIMATE_H
