// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H

#include <CGAL/Poisson_disk_sampling_3/internal/Cell_hash_table.h>

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

  /// `cell_size` > 0. \throws Invalid_input (from `grid_cell()`) if |coordinate| / cell_size reaches 2^62
  explicit Point_hash_grid(double cell_size, std::size_t expected_points = 0)
    : inv_cell_(1. / cell_size), cells_(expected_points / 2)
  {
    CGAL_precondition(cell_size > 0);
    points_.reserve(3 * expected_points);
    next_.reserve(expected_points);
  }

  std::size_t size() const { return next_.size(); }
  const double* point(Index i) const { return &points_[3 * std::size_t(i)]; }

  Index insert(const double* p)
  {
    const Index i = Index(next_.size());
    points_.insert(points_.end(), p, p + 3);
    // a new cell gets i as its head; an old one gets i in front of its list
    std::uint32_t& head = cells_.find_or_insert(cell_of(p[0]), cell_of(p[1]), cell_of(p[2]), i);
    next_.push_back(head == i ? none : head);
    head = i;
    return i;
  }

  /// calls `f(index, point)` for every point at distance <= `radius` from `p`, and maybe a few more.
  /// The query box is widened by more than the rounding error of its corners, so none is missed.
  template <class F>
  void for_each_near(const double* p, double radius, F&& f) const
  {
    double lo[3], hi[3];
    for(int i = 0; i < 3; ++i) {
      const double m = widened_reach(radius, p[i]);
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
          for(Index i = cells_.find(x, y, z); i != none; i = next_[i])
            f(i, point(i));
  }

private:
  std::int64_t cell_of(double c) const { return grid_cell(c, inv_cell_); }

  double inv_cell_;
  Cell_hash_table cells_;
  std::vector<double> points_;
  std::vector<Index> next_;
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H
