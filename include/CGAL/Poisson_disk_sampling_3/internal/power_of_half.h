// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POWER_OF_HALF_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POWER_OF_HALF_H

#include <array>
#include <cmath>
#include <cstddef>

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

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POWER_OF_HALF_H
