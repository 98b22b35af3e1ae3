// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POWER_OF_HALF_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POWER_OF_HALF_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// 2^-k, exactly: from a table for k < 511 (std::ldexp was 6% of the sampling time on meshes), by
/// std::ldexp beyond. Multiplying by it rounds once, like std::ldexp, even into subnormals.
inline double power_of_half(std::size_t k)
{
  static const std::array<double, 511> table = [] {
    std::array<double, 511> t{};
    for(std::size_t i = 0; i < t.size(); ++i) t[i] = std::ldexp(1., -int(i));
    return t;
  }();
  return k < table.size() ? table[k] : std::ldexp(1., -int(k));
}

/// x 2^e, by a product with the double 2^e where that is a normal double (std::ldexp is a call of the
/// library: seven a face were a tenth of the triangle model's table on 3.3 million faces), else by
/// std::ldexp; the same result, rounded once, even into subnormals
inline double times_power_of_two(double x, int e)
{
  if(e < -1022 || e > 1023) return std::ldexp(x, e);
  const std::uint64_t bits = std::uint64_t(e + 1023) << 52;
  double p;
  std::memcpy(&p, &bits, sizeof p);
  return x * p;
}

/// std::ilogb(x) for a finite x other than 0, read from the bits of a normal double (a call of the
/// library only for a subnormal one)
inline int binary_exponent(double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int e = int(bits >> 52 & 0x7ff);
  return e != 0 ? e - 1023 : std::ilogb(x);
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POWER_OF_HALF_H
