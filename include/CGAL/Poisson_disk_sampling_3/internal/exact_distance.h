// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_EXACT_DISTANCE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_EXACT_DISTANCE_H

#include <CGAL/Exact_rational.h>
#include <CGAL/enum.h>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// Exact sign of |p - q|^2 - d^2 for points given by double coordinates and a double distance d.
/// The double evaluation decides unless it is within a relative 1e-10 of the threshold (its error is
/// below 1e-15 relative), then GMP rationals decide.
inline CGAL::Comparison_result compare_distance_exact(const double* p, const double* q, double d)
{
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  const double d2 = dx * dx + dy * dy + dz * dz;
  const double t2 = d * d;
  if(d2 < t2 * (1. - 1e-10)) return CGAL::SMALLER;
  if(d2 > t2 * (1. + 1e-10)) return CGAL::LARGER;
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
