// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_SIN_COS_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_SIN_COS_H

#include <cmath>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The sine and cosine of `x`, each within 2^-52 of the exact value (absolute error; checked
/// against 50-digit values in test_sphere.cpp), computed with additions and multiplications only, so
/// that they are the same on every platform with IEEE doubles. For |x| <= 16 pi: x is reduced to
/// r = x - k pi / 2, |r| <= pi / 4 (k pi / 2 in two parts: the first, with its last 8 bits zero,
/// times k <= 32 is exact), then Taylor polynomials of degree 17 and 18 in r, whose truncation errors
/// are below 1e-19 there. Beyond, `std::sin` and `std::cos`.
///
/// (The sphere's model evaluates the sines and cosines of two or three longitudes per dart: with the
/// C library's `sincos`, whose first step saves and sets the rounding mode, that was 9% of the time
/// of a driver sampling the unit sphere at a million points.)
inline void sin_cos(double x, double& s, double& c)
{
  constexpr double pi = 3.14159265358979323846;
  if(!(std::abs(x) <= 16 * pi)) {
    s = std::sin(x);
    c = std::cos(x);
    return;
  }
  // pi / 2 = half_pi_1 + half_pi_2 + (8.5e-32): half_pi_1 is pi / 2 cut to 45 bits
  constexpr double half_pi_1 = 0x1.921fb54442dp+0;
  constexpr double half_pi_2 = 0x1.8469898cc5170p-48;
  // k, the nearest integer to x / (pi / 2), by a conversion that truncates whatever the rounding mode
  const long n = static_cast<long>(x * 0x1.45f306dc9c883p-1 + (x < 0 ? -0.5 : 0.5)); // x 2 / pi
  const double k = double(n);
  const double r = (x - k * half_pi_1) - k * half_pi_2;
  const double z = r * r;
  // sin r = r - r^3/3! + ... - r^19/19!, cos r = 1 - r^2/2! + ... + r^20/20!, the last terms left out;
  // the coefficients are 1/n! rounded to nearest (literals, not quotients: compilers do not fold a
  // quotient under -frounding-math, which CGAL sets, and would divide at every call)
  const double ps =
      -0x1.5555555555555p-3 +
      z * (0x1.1111111111111p-7 +
           z * (-0x1.a01a01a01a01ap-13 +
                z * (0x1.71de3a556c734p-19 +
                     z * (-0x1.ae64567f544e4p-26 +
                          z * (0x1.6124613a86d09p-33 + z * (-0x1.ae7f3e733b81fp-41 + z * 0x1.952c77030ad4ap-49))))));
  const double pc =
      0x1.5555555555555p-5 +
      z * (-0x1.6c16c16c16c17p-10 +
           z * (0x1.a01a01a01a01ap-16 +
                z * (-0x1.27e4fb7789f5cp-22 +
                     z * (0x1.1eed8eff8d898p-29 +
                          z * (-0x1.93974a8c07c9dp-37 + z * (0x1.ae7f3e733b81fp-45 + z * -0x1.6827863b97d97p-53))))));
  const double sr = r + r * z * ps;
  const double cr = (1 - 0.5 * z) + z * z * pc;
  // sin(r + k pi / 2) and cos(r + k pi / 2) by the quarter turns k mod 4
  switch(n & 3) { // k mod 4, also for k < 0
  case 0: s = sr; c = cr; break;
  case 1: s = cr; c = -sr; break;
  case 2: s = -sr; c = -cr; break;
  default: s = -cr; c = sr; break;
  }
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_SIN_COS_H
