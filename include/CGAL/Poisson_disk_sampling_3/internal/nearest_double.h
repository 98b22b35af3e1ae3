// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_NEAREST_DOUBLE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_NEAREST_DOUBLE_H

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The double nearest to `x`, ties to even, for a number type of a CGAL kernel: the number every
/// sampler and validation reads a coordinate as. `CGAL::to_double()` is not that number for exact
/// types: for `Epeck`'s lazy numbers it is the middle of their current interval, which moves once
/// anything in the program has asked for their exact value (the same mesh then gave other points),
/// and for `CGAL::Gmpq` it is truncated. For an exact type (`Algebraic_structure_traits::Is_exact`),
/// the interval of `CGAL::to_interval()` is narrowed to two neighbouring doubles by comparisons of `x`
/// with doubles, and `x` is compared with their midpoint through differences (no division, so that
/// rings serve too). A lazy number whose value is not a double is thus computed exactly, once (its
/// exact value is kept, as CGAL keeps it after any exact predicate). For an inexact type, such as
/// `Quotient<double>` or `Interval_nt`, whose comparisons round, the result is `CGAL::to_double()`. A
/// value beyond the largest double reads as an infinity, which the callers refuse.
template <class NT>
double nearest_double(const NT& x)
{
  if constexpr(std::is_same<NT, double>::value) {
    return x;
  } else if constexpr(!CGAL::Algebraic_structure_traits<NT>::Is_exact::value) {
    return CGAL::to_double(x);
  } else {
    const std::pair<double, double> i = CGAL::to_interval(x);
    double lo = i.first, hi = i.second;
    if(lo == hi) return lo; // a double: coordinates read from a file
    if(!(lo < hi)) return CGAL::to_double(x);
    // an interval that overflowed, for a value that may be in range (a huge homogeneous weight)
    const double largest = (std::numeric_limits<double>::max)();
    const double infinity = std::numeric_limits<double>::infinity();
    if(hi == infinity) {
      if(CGAL::compare(x, NT(largest)) == CGAL::LARGER) return infinity;
      hi = largest;
    }
    if(lo == -infinity) {
      if(CGAL::compare(x, NT(-largest)) == CGAL::SMALLER) return -infinity;
      lo = -largest;
    }
    // lo <= x <= hi; then lo < x < hi, with no double strictly between them
    if(CGAL::compare(x, NT(lo)) == CGAL::EQUAL) return lo;
    if(CGAL::compare(x, NT(hi)) == CGAL::EQUAL) return hi;
    for(double next = std::nextafter(lo, hi); next != hi; next = std::nextafter(lo, hi)) {
      double m = 0.5 * lo + 0.5 * hi; // (no overflow; at most a rounding off the middle)
      if(!(lo < m && m < hi)) m = next;
      const CGAL::Comparison_result c = CGAL::compare(x, NT(m));
      if(c == CGAL::EQUAL) return m;
      (c == CGAL::SMALLER ? hi : lo) = m;
    }
    const CGAL::Comparison_result c = CGAL::compare(NT(x - NT(lo)), NT(NT(hi) - x));
    if(c != CGAL::EQUAL) return c == CGAL::SMALLER ? lo : hi;
    // halfway: the one whose last bit is 0 (the significands of neighbouring doubles differ by one)
    std::uint64_t bits;
    std::memcpy(&bits, &lo, sizeof bits);
    return (bits & 1) == 0 ? lo : hi;
  }
}

/// the coordinates of a point of a CGAL kernel, each read by `nearest_double()`
template <class Point>
std::array<double, 3> nearest_doubles(const Point& p)
{
  return {{nearest_double(p.x()), nearest_double(p.y()), nearest_double(p.z())}};
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_NEAREST_DOUBLE_H
