// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_NEIGHBOR_BUCKETS_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_NEIGHBOR_BUCKETS_H

#include <CGAL/Poisson_disk_sampling_3/internal/Cell_hash_table.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The engine's samples, organised for the one query it makes per dart: the samples within distance
/// `reach` of a point. Space is cut into cubic cells of side `cell_factor * reach`; each cell keeps,
/// in one contiguous bucket, a copy of every sample within `reach` of the cell, so a query reads one
/// bucket: one hash probe and a sequential scan. (A grid of single copies, as `Point_hash_grid`, has
/// the query visit eight cells, each a hash probe and a range elsewhere in memory: on large sets
/// each is a cache miss.) A sample is copied into the cells that meet the cube of half-side `reach`
/// around it, (1 + 2 / cell_factor)^3 of them on average: memory stays O(samples).
class Neighbor_buckets
{
public:
  typedef std::array<double, 3> Point;

  /// `expected_points` only sizes the hash table at the start
  Neighbor_buckets(double reach, double cell_factor, std::size_t expected_points)
    : reach_(reach), inv_cell_(1. / (cell_factor * reach)), cells_(expected_points / 8)
  {
    CGAL_precondition(reach > 0 && cell_factor >= 2);
  }

  std::size_t size() const { return count_; }

  /// a cell of the grid
  struct Cell
  {
    std::int64_t x, y, z;
  };

  Cell cell(const Point& p) const
  {
    return Cell{grid_cell(p[0], inv_cell_), grid_cell(p[1], inv_cell_), grid_cell(p[2], inv_cell_)};
  }

  /// the bucket of a cell: it holds every sample within `reach` of the cell, and some farther ones;
  /// nullptr if there is no sample near the cell. Valid until the next `insert()`.
  const std::vector<Point>* bucket(const Cell& c) const
  {
    const std::uint32_t b = cells_.find(c.x, c.y, c.z);
    return b == Cell_hash_table::none ? nullptr : &buckets_[b];
  }

  const std::vector<Point>* bucket(const Point& p) const { return bucket(cell(p)); }

  /// The query of a cell makes three dependent memory accesses: the hash slot, the bucket's header,
  /// its points. These start one of them without waiting, so that a batch of queries overlaps them:
  /// `prefetch_slot` before `bucket()`, `prefetch_header` on its result, then `prefetch_points`.
  void prefetch_slot(const Cell& c) const { cells_.prefetch(c.x, c.y, c.z); }
  static void prefetch_header(const std::vector<Point>* bucket)
  {
    if(bucket) internal::prefetch_object(bucket);
  }
  static void prefetch_points(const std::vector<Point>* bucket) { prefetch_lines<&internal::prefetch>(bucket); }
  /// the same into the second-level cache only: for a whole batch's buckets, which overflow the first
  /// level (see `Dart_throwing_engine`)
  static void prefetch_points_to_second_level(const std::vector<Point>* bucket)
  {
    prefetch_lines<&internal::prefetch_to_second_level>(bucket);
  }

  void insert(const Point& q) { insert(&q, &q + 1); }

  /// Inserts the points of [first, last), with the same result as `insert()` on each in turn. A point
  /// goes to three or four buckets on average, each a hash probe and a write at the bucket's end,
  /// all of them cache misses on a large set: here they are made in stages, each of which starts the
  /// memory accesses of the next one for all the points, so that their misses overlap.
  void insert(const Point* first, const Point* last)
  {
    copies_.clear();
    for(const Point* q = first; q != last; ++q) {
      // The cells that meet the box [q - m, q + m]; grid_cell is monotone, so the cell of any p
      // within reach of q is among them.
      std::int64_t lo[3], hi[3];
      for(int i = 0; i < 3; ++i) {
        const double m = widened_reach(reach_, (*q)[i]);
        lo[i] = grid_cell((*q)[i] - m, inv_cell_);
        hi[i] = grid_cell((*q)[i] + m, inv_cell_);
      }
      for(std::int64_t x = lo[0]; x <= hi[0]; ++x)
        for(std::int64_t y = lo[1]; y <= hi[1]; ++y)
          for(std::int64_t z = lo[2]; z <= hi[2]; ++z) {
            copies_.push_back(Copy{Cell{x, y, z}, q, 0});
            cells_.prefetch(x, y, z);
          }
    }
    // buckets are made in the order of the copies, as one insert() after the other makes them
    for(Copy& c : copies_) {
      // (a bucket's number is 32 bits, and 2^32 - 1 means none: at most 27 cells a sample, so more
      // than 1.5 10^8 samples, far above the default bound)
      if(buckets_.size() >= std::size_t(Cell_hash_table::none))
        throw Point_limit_exceeded("more than 2^32 - 2 cells hold samples (more than 1.5 10^8 samples)");
      c.bucket = cells_.find_or_insert(c.cell.x, c.cell.y, c.cell.z, std::uint32_t(buckets_.size()));
      if(c.bucket == buckets_.size()) buckets_.emplace_back();
      prefetch_header(&buckets_[c.bucket]);
    }
    for(const Copy& c : copies_) {
      const std::vector<Point>& b = buckets_[c.bucket];
      if(b.size() < b.capacity()) internal::prefetch(b.data() + b.size());
      else prefetch_points(&b); // a full bucket is moved to a larger array: every line is read
    }
    for(const Copy& c : copies_) {
      // a bucket grows by a quarter, not by doubling: the buckets' free room is the largest part of
      // the sampler's memory that is not data (sampling_only/NAME/N: 20 bytes a point less on lion.off
      // and pipe.off), and the copies this adds are a few hundred bytes a sample. It starts with
      // room for one point, then two, then four: where samples lie far apart (the first runs of a
      // `number_of_points` search on strips far narrower than the distance), most buckets hold
      // one copy, and room for four took 112 bytes of the heap for each (those runs' peak 28% lower)
      std::vector<Point>& b = buckets_[c.bucket];
      if(b.size() == b.capacity())
        b.reserve(b.size() < 2 ? b.size() + 1 : b.size() < 4 ? 4 : b.size() + (b.size() + 3) / 4);
      b.push_back(*c.point);
    }
    count_ += std::size_t(last - first);
  }

private:
  template <void (*ask)(const void*)>
  static void prefetch_lines(const std::vector<Point>* bucket)
  {
    if(!bucket) return;
    // every cache line of the bucket (20 points, 8 lines on average), up to 16: a bucket is too
    // short for the hardware's prefetcher to follow its scan. Against the first two lines only: 22 ns
    // less per dart at one million points (bench_stages, stages points + scan, five alternating runs)
    std::uintptr_t line = reinterpret_cast<std::uintptr_t>(bucket->data()) & ~std::uintptr_t(63);
    const std::uintptr_t end =
        (std::min)(reinterpret_cast<std::uintptr_t>(bucket->data() + bucket->size()), line + 16 * 64);
    for(; line < end; line += 64) ask(reinterpret_cast<const void*>(line));
  }

  // a copy of a point to write into the bucket of a cell
  struct Copy
  {
    Cell cell;
    const Point* point;
    std::uint32_t bucket;
  };

  std::vector<Copy> copies_; // scratch of insert()
  double reach_, inv_cell_;
  Cell_hash_table cells_;
  std::vector<std::vector<Point>> buckets_;
  std::size_t count_ = 0;
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_NEIGHBOR_BUCKETS_H
