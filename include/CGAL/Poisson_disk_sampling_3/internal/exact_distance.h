// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_EXACT_DISTANCE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_EXACT_DISTANCE_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/enum.h>

#include <cmath>
#include <string>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The minimum distances that sampling and the maximality certificate accept, 2^-400 to 2^400
/// (about 3.9e-121 to 2.6e120). The coverage tests bound their rounding errors relative to the
/// numbers they compute; that holds while squares of distances stay normal doubles, far from the
/// subnormal range (below 2^-1022, where the error of a square is absolute) and from overflow. The
/// samplers also require the coordinates to be below 2^30 D in magnitude (`position_error()`), so
/// their squares stay below 2^862.
constexpr double smallest_minimum_distance = 0x1.0p-400;
constexpr double largest_minimum_distance = 0x1.0p+400;

/// throws `Invalid_input` unless `d` is in [smallest_minimum_distance, largest_minimum_distance]; the
/// message names `d` by `what` where given (a distance the package chose, not one the user gave)
inline void check_distance_range(double d, const std::string& what = std::string())
{
  if(!(d >= smallest_minimum_distance && d <= largest_minimum_distance))
    throw Invalid_input((what.empty() ? "the minimum distance " + number_text(d) : what) +
                        " is outside the range 2^-400 to 2^400 (about 3.9e-121 to 2.6e120) that the package "
                        "handles; scale the input");
}

/// throws `Invalid_input` unless `d` exceeds 2^20 times `position_error`, a model's bound on the
/// rounding of its points: below, rounding decides coverage, the subdivision would not end before
/// its depth floor, and the certificate would split every fragment to its own floor. The message
/// names `d` by `what` where given, as check_distance_range() does.
inline void check_distance_precision(double d, double position_error, const std::string& what = std::string())
{
  if(!(position_error >= 0) || !std::isfinite(position_error))
    throw Invalid_input("the surface model gave the position error " + number_text(position_error) +
                        "; position_error() must be a finite number, not negative");
  if(!(d > 0x1.0p20 * position_error))
    throw Invalid_input((what.empty() ? "the minimum distance " + number_text(d) : what) +
                        " is too small for the precision of the coordinates (rounding error " +
                        number_text(position_error) + ")");
}

/// Exact sign of |p - q|^2 - d^2 for points given by double coordinates and a double distance d.
/// The double evaluation decides unless it is within a relative 1e-10 of the threshold (its error is
/// below 1e-15 relative while d^2 is a normal double far from overflow, which the first test makes
/// sure of), then GMP rationals decide. So it is exact at any scale.
inline CGAL::Comparison_result compare_distance_exact(const double* p, const double* q, double d)
{
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  const double d2 = dx * dx + dy * dy + dz * dz;
  const double t2 = d * d;
  if(t2 >= 0x1.0p-900 && t2 <= 0x1.0p+900) {
    if(d2 < t2 * (1. - 1e-10)) return CGAL::SMALLER;
    if(d2 > t2 * (1. + 1e-10)) return CGAL::LARGER;
  }
  typedef CGAL::Exact_rational ET;
  ET s(0);
  for(int i = 0; i < 3; ++i) {
    const ET di = ET(p[i]) - ET(q[i]);
    s += di * di;
  }
  const ET ed(d);
  return CGAL::compare(s, ed * ed);
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_EXACT_DISTANCE_H
