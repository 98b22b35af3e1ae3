// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_CELL_HASH_TABLE_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_CELL_HASH_TABLE_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <atomic>
#include <chrono>
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
///
/// A slot takes 16 bytes: it keeps the low 32 bits of the cell's coordinates minus those of the first
/// cell inserted (the origin), which identify the cell as long as every cell inserted lies within
/// 2^31 cells of the origin on each axis; a lookup outside that window then finds nothing without
/// probing. The first insertion outside the window makes the table keep the full coordinates of each
/// slot beside it as well (24 bytes more a slot), and compare them too. (Full coordinates in every
/// slot, 32 bytes, made the table twice as large, and the sampler 5% slower at one million points.)
class Cell_hash_table
{
public:
  static constexpr std::uint32_t none = std::uint32_t(-1);

  /// `expected_cells` only sizes the table at the start
  explicit Cell_hash_table(std::size_t expected_cells = 0) : key_(new_key())
  {
    slots_.assign(expected_cells < 8 ? 16 : 2 * expected_cells, Slot());
  }

  std::size_t size() const { return used_; }

  /// brings the first slot the lookup of a cell reads into the cache, without waiting for it
  void prefetch(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    internal::prefetch(&slots_[slot_of(hash(x, y, z))]);
  }

  /// the value of a cell, `none` if it has none
  std::uint32_t find(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    const Cell c{x, y, z};
    if(wide_.empty() && !in_window(c)) return none;
    const Slot key = key_of(c);
    for(std::size_t k = slot_of(hash(x, y, z));; k = next(k)) {
      const Slot& s = slots_[k];
      if(s.value == none) return none;
      if(holds(k, key, c)) return s.value;
    }
  }

  /// the slots a lookup of the cell reads (for tests of the hash)
  std::size_t probes(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    const Cell c{x, y, z};
    const Slot key = key_of(c);
    std::size_t n = 1;
    for(std::size_t k = slot_of(hash(x, y, z)); slots_[k].value != none && !holds(k, key, c); k = next(k)) ++n;
    return n;
  }

  /// the value of a cell, set to `value_if_new` (not `none`) if the cell had none; the reference
  /// stays valid until the next call of this function
  std::uint32_t& find_or_insert(std::int64_t x, std::int64_t y, std::int64_t z, std::uint32_t value_if_new)
  {
    const Cell c{x, y, z};
    if(used_ == 0) origin_ = c;
    if(2 * (used_ + 1) > slots_.size()) grow();
    if(wide_.empty() && !in_window(c)) widen();
    const Slot key = key_of(c);
    for(std::size_t k = slot_of(hash(x, y, z));; k = next(k)) {
      Slot& s = slots_[k];
      if(s.value == none) {
        s = key;
        s.value = value_if_new;
        if(!wide_.empty()) wide_[k] = c;
        ++used_;
        return s.value;
      }
      if(holds(k, key, c)) return s.value;
    }
  }

private:
  struct Cell
  {
    std::int64_t x, y, z;
    bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
  };

  struct Slot
  {
    std::uint32_t x = 0, y = 0, z = 0; // the low bits of the cell minus the origin
    std::uint32_t value = none;
  };

  // whether the used slot k holds cell c, whose key is `key`
  bool holds(std::size_t k, const Slot& key, const Cell& c) const
  {
    const Slot& s = slots_[k];
    return s.x == key.x && s.y == key.y && s.z == key.z && (wide_.empty() || wide_[k] == c);
  }

  // the difference of two coordinates below 2^62 in magnitude fits in 64 bits; modulo 2^32
  static std::uint32_t low_bits(std::int64_t a, std::int64_t o) { return std::uint32_t(std::uint64_t(a - o)); }
  static bool in_window(std::int64_t a, std::int64_t o)
  {
    const std::int64_t d = a - o;
    return d >= -(std::int64_t(1) << 31) && d < (std::int64_t(1) << 31);
  }
  bool in_window(const Cell& c) const
  {
    return in_window(c.x, origin_.x) && in_window(c.y, origin_.y) && in_window(c.z, origin_.z);
  }
  Slot key_of(const Cell& c) const
  {
    Slot s;
    s.x = low_bits(c.x, origin_.x);
    s.y = low_bits(c.y, origin_.y);
    s.z = low_bits(c.z, origin_.z);
    return s;
  }
  // the cell of a slot, while all lie in the window
  Cell cell_in_window(const Slot& s) const
  {
    return Cell{origin_.x + std::int32_t(s.x), origin_.y + std::int32_t(s.y), origin_.z + std::int32_t(s.z)};
  }

