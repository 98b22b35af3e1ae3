// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_FACE_CLUSTERS_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_FACE_CLUSTERS_H

#include <CGAL/Poisson_disk_sampling_3/internal/power_of_half.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The faces of a surface sorted along a Morton (Z-order) curve of their centroids, for the triangle
/// model's clusters of small faces (see `Triangle_fragment_traits_3`, "Clusters of small faces"). The
/// faces whose centroids lie in one cell of the octree of the curve are consecutive positions, so that
/// a cluster is a range [a, b) of positions, and its children, the cells one level down, are its
/// sub-ranges. Each position has its face, its Morton code, an upper bound of its face's reach (the
/// largest distance from the centroid to a corner) and its face's area as an integer weight, summed in
/// a prefix array, so that a range's area and the draw of a face in proportion to area within it need
/// no sum over the range.
///
/// The codes have 16 bits per axis over a cube whose side is a power of two, so that the cells' sides
/// are exact and the order does not change when the surface is scaled by a power of two. A cell's box
/// is computed in double precision; `slack()` bounds how far a face's computed centroid may lie outside
/// the box of the cell its code names, and the rounding of the box's corners.
class Face_clusters
{
public:
  typedef std::array<double, 3> Point;
  static constexpr int bits = 16; // per axis: codes of 48 bits

  /// builds the index of `n` faces: `face(i, centroid, reach)` writes the centroid and the reach of
  /// face i and returns its area (a face of area 0 is left out). `slack` bounds the rounding of the
  /// centroids and reaches the callable computes (per coordinate).
  template <class Face>
  void build(std::size_t n, const Face& face, double slack)
  {
    // first the entries with their face, reach and area (its bits in `weight`) and the centroids apart,
    // then, once the cube and the unit of weight are known, their codes and weights
    std::vector<Point> centroid;
    std::vector<Entry> keyed;
    centroid.reserve(n), keyed.reserve(n);
    Point lo{{0, 0, 0}}, hi{{0, 0, 0}};
    double total = 0, max_reach = 0;
    for(std::size_t i = 0; i < n; ++i) {
      Point c;
      double r;
      const double a = face(i, c, r);
      if(!(a > 0)) continue;
      for(int j = 0; j < 3; ++j) {
        lo[j] = centroid.empty() ? c[j] : (std::min)(lo[j], c[j]);
        hi[j] = centroid.empty() ? c[j] : (std::max)(hi[j], c[j]);
      }
      float rf = float(r);
      if(double(rf) < r) rf = std::nextafter(rf, std::numeric_limits<float>::infinity());
      std::uint64_t area_bits;
      std::memcpy(&area_bits, &a, sizeof area_bits);
      centroid.push_back(c);
      keyed.push_back(Entry{0, area_bits, std::uint32_t(i), rf});
      total += a;
      max_reach = (std::max)(max_reach, r);
    }
    const std::size_t m = centroid.size();
    // the cube: its side a power of two above the centroids' extent (and above a reach, so that it is
    // positive where all centroids coincide)
    double extent = max_reach, magnitude = 0;
    for(int j = 0; j < 3; ++j) {
      extent = (std::max)(extent, hi[j] - lo[j]);
      magnitude = (std::max)({magnitude, std::abs(lo[j]), std::abs(hi[j])});
    }
    origin_ = lo;
    side_ = extent > 0 ? std::ldexp(1.0, std::ilogb(extent) + 1) : 1.0;
    // c - lo rounds by eps |c - lo|, and the corners of a box, lo + i h, by eps (|lo| + side): the
    // computed centroid lies in its code's box, as computed, up to far less than this
    slack_ = slack + 64 * std::numeric_limits<double>::epsilon() * (magnitude + side_);

    // codes, then a stable radix sort by code (ties in face order)
    const double to_grid = std::ldexp(1.0, bits) / side_; // a power of two: exact
    // weights: areas as integers, in units of 2^-scale, their sum below 2^52 so that a range's sum,
    // converted to double, and u times it are exact to within one unit
    scale_ = total > 0 ? 51 - std::ilogb(total) : 0;
    constexpr int digit = 12, digits = (3 * bits + digit - 1) / digit;
    constexpr std::uint64_t mask = (std::uint64_t(1) << digit) - 1;
    std::vector<std::size_t> count(std::size_t(digits) << digit, 0); // the digits' histograms, in one pass
    for(std::size_t i = 0; i < m; ++i) {
      std::uint64_t q[3];
      for(int j = 0; j < 3; ++j) {
        const double x = (centroid[i][j] - lo[j]) * to_grid;
        q[j] = x <= 0 ? 0 : x >= double((1u << bits) - 1) ? (1u << bits) - 1 : std::uint64_t(x);
      }
      Entry& e = keyed[i];
      e.code = spread(q[0]) << 2 | spread(q[1]) << 1 | spread(q[2]);
      double a;
      std::memcpy(&a, &e.weight, sizeof a);
      e.weight = std::uint64_t(times_power_of_two(a, scale_));
      for(int d = 0; d < digits; ++d) ++count[(std::size_t(d) << digit) + (e.code >> (d * digit) & mask)];
    }
    std::vector<Point>().swap(centroid);
    std::vector<Entry> other(m);
    for(int d = 0; d < digits; ++d) {
      std::size_t* c = &count[std::size_t(d) << digit];
      if(std::find(c, c + (std::size_t(1) << digit), m) != c + (std::size_t(1) << digit)) continue; // one value
      std::size_t sum = 0;
      for(std::size_t k = 0; k < (std::size_t(1) << digit); ++k) {
        const std::size_t x = c[k];
        c[k] = sum, sum += x;
      }
      const int shift = d * digit;
      for(const Entry& k : keyed) other[c[k.code >> shift & mask]++] = k;
      keyed.swap(other);
    }
    std::vector<Entry>().swap(other);

    // in place: each position's weight becomes the sum of the weights before it
    std::uint64_t sum = 0;
    for(Entry& e : keyed) {
      const std::uint64_t w = e.weight;
      e.weight = sum, sum += w;
    }
    entries_.swap(keyed);
    total_weight_ = sum;
  }

