// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Cell_hash_table.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// Points in a uniform grid of cubic cells, stored sparsely and built once from all the points: the
/// points are sorted by cell, in the lexicographic order of the cells' (x, y, z) indices, so that a
/// cell's points lie next to each other and the cells near a point mostly near its own; an
/// open-addressing hash table maps a cell to its range. Memory is O(points): a surface sample set
/// occupies a vanishing fraction of the cells of its bounding box.
///
/// (A first version kept the points in their given order, a cell's points in a linked list: a query
/// read one random place in memory for each point it found, and `is_poisson_disk_set` took 1.4 s on
/// a million samples of lion.off; 0.55 s sorted.)
class Point_hash_grid
{
public:
  typedef std::uint32_t Index;

  /// The grid of the `n` points (`xyz[3 i]`, `xyz[3 i + 1]`, `xyz[3 i + 2]`), point `i` having index
  /// `i`; `cell_size` > 0.
  /// \throws Invalid_input (from `grid_cell()`) if |coordinate| / cell_size reaches 2^62, or if there
  /// are 2^32 - 1 points or more
  Point_hash_grid(double cell_size, const double* xyz, std::size_t n) : inv_cell_(1. / cell_size)
  {
    CGAL_precondition(cell_size > 0);
    if(n >= std::size_t(Cell_hash_table::none))
      throw Invalid_input("too many points for the grid (at most 2^32 - 2)");
    std::vector<std::int64_t> cell(3 * n);
    for(std::size_t i = 0; i < 3 * n; ++i) cell[i] = cell_of(xyz[i]);
    auto same_cell = [&](std::size_t a, std::size_t b) {
      return cell[3 * a] == cell[3 * b] && cell[3 * a + 1] == cell[3 * b + 1] && cell[3 * a + 2] == cell[3 * b + 2];
    };
    std::vector<Index> order(n);
    for(std::size_t i = 0; i < n; ++i) order[i] = Index(i);
    // the cells' order; by one 64-bit key when the cells span fewer than 2^21 on each axis
    std::int64_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for(int a = 0; a < 3 && n > 0; ++a) {
      lo[a] = hi[a] = cell[std::size_t(a)];
      for(std::size_t i = 1; i < n; ++i) {
        lo[a] = (std::min)(lo[a], cell[3 * i + std::size_t(a)]);
        hi[a] = (std::max)(hi[a], cell[3 * i + std::size_t(a)]);
      }
    }
    const std::uint64_t span = std::uint64_t(1) << 21;
    if(std::uint64_t(hi[0] - lo[0]) < span && std::uint64_t(hi[1] - lo[1]) < span &&
       std::uint64_t(hi[2] - lo[2]) < span) {
      std::vector<std::pair<std::uint64_t, Index>> keyed(n);
      for(std::size_t i = 0; i < n; ++i)
        keyed[i] = {std::uint64_t(cell[3 * i] - lo[0]) << 42 | std::uint64_t(cell[3 * i + 1] - lo[1]) << 21 |
                        std::uint64_t(cell[3 * i + 2] - lo[2]),
                    Index(i)};
      std::sort(keyed.begin(), keyed.end());
      for(std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
    } else {
      std::sort(order.begin(), order.end(), [&](Index a, Index b) {
        const std::int64_t* p = &cell[3 * std::size_t(a)];
        const std::int64_t* q = &cell[3 * std::size_t(b)];
        return std::make_tuple(p[0], p[1], p[2], a) < std::make_tuple(q[0], q[1], q[2], b);
      });
    }
    std::size_t cells = 0;
    for(std::size_t k = 0; k < n; ++k) cells += k == 0 || !same_cell(order[k], order[k - 1]);
    cells_ = Cell_hash_table(cells);
    begin_.reserve(cells + 1);
    points_.resize(3 * n);
    index_.resize(n);
    for(std::size_t k = 0; k < n; ++k) {
      const std::size_t i = order[k];
      if(k == 0 || !same_cell(i, order[k - 1])) {
        cells_.find_or_insert(cell[3 * i], cell[3 * i + 1], cell[3 * i + 2], Index(begin_.size()));
        begin_.push_back(Index(k));
      }
      for(int a = 0; a < 3; ++a) points_[3 * k + std::size_t(a)] = xyz[3 * i + std::size_t(a)];
      index_[k] = Index(i);
    }
    begin_.push_back(Index(n));
  }

  std::size_t size() const { return index_.size(); }
  /// the `k`-th point in the grid's order (by cell)
  const double* point(std::size_t k) const { return &points_[3 * k]; }
  /// the index of the `k`-th point in the grid's order
  Index index(std::size_t k) const { return index_[k]; }

  /// calls `f(index, point)` for every point at distance <= `radius` from `p`, and maybe a few more,
  /// `point` pointing into the grid's own copy (so that two of them compare as their positions in
  /// the grid's order). The query box is widened by more than the rounding error of its corners, so
  /// none is missed. Where `f` returns a `bool`, the query stops at the first point for which it
  /// returns true.
  /// \throws Invalid_input (from `grid_cell()`) if |coordinate| + radius reaches 2^62 cells
  template <class F>
  void for_each_near(const double* p, double radius, F&& f) const
  {
    std::int64_t box[6];
    cell_box(p, radius, box);
    for_each_cell(box, [&](std::size_t first, std::size_t last) {
      for(std::size_t k = first; k < last; ++k)
        if(stops(f, index_[k], &points_[3 * k])) return true;
      return false;
    });
  }

  /// calls `f(k, j, q)` once for each pair of points at distance <= `radius` from each other (and
  /// maybe a few more pairs), where `k` is the place of the first in the grid's order (`point(k)`,
  /// `index(k)`) and `j` and `q` the index and position of the second, which comes after it in that
  /// order: the points in the grid's order, by cell, so that the points near one point are mostly
  /// near the one before. Where `f` returns a `bool`, the pairs stop at the first for which it
  /// returns true.
  template <class F>
  void for_each_pair_near(double radius, F&& f) const
  {
    bool stopped = false;
    for(std::size_t k = 0; k < size() && !stopped; ++k) {
      const double* p = point(k);
      auto pair = [&](Index j, const double* q) { return f(k, j, q); };
      for_each_near(p, radius, [&](Index j, const double* q) { return q > p && (stopped = stops(pair, j, q)); });
    }
  }

  /// Queries that follow each other closely, as the pieces of a surface split depth first: a query
  /// whose box meets the same cells as the one before reads no hash slot. (The certificate of a
  /// million samples of lion.off spent a quarter of its time in the hash table, eight lookups a
  /// piece; an eighth with this, and a fifth less time in all.)
  class Nearby_queries
  {
  public:
    explicit Nearby_queries(const Point_hash_grid& grid) : grid_(grid) {}

    /// as `Point_hash_grid::for_each_near()`, which stops at the first point for which `f` returns
    /// true where it returns a `bool` (the certificate stops at the first ball that holds a piece:
    /// checked at a distance far above the samples' spacing, each piece has millions of samples
    /// within reach, and it took 107 s on 2.5 million samples of lion.off where the first one tested
    /// settles each face)
    template <class F>
    void for_each_near(const double* p, double radius, F&& f)
    {
      std::int64_t box[6];
      grid_.cell_box(p, radius, box);
      if(!valid_ || !std::equal(box, box + 6, box_)) {
        valid_ = false; // until the ranges are complete (push_back may throw)
        ranges_.clear();
        grid_.for_each_cell(box, [&](std::size_t first, std::size_t last) {
          ranges_.push_back({first, last});
          return false;
        });
        std::copy(box, box + 6, box_);
        valid_ = true;
      }
      for(const auto& r : ranges_)
        for(std::size_t k = r.first; k < r.second; ++k)
          if(stops(f, grid_.index_[k], &grid_.points_[3 * k])) return;
    }

  private:
    const Point_hash_grid& grid_;
    bool valid_ = false;
    std::int64_t box_[6];
    std::vector<std::pair<std::size_t, std::size_t>> ranges_; // the points of the box's cells
  };

private:
  std::int64_t cell_of(double c) const { return grid_cell(c, inv_cell_); }

  // the cells x0..x1, y0..y1, z0..z1 of the box of half side `radius` around p, widened by more than
  // the rounding error of its corners
  void cell_box(const double* p, double radius, std::int64_t* box) const
  {
    for(int i = 0; i < 3; ++i) {
      const double m = widened_reach(radius, p[i]);
      box[2 * i] = cell_of(p[i] - m);
      box[2 * i + 1] = cell_of(p[i] + m);
    }
  }

  // calls f(first, last) for the range of points of each non-empty cell of the box; stops where a
  // call returns true
  template <class F>
  void for_each_cell(const std::int64_t* box, F&& f) const
  {
    for(std::int64_t x = box[0]; x <= box[1]; ++x)
      for(std::int64_t y = box[2]; y <= box[3]; ++y)
        for(std::int64_t z = box[4]; z <= box[5]; ++z) {
          const std::uint32_t c = cells_.find(x, y, z);
          if(c != Cell_hash_table::none && f(std::size_t(begin_[c]), std::size_t(begin_[c + 1]))) return;
        }
  }

  // calls f(i, q); whether the query stops there: what f returns where it returns a bool, else false
  template <class F>
  static bool stops(F& f, Index i, const double* q)
  {
    if constexpr(std::is_same<decltype(f(i, q)), bool>::value) {
      return f(i, q);
    } else {
      f(i, q);
      return false;
    }
  }

  double inv_cell_;
  Cell_hash_table cells_;
  std::vector<Index> begin_;   // the first point of each cell, in the grid's order; then the number of points
  std::vector<double> points_; // the points, by cell
  std::vector<Index> index_;   // their indices
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_POINT_HASH_GRID_H