  // from now on, the full coordinates of each slot are kept beside it
  void widen()
  {
    wide_.assign(slots_.size(), Cell{0, 0, 0});
    for(std::size_t k = 0; k < slots_.size(); ++k)
      if(slots_[k].value != none) wide_[k] = cell_in_window(slots_[k]);
  }

  // The hash of a cell, with the table's key. A hash linear in the cell (a sum of products) sends
  // all the cells that differ by combinations of a few short vectors, which lattice reduction finds,
  // to one slot and one probe chain: 262,144 tiny triangles at such cells took 147 s to sample
  // instead of 0.4 s. Here each coordinate enters after the state has been multiplied and shifted,
  // and the key, drawn anew for each table, keeps a set of cells found for one table from piling up
  // in another. Where a cell lies in the table decides nothing but the table's speed: values are
  // found by their cells, and the points sampled do not depend on the key.
  std::uint64_t hash(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    std::uint64_t h = (std::uint64_t(x) ^ key_) * 0x9E3779B97F4A7C15ull;
    h = ((h ^ (h >> 32)) + std::uint64_t(y)) * 0xC2B2AE3D27D4EB4Full;
    h = ((h ^ (h >> 32)) + std::uint64_t(z)) * 0x165667B19E3779F9ull;
    h ^= h >> 31; // mix the high bits into the low ones, then the product mixes them back up
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    return h;
  }

  // a key for a new table: the clock, a count of the tables made and where the count lies (the
  // program's address space is laid out anew at each start), mixed
  static std::uint64_t new_key()
  {
    static std::atomic<std::uint64_t> tables{0};
    std::uint64_t k = std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                      ((tables.fetch_add(1, std::memory_order_relaxed) + 1) * 0x9E3779B97F4A7C15ull) ^
                      std::uint64_t(reinterpret_cast<std::uintptr_t>(&tables));
    k = (k ^ (k >> 30)) * 0xBF58476D1CE4E5B9ull;
    k = (k ^ (k >> 27)) * 0x94D049BB133111EBull;
    return k ^ (k >> 31);
  }

  // the slot of a hash: its high 32 bits scaled to the table's size, which need not be a power of two
  // (a table of twice the cells expected, not of the power of two above that: 4,600 slots instead of
  // 8,192 for the sphere at 10,000 points)
  std::size_t slot_of(std::uint64_t h) const
  {
    const std::uint64_t n = slots_.size();
    return std::size_t(n <= 0xFFFFFFFFu ? ((h >> 32) * n) >> 32 : h % n);
  }
  std::size_t next(std::size_t k) const { return k + 1 == slots_.size() ? 0 : k + 1; }

  void grow()
  {
    std::vector<Slot> old(2 * slots_.size());
    old.swap(slots_);
    std::vector<Cell> old_wide(wide_.empty() ? 0 : slots_.size(), Cell{0, 0, 0});
    old_wide.swap(wide_);
    for(std::size_t i = 0; i < old.size(); ++i) {
      const Slot& s = old[i];
      if(s.value == none) continue;
      const Cell c = old_wide.empty() ? cell_in_window(s) : old_wide[i];
      std::size_t k = slot_of(hash(c.x, c.y, c.z));
      while(slots_[k].value != none) k = next(k);
      slots_[k] = s;
      if(!wide_.empty()) wide_[k] = c;
    }
  }

  std::vector<Slot> slots_;
  std::vector<Cell> wide_; // empty while every cell lies in the window; then the cell of each slot
  Cell origin_{0, 0, 0};   // the first cell inserted
  std::size_t used_ = 0;
  std::uint64_t key_;      // of hash()
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_CELL_HASH_TABLE_H