  std::size_t size() const { return entries_.size(); }
  std::uint32_t face(std::size_t p) const { return entries_[p].face; }
  std::uint64_t code(std::size_t p) const { return entries_[p].code; }
  float reach(std::size_t p) const { return entries_[p].reach; }
  std::uint64_t weight(std::size_t p) const { return before(p + 1) - before(p); }
  double slack() const { return slack_; }
  void prefetch(std::size_t a) const { internal::prefetch_object(&entries_[a]); }

  /// the area of the faces at positions [a, b), as their weights give it (the same double on every call)
  double area(std::size_t a, std::size_t b) const { return times_power_of_two(double(before(b) - before(a)), -scale_); }

  /// the position in [a, b) whose weight holds u in [0, 1) times the range's weight: a face drawn in
  /// proportion to its weight for u uniform (to within a unit of 2^-52 of the surface's area)
  std::size_t pick(std::size_t a, std::size_t b, double u) const
  {
    const std::uint64_t first = before(a), total = before(b) - first;
    const std::uint64_t x = first + (std::min)(total - 1, std::uint64_t(u * double(total)));
    // the last position p whose weights before it are at most x
    return std::size_t(std::upper_bound(entries_.begin() + std::ptrdiff_t(a) + 1, entries_.begin() + std::ptrdiff_t(b), x,
                                        [](std::uint64_t y, const Entry& e) { return y < e.weight; }) -
                       entries_.begin()) - 1;
  }

  /// the level of the deepest cell that holds positions [a, b), b > a (0 the cube, `bits` a cell of the grid)
  int level(std::size_t a, std::size_t b) const
  {
    const std::uint64_t x = entries_[a].code ^ entries_[b - 1].code;
    return x == 0 ? bits : (3 * bits - bit_length(x)) / 3;
  }

