// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_RANDOM_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_RANDOM_H

#include <cstdint>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// splitmix64: the successive states of a Weyl sequence (step 0x9E3779B97F4A7C15) through a mixing
/// function. It seeds `Random`, and a dart draws its point from one seeded by a draw of `Random`.
/// Streams of different seeds share no state unless their seeds are within a few steps of each other,
/// a chance of about 2^-60 for two random seeds.
class Stream
{
public:
  explicit Stream(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next()
  {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// uniform double in [0, 1), 53 random bits
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }

private:
  std::uint64_t state_;
};

// xoshiro256** seeded with splitmix64. We do not use <random> distributions: their output differs
// between standard libraries, and the package promises the same points for the same seed everywhere.
class Random
{
public:
  explicit Random(std::uint64_t seed)
  {
    Stream seeds(seed);
    for(std::uint64_t& si : s_) si = seeds.next();
  }

  std::uint64_t next()
  {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// uniform double in [0, 1), 53 random bits
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }

  /// uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the bias is below 2^-32 for n < 2^32)
  std::uint64_t uniform_index(std::uint64_t n) { return high_half_of_product(next(), n); }

  /// the upper 64 bits of the 128-bit product x n: by a 128-bit multiplication where the compiler
  /// has one, else from 32-bit halves (the same value: the stream does not depend on the compiler)
  static std::uint64_t high_half_of_product(std::uint64_t x, std::uint64_t n)
  {
#if defined(__SIZEOF_INT128__)
    // __extension__: the type is GCC's and Clang's, which -pedantic-errors would refuse
    __extension__ typedef unsigned __int128 Wide;
    return std::uint64_t((static_cast<Wide>(x) * n) >> 64);
#else
    return high_half_of_product_by_halves(x, n);
#endif
  }

  /// `high_half_of_product()` by 32-bit halves, for any compiler
  static std::uint64_t high_half_of_product_by_halves(std::uint64_t x, std::uint64_t n)
  {
    const std::uint64_t low = 0xffffffffu;
    const std::uint64_t x0 = x & low, x1 = x >> 32, n0 = n & low, n1 = n >> 32;
    const std::uint64_t p00 = x0 * n0, p01 = x0 * n1, p10 = x1 * n0, p11 = x1 * n1;
    // the carry out of the low 64 bits: bits 32 to 63 of the three terms that reach them
    const std::uint64_t middle = (p00 >> 32) + (p01 & low) + (p10 & low);
    return p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
  }

private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_RANDOM_H
