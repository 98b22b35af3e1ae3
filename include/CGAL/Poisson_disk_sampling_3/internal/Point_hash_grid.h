// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H

#include <CGAL/assertions.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// Points in a uniform grid of cubic cells, stored sparsely: an open-addressing hash table maps a cell
/// to the first of its points, and the points of a cell form a linked list. Memory is O(points): a
/// surface sample set occupies a vanishing fraction of the cells of its bounding box.
class Point_hash_grid
{
public:
  typedef std::uint32_t Index;
  static constexpr Index none = Index(-1);

  /// `cell_size` > 0; callers make sure |coordinate| / cell_size stays below 2^62.
  explicit Point_hash_grid(double cell_size, std::size_t expected_points = 0)
    : inv_cell_(1. / cell_size)
  {
    CGAL_precondition(cell_size > 0);
    std::size_t capacity = 16;
    while(capacity < expected_points) capacity *= 2; // about four times the number of cells used
    slots_.assign(capacity, Slot());
    points_.reserve(3 * expected_points);
    next_.reserve(expected_points);
  }

  std::size_t size() const { return next_.size(); }
  const double* point(Index i) const { return &points_[3 * std::size_t(i)]; }

  Index insert(const double* p)
  {
    const Index i = Index(next_.size());
    points_.insert(points_.end(), p, p + 3);
    Slot& s = find_or_create(cell_of(p[0]), cell_of(p[1]), cell_of(p[2]));
    next_.push_back(s.head);
    s.head = i;
    return i;
  }

  /// calls `f(index, point)` for every point at distance <= `radius` from `p`, and maybe a few more.
  /// The query box is widened by more than the rounding error of its corners, so none is missed.
  template <class F>
  void for_each_near(const double* p, double radius, F&& f) const
  {
    double lo[3], hi[3];
    for(int i = 0; i < 3; ++i) {
      const double m = radius * (1 + 1e-9) + 1e-15 * std::abs(p[i]);
      lo[i] = p[i] - m;
      hi[i] = p[i] + m;
    }
    for_each_in_box(lo, hi, f);
  }

  /// calls `f(index, point)` for every point in a cell that meets the box [lo, hi]; may call it for
  /// points outside the box, never misses one inside
  template <class F>
  void for_each_in_box(const double* lo, const double* hi, F&& f) const
  {
    const std::int64_t x0 = cell_of(lo[0]), x1 = cell_of(hi[0]);
    const std::int64_t y0 = cell_of(lo[1]), y1 = cell_of(hi[1]);
    const std::int64_t z0 = cell_of(lo[2]), z1 = cell_of(hi[2]);
    for(std::int64_t x = x0; x <= x1; ++x)
      for(std::int64_t y = y0; y <= y1; ++y)
        for(std::int64_t z = z0; z <= z1; ++z)
          for(Index i = head(x, y, z); i != none; i = next_[i])
            f(i, point(i));
  }

private:
  struct Slot
  {
    std::int64_t x = 0, y = 0, z = 0;
    Index head = none;
  };

  std::int64_t cell_of(double c) const { return std::int64_t(std::floor(c * inv_cell_)); }

  static std::size_t hash(std::int64_t x, std::int64_t y, std::int64_t z)
  {
    std::uint64_t h = std::uint64_t(x) * 0x9E3779B97F4A7C15ull;
    h ^= std::uint64_t(y) * 0xC2B2AE3D27D4EB4Full;
    h ^= std::uint64_t(z) * 0x165667B19E3779F9ull;
    return std::size_t(h ^ (h >> 29));
  }

  Index head(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t k = hash(x, y, z) & mask;; k = (k + 1) & mask) {
      const Slot& s = slots_[k];
      if(s.head == none) return none;
      if(s.x == x && s.y == y && s.z == z) return s.head;
    }
  }

  Slot& find_or_create(std::int64_t x, std::int64_t y, std::int64_t z)
  {
    if(2 * (used_ + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t k = hash(x, y, z) & mask;; k = (k + 1) & mask) {
      Slot& s = slots_[k];
      if(s.head == none) {
        s.x = x; s.y = y; s.z = z;
        ++used_;
        return s;
      }
      if(s.x == x && s.y == y && s.z == z) return s;
    }
  }

  void grow()
  {
    std::vector<Slot> old(2 * slots_.size());
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for(const Slot& s : old) {
      if(s.head == none) continue;
      std::size_t k = hash(s.x, s.y, s.z) & mask;
      while(slots_[k].head != none) k = (k + 1) & mask;
      slots_[k] = s;
    }
  }

  double inv_cell_;
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
  std::vector<double> points_;
  std::vector<Index> next_;
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H