  /// the level of the cells whose side is at most `length`, at most `bits`
  int level_for(double length) const
  {
    int l = 0;
    while(l < bits && std::ldexp(side_, -l) > length) ++l;
    return l;
  }

  /// a ball that holds every face at positions [a, b): around the centre of their cell, of the half
  /// diagonal of its box plus the slack plus `reach` (the faces' largest reach)
  void bounding_ball(std::size_t a, std::size_t b, double reach, Point& centre, double& radius) const
  {
    const int l = level(a, b);
    const double h = times_power_of_two(side_, -l); // (each coverage test of a cluster: no call)
    const std::uint64_t c = entries_[a].code >> (3 * (bits - l));
    for(int j = 0; j < 3; ++j) centre[j] = origin_[j] + (double(gather(c >> (2 - j))) + 0.5) * h;
    radius = (0.8660254037844387 * h + 2 * slack_ + reach) * (1 + 0x1.0p-40);
  }

  /// calls `visit(s, e)` for each cell one level below the deepest cell of [a, b) that holds some of
  /// its positions, in order; for positions that all have one code, `visit(p, p + 1)` for each
  template <class Visit>
  void children(std::size_t a, std::size_t b, const Visit& visit) const
  {
    const int l = level(a, b);
    if(l == bits) {
      for(std::size_t p = a; p < b; ++p) visit(p, p + 1);
      return;
    }
    const int shift = 3 * (bits - l - 1);
    for(std::size_t s = a; s < b;) {
      const std::uint64_t key = entries_[s].code >> shift;
      const std::size_t e = std::size_t(
          std::upper_bound(entries_.begin() + std::ptrdiff_t(s), entries_.begin() + std::ptrdiff_t(b), key,
                           [shift](std::uint64_t k, const Entry& x) { return k < (x.code >> shift); }) -
          entries_.begin());
      visit(s, e);
      s = e;
    }
  }

  /// the largest reach at positions [a, b)
  double max_reach(std::size_t a, std::size_t b) const
  {
    float r = 0;
    for(std::size_t p = a; p < b; ++p) r = (std::max)(r, entries_[p].reach);
    return double(r);
  }

private:
  // the bits of x spread to every third bit
  static std::uint64_t spread(std::uint64_t x)
  {
    x &= (std::uint64_t(1) << bits) - 1;
    x = (x | x << 32) & 0x1F00000000FFFFull;
    x = (x | x << 16) & 0x1F0000FF0000FFull;
    x = (x | x << 8) & 0x100F00F00F00F00Full;
    x = (x | x << 4) & 0x10C30C30C30C30C3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
  }
  // the inverse of spread(): every third bit of x, from bit 0
  static std::uint64_t gather(std::uint64_t x)
  {
    x &= 0x1249249249249249ull;
    x = (x | x >> 2) & 0x10C30C30C30C30C3ull;
    x = (x | x >> 4) & 0x100F00F00F00F00Full;
    x = (x | x >> 8) & 0x1F0000FF0000FFull;
    x = (x | x >> 16) & 0x1F00000000FFFFull;
    x = (x | x >> 32) & ((std::uint64_t(1) << bits) - 1);
    return x;
  }
  static int bit_length(std::uint64_t x) // x > 0
  {
#if defined(__GNUC__) || defined(__clang__)
    return 64 - __builtin_clzll(x);
#else
    int n = 0;
    while(x) x >>= 1, ++n;
    return n;
#endif
  }

  // the sum of the weights of the positions before p, p <= size()
  std::uint64_t before(std::size_t p) const { return p < entries_.size() ? entries_[p].weight : total_weight_; }

  struct Entry // a position (while the index is built, `weight` is its own)
  {
    std::uint64_t code, weight; // its Morton code; the weights of the positions before it
    std::uint32_t face;
    float reach;                // rounded up
  };
  std::vector<Entry> entries_;
  std::uint64_t total_weight_ = 0;
  Point origin_{{0, 0, 0}};
  double side_ = 1, slack_ = 0;
  int scale_ = 0;
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_FACE_CLUSTERS_H
