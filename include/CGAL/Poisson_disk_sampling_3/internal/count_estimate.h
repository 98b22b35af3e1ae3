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

/// The first distance of a `number_of_points` search for `n` points: `d0`, the distance at which a
/// maximal set in the plane has `n` points on the surface's area (about 0.6965 area / d0^2 points),
/// unless random points on the surface say that it is far too small. A maximal set at distance d in
/// the plane has about 0.6965 pi area / A_d points, where A_d = pi d^2 is the area within d of a
/// point; on strips far narrower than d, A_d is far below pi d^2, and the plane's distance gives a
/// hundred to a thousand times the target. The points' pairs within d estimate the mean of A_d: 2
/// pairs / (m (m - 1)) is about A_d / area for m points. Where the count that estimate gives at `d0`
/// is more than 2 n, the distance whose estimated count is `n` is returned instead, to a factor of
/// 2^(1/1024) (at most 2^60 `d0`).
///
/// The estimate only raises the distance. Its count follows the mean of A_d over the surface, where
/// a maximal set's follows the mean of 1 / A_d, region by region, which is larger: on a surface
/// made of parts of different kinds (copies of a face that overlap, and strips far narrower than
/// d), its count is below the set's, and lowering the distance by it made runs stop at 2n + 64
/// points, one for each factor of about 2: on 1,000 copies of a square 5.3 10^-6 wide and 10 strips
/// 100 long and 2.8 10^-11 wide, 1,000 points at seed 1 ended in `Target_not_reached` after 24
/// runs, 20 of them stopped, where the search from the plane's distance takes 19. Where the plane's
/// distance is too large (faces that overlap), its runs are complete, with fewer points than the
/// target, and the search's steps correct it. The estimate is also off by the density of the
/// surface at hand against the plane's: on strips far narrower than d and farther apart than it, a
/// maximal set has about 1 / 1.34 d points per unit of length, the estimate 1 / 0.91 d, so the
/// first run has about a third too few points; on strips 3.5 times closer to each other than d, 12%
/// too few to 14% too many (test `MeshSampling.FirstCountDistanceFromRandomPoints`). The points
/// number 20 sqrt(n), at least 1,000 and at most 200,000: from 2,500 to 10^8 points, about 440 of
/// their pairs lie within the distance sought, a spread of about 5% (more pairs below, fewer
/// above).
///
/// `d0` is returned below 100 points, where runs are cheap; where `d0` is below `lowest`, the
/// smallest distance the search may take, which raises `d0` to it or refuses it (near the
/// coordinates' precision, the grid of the points would scan boxes of cells far wider than `d0`:
/// 17 s for 10^6 points on a triangle 10^-13 wide at (1, 1, 1)); and where the grid of the points
/// cannot hold a distance.
template <class Traits>
double first_count_distance(const Traits& traits, double area, std::size_t n, double d0, double lowest,
                            std::uint64_t seed)
{
  if(n < 100 || !(d0 >= lowest)) return d0;
  const double points = (std::min)(200000., (std::max)(1000., 20 * std::sqrt(double(n))));
  const std::vector<double> xyz = random_surface_points(traits, area, std::size_t(points), seed);
  const double m = double(xyz.size() / 3);
  if(m < 500) return d0; // (a model whose random_sample() refuses most darts)
  // the pairs within d of each other that make the estimated count n
  const double target = 0.6965 * 3.141592653589793 * (m * (m - 1) / 2) / double(n);
  const std::size_t limit = std::size_t(4 * target) + 16;
  try {
    auto pairs = [&](double d) { return double(close_pairs(xyz, d, limit)); };
    if(pairs(d0) >= target / 2) return d0;
    // a bracket [lo, hi] with fewer pairs than the target at lo and as many or more at hi
    double lo = d0, hi = d0;
    for(int k = 0;; ++k) {
      if(k == 60) return d0;
      hi = 2 * lo;
      if(pairs(hi) >= target) break;
      lo = hi;
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
