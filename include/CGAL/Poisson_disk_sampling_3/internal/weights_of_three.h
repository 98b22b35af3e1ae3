// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_WEIGHTS_OF_THREE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_WEIGHTS_OF_THREE_H

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The union coverage tests look for weights of three balls whose weighted criterion is -1 at three
/// points, A[c][t] being ball t's criterion at point c: the solution w of A w = (-1, -1, -1), by
/// Cramer's rule. False if A is singular (or its determinant not finite). The weights are a proposal
/// only: each test checks them with its own bound before it relies on them.
inline bool weights_of_three(const double (&A)[3][3], double (&w)[3])
{
  auto det = [](const double (&M)[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  };
  const double d = det(A);
  if(!(d != 0)) return false;
  for(int t = 0; t < 3; ++t) { // column t replaced by the right-hand side
    double B[3][3];
    for(int c = 0; c < 3; ++c)
      for(int q = 0; q < 3; ++q) B[c][q] = q == t ? 1. : A[c][q];
    w[t] = -(det(B) / d);
  }
  return true;
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_WEIGHTS_OF_THREE_H
