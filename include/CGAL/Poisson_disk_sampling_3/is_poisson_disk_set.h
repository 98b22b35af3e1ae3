// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_IS_POISSON_DISK_SET_H
#define CGAL_POISSON_DISK_SAMPLING_3_IS_POISSON_DISK_SET_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Point_hash_grid.h>
#include <CGAL/Poisson_disk_sampling_3/internal/exact_distance.h>
#include <CGAL/Poisson_disk_sampling_3/internal/nearest_double.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Ref
/// The answer of `is_poisson_disk_set()`: converts to `true` when the set is valid, and otherwise
/// names a pair of points closer than the minimum distance.
struct Poisson_disk_check
{
  bool valid = true;       ///< no two points are closer than the minimum distance
  std::size_t first = 0;   ///< when not valid: index of one point of an offending pair
  std::size_t second = 0;  ///< when not valid: index of the other point, `second > first`
  /// `valid`
  explicit operator bool() const { return valid; }
};

namespace internal {

// the coordinates of a point of a CGAL kernel, as the nearest doubles, or of a model's point,
// `std::array<double, 3>`
template <class Point>
std::array<double, 3> coordinates(const Point& p)
{
  if constexpr(std::is_same<Point, std::array<double, 3>>::value) return p;
  else return nearest_doubles(p);
}

template <class PointRange>
std::vector<double> coordinates_of(const PointRange& points)
{
  std::vector<double> xyz;
  std::size_t i = 0;
  for(const auto& p : points) {
    for(double c : coordinates(p)) {
      if(!std::isfinite(c)) throw Invalid_input("point " + std::to_string(i) + " has a coordinate that is not finite");
      xyz.push_back(c);
    }
    ++i;
  }
  return xyz;
}

inline void check_distance(double d)
{
  if(!(d > 0) || !std::isfinite(d)) throw Invalid_input("the minimum distance must be positive and finite");
}

/// a grid of the given points with cells of side 2d. Refuses a distance below 2^-44 of the largest
/// |coordinate| m: a query's box is widened by 1e-15 m for the rounding of its corners, which beyond
/// about 2^50 d would span many cells per query (a thousand on each axis at 2^60 d; at 2^63 d the cell
/// indices reach the 2^62 that grid_cell() refuses); and refuses m + 4d beyond the doubles' range,
/// where the boxes' corners would be infinite.
inline Point_hash_grid grid_of(const std::vector<double>& xyz, double d)
{
  double m = 0;
  for(double c : xyz) m = (std::max)(m, std::abs(c));
  if(m > 0x1.0p44 * d)
    throw Invalid_input("the minimum distance is too small for the extent of the points: a coordinate is more "
                        "than 2^44 times the distance");
  if(!(m + 4 * d <= (std::numeric_limits<double>::max)()))
    throw Invalid_input("the coordinates plus the minimum distance exceed the range of doubles");
  return Point_hash_grid(2 * d * (1 + 0x1.0p-10), xyz.data(), xyz.size() / 3);
}

} // namespace internal

/// \ingroup PkgPoissonDiskSampling3Ref
/// Checks that no two points are closer than `minimum_distance`: for every pair, |p - q| >= d is
/// decided exactly on the stored coordinates (converted to double), with a floating-point filter and
/// exact rational arithmetic where the filter cannot decide. Sorts the points by cell of a grid of side
/// 2d (O(n log n)), then runs in expected linear time.
///
/// @tparam PointRange a range of `Point_3` of any CGAL kernel, or of `std::array<double, 3>` (the points
/// of the samples of a model of `SurfaceFragmentTraits_3`)
/// @param points the points
/// @param minimum_distance the distance d = 2r
/// \returns the verdict, and an offending pair if there is one
/// \throws Invalid_input if d is not positive and finite, a coordinate is not finite, the largest
/// |coordinate| is more than 2^44 d, or it plus 4 d exceeds the range of doubles
template <class PointRange>
Poisson_disk_check is_poisson_disk_set(const PointRange& points, double minimum_distance)
{
  internal::check_distance(minimum_distance);
  std::vector<double> xyz = internal::coordinates_of(points);
  double d = minimum_distance;
  // Distances below 2^-400 (which the samplers refuse) are scaled up: under about 2.8e-309 the grid's
  // 1 / cell would overflow. The coordinates and d are multiplied by one power of two, which is exact
  // (or overflows, for coordinates that the grid refuses anyway) and leaves every comparison of
  // distances as it was.
  if(d < 0x1.0p-400) {
    const int e = -std::ilogb(d);
    for(double& c : xyz) c = std::ldexp(c, e);
    d = std::ldexp(d, e);
  }
  const internal::Point_hash_grid grid = internal::grid_of(xyz, d);
  Poisson_disk_check result;
  // each pair once, up to the first too close
  grid.for_each_pair_near(d, [&](std::size_t k, internal::Point_hash_grid::Index j, const double* q) {
    if(internal::compare_distance_exact(grid.point(k), q, d) != CGAL::SMALLER) return false;
    const std::size_t i = grid.index(k);
    result.valid = false;
    result.first = (std::min)(i, std::size_t(j));
    result.second = (std::max)(i, std::size_t(j));
    return true;
  });
  return result;
}

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_IS_POISSON_DISK_SET_H
