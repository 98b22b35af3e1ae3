// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_CELL_HASH_TABLE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_CELL_HASH_TABLE_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The cell of a uniform grid that holds coordinate `c`, for `inv_cell` = 1 / cell side. Monotone in
/// `c`, so a box's corner cells bound the cells of the points in it.
/// \throws Invalid_input if the cell index would not fit in 64 bits (or `c` is not finite)
inline std::int64_t grid_cell(double c, double inv_cell)
{
  const double x = c * inv_cell;
  if(!(std::abs(x) < 0x1.0p62)) // converting would be undefined
    throw Invalid_input("a coordinate is too large relative to the minimum distance (or not finite)");
  // floor(x) without a call to std::floor (which is not inlined without SSE4.1): the conversion
  // truncates towards zero, exactly for |x| < 2^62
  const std::int64_t t = std::int64_t(x);
  return t - std::int64_t(x < double(t));
}

/// The half-side of a box around coordinate `c` that holds every point within `reach` of it, widened
/// by more than the rounding error of computing the box's corners `c - m` and `c + m`
inline double widened_reach(double reach, double c) { return reach * (1 + 1e-9) + 1e-15 * std::abs(c); }

/// A map from the integer coordinates of a grid cell to a 32-bit value, by open addressing. Sparse:
/// memory is O(cells used), which for points on a surface is a vanishing part of the bounding box.
class Cell_hash_table
{
public:
  static constexpr std::uint32_t none = std::uint32_t(-1);

  /// `expected_cells` only sizes the table at the start
  explicit Cell_hash_table(std::size_t expected_cells = 0)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * expected_cells) capacity *= 2;
    slots_.assign(capacity, Slot());
  }

  std::size_t size() const { return used_; }

  /// brings the first slot the lookup of a cell reads into the cache, without waiting for it
  void prefetch(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    internal::prefetch(&slots_[hash(x, y, z) & (slots_.size() - 1)]);
  }

  /// the value of a cell, `none` if it has none
  std::uint32_t find(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t k = hash(x, y, z) & mask;; k = (k + 1) & mask) {
      const Slot& s = slots_[k];
      if(s.value == none) return none;
      if(s.x == x && s.y == y && s.z == z) return s.value;
    }
  }

  /// the value of a cell, set to `value_if_new` (not `none`) if the cell had none; the reference
  /// stays valid until the next call of this function
  std::uint32_t& find_or_insert(std::int64_t x, std::int64_t y, std::int64_t z, std::uint32_t value_if_new)
  {
    if(2 * (used_ + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t k = hash(x, y, z) & mask;; k = (k + 1) & mask) {
      Slot& s = slots_[k];
      if(s.value == none) {
        s.x = x;
        s.y = y;
        s.z = z;
        s.value = value_if_new;
        ++used_;
        return s.value;
      }
      if(s.x == x && s.y == y && s.z == z) return s.value;
    }
  }

private:
  struct Slot
  {
    std::int64_t x = 0, y = 0, z = 0;
    std::uint32_t value = none;
  };

  static std::size_t hash(std::int64_t x, std::int64_t y, std::int64_t z)
  {
    std::uint64_t h = std::uint64_t(x) * 0x9E3779B97F4A7C15ull + std::uint64_t(y) * 0xC2B2AE3D27D4EB4Full +
                      std::uint64_t(z) * 0x165667B19E3779F9ull;
    h ^= h >> 31; // the low bits pick the slot: mix the high ones in
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    return std::size_t(h);
  }

  void grow()
  {
    std::vector<Slot> old(2 * slots_.size());
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for(const Slot& s : old) {
      if(s.value == none) continue;
      std::size_t k = hash(s.x, s.y, s.z) & mask;
      while(slots_[k].value != none) k = (k + 1) & mask;
      slots_[k] = s;
    }
  }

  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_CELL_HASH_TABLE_H
