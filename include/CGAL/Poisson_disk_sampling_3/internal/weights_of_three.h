// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_WEIGHTS_OF_THREE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_WEIGHTS_OF_THREE_H

#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

// the determinant of M, expanded along its first row
inline double determinant_3(const double (&M)[3][3])
{
  return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
         M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

// the solution of M w = (-1, -1, -1), for d = det(M) != 0, by Cramer's rule
inline void solve_3(const double (&M)[3][3], double d, double (&w)[3])
{
  for(int t = 0; t < 3; ++t) { // column t replaced by the right-hand side
    double B[3][3];
    for(int c = 0; c < 3; ++c)
      for(int q = 0; q < 3; ++q) B[c][q] = q == t ? 1. : M[c][q];
    w[t] = -(determinant_3(B) / d);
  }
}

// weights_of_three() for a determinant that is not a normal double: A scaled by a power of two
CGAL_PDS_NOINLINE inline bool weights_of_three_scaled(const double (&A)[3][3], double (&w)[3])
{
  double largest = 0;
  for(const auto& row : A)
    for(double x : row) largest = (std::max)(largest, std::abs(x));
  if(!(largest > 0 && largest <= (std::numeric_limits<double>::max)())) return false;
  int e;
  std::frexp(largest, &e);
  double S[3][3];
  for(int c = 0; c < 3; ++c)
    for(int q = 0; q < 3; ++q) S[c][q] = std::ldexp(A[c][q], -e);
  const double d = determinant_3(S);
  if(!(d != 0) || !(std::abs(d) <= (std::numeric_limits<double>::max)())) return false;
  solve_3(S, d, w);
  return true;
}

/// The union coverage tests look for weights of three balls whose weighted criterion is -1 at three
/// points, A[c][t] being ball t's criterion at point c: a positive multiple of the solution w of
/// A w = (-1, -1, -1), by Cramer's rule. False if A is singular. The weights are a proposal only:
/// each test checks them with its own bound, in which a positive factor cancels, before it relies on
/// them.
///
/// The criteria scale with the square of the surface's size, and the determinant with its sixth
/// power: for a surface about 2^170 times larger or smaller than 1 it would overflow or underflow.
/// Then the system is solved scaled by a power of two, which is exact (but for entries that become
/// subnormal) and multiplies the solution by that power: the weights are those of the same surface
/// at size 1, scaled, and the samples the same points, scaled.
inline bool weights_of_three(const double (&A)[3][3], double (&w)[3])
{
  const double d = determinant_3(A);
  const double d_abs = std::abs(d);
  // zero, subnormal, infinite or NaN: A is singular, or its entries are far from 1
  if(!(d_abs >= (std::numeric_limits<double>::min)() && d_abs <= (std::numeric_limits<double>::max)()))
    return weights_of_three_scaled(A, w);
  solve_3(A, d, w);
  return true;
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_WEIGHTS_OF_THREE_H
