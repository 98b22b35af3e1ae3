// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_TRIANGLE_FRAGMENT_TRAITS_3_H
#define CGAL_POISSON_DISK_SAMPLING_3_TRIANGLE_FRAGMENT_TRAITS_3_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Face_clusters.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Triangle_in_ball_union.h>
#include <CGAL/Poisson_disk_sampling_3/internal/power_of_half.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Concepts
/// \cgalModels `SurfaceFragmentTraits_3`
///
/// Triangles as surface fragments (paper Section 4). The surface is a set of triangles added with
/// `add_triangle()`; the fragments are triangles of a root piece's parameter space: the sub-triangles
/// of its regular 4-to-1 midpoint subdivision, and the pieces that `refine()` leaves when it cuts off
/// along a chord what one ball holds (see "Chord cuts" below). A root piece is a whole face, or, for a
/// long thin face and a given minimum distance D, one of the rows' triangles of the blocks that
/// `initial_fragments(out, D)` writes for it; the blocks (trapezoids: `is_block()`) are fragments too
/// (see "Long thin triangles" below). A fragment is stored as its face, its piece, one corner
/// in the piece's parameter space and the other two as integer offsets from it in units of 2^-level
/// (32 bytes); the face is V0 + u (V1 - V0) + v (V2 - V0), and pieces have corners at dyadic (u, v),
/// so that the corners of fragments have exact dyadic parameters (see `level()`).
/// Each triangle is rotated to start at its lexicographically smallest corner, so that the samples
/// do not depend on which corner a mesh data structure lists first (`Surface_mesh` and `Polyhedron_3`
/// give the same points); they do depend on the order of the triangles and on the orientation of each
/// (its corners' cyclic order); `barycentric_coordinates()` maps back to the order in which the
/// corners were given.
///
/// Long thin triangles: subdivision keeps a triangle's shape, so a face L long and w wide would be cut
/// into slivers as thin as the face, about (L / D)^2 of them around a face narrower than D. With a
/// minimum distance D, such faces are therefore cut into rows, with dyadic parameters so that the
/// pieces tile the face exactly:
/// - a face whose largest angle is below 120 degrees (a needle: one short edge, two long ones) into
///   2^k rows parallel to its shortest edge, each row a trapezoid cut into two triangles, the last
///   row (at the far corner) a triangle: 2^(k+1) - 1 pieces;
/// - a face with an angle of 120 degrees or more (a cap, its corners nearly in line) first into two
///   needles, by a segment from the obtuse corner to a multiple of 2^-k of the opposite edge nearest
///   the foot of the altitude, then each needle into rows.
///
/// With w the face's shortest edge (a needle) or its height over its longest edge (a cap), L its
/// longest edge, and 2^k the largest power of two up to L / max(D, w) (at most 2^12), the rows are
/// one to two times max(D, w) long (up to four times in a cap) where L < 2^13 max(D, w); a face longer
/// than that has 2^12 rows, longer (see the user manual, "Long thin triangles"). A face with
/// L < 4 max(D, w) stays whole: cutting it would save fewer darts than the pieces cost (lion.off at a
/// million points is as
/// fast either way).
///
/// The rows are made as darts reach them: `initial_fragments(out, D)` writes one fragment per needle,
/// the block of all its rows (its one row's triangle if it has one row), a trapezoid between two row
/// lines. A block that gets a dart and that no ball holds is split into its halves, the blocks of
/// the first and of the last half of its rows, and a block of two rows into the rows' triangles, so
/// that the fragments follow the darts instead of the faces' length over D. The halves of a block
/// get the single-ball test only: they are long, and the union test, cubic in the balls that meet
/// them, cost more than the darts it saved (blade.off at 10,000 points: 9.7 darts a point instead of
/// 15.2, but 0.087 s instead of 0.064). Longest-edge bisection, which would keep every fragment a
/// triangle, cuts a needle along its length as often as across it, and was slower still (see
/// `benchmark/README.md`, change 43).
///
/// Chord cuts (the paper's Section 7 clips along an approximate dart boundary, cutting off free
/// surface; these cuts cut off only what a ball provably holds, see design.md, "Chord cuts"): when a
/// dart finds a fragment at most 4 D across partly covered, and a ball of `near` holds one or two of
/// its corners, `refine()` cuts off the part of the fragment that the ball holds, up to the chord
/// between two points of its edges: a triangle at one corner, or a quadrilateral along an edge. The
/// chord's ends are multiples of 1/64 of their edges (of a coarser fraction where the fragment's
/// lattice is already much finer than its size, see `level()`), moved towards the ball's corners until
/// their computed points are in the ball with the margin of `is_covered()`; the part cut off, the
/// convex hull of points in the ball, is covered. When the ball that takes the most takes at least a
/// quarter of the fragment, what is left (a triangle, or a quadrilateral as two triangles) replaces the
/// fragment's four children, after the same single-ball and union tests. Its corners are exact points
/// of a lattice up to 2^-6 finer than the fragment's (made as coarse as they allow), and it is refined
/// like any fragment, by midpoint subdivision or by another cut. The darts then follow the free part of
/// a fragment instead of the quarters of a subdivision: on lion.off at about one million points, 6.2
/// darts per sample instead of 8.0, and 1.87 fragments active per sample at the peak instead of 2.34
/// (see `benchmark/README.md`, change 38).
///
/// Clusters of small faces: where the faces are much smaller than D (their mean area at most D^2 / 64,
/// at least half of them reaching at most D / 4 from their centroid, and at least 64 faces of positive
/// area), a dart per face would cost hundreds of darts a sample, each finding its face covered.
/// `initial_fragments(out, D)` then
/// writes clusters: the faces whose reach (the largest distance from the centroid to a corner) is at
/// most D / 4, and whose centroids lie in one cell of an octree at most D / 2 wide, sorted along a
/// Morton curve (`internal/Face_clusters.h`, made once and shared by copies of the model). A dart on
/// a cluster (`is_cluster()`) draws one of its faces in proportion to its area (to within 2^-20 of it:
/// the areas are integers in units of 2^-52 of the surface's), then a point on it. A ball holds a
/// cluster when it holds a ball around the cell's centre that holds every face of it (the cell's half
/// diagonal, plus the faces' largest reach, plus a bound on rounding); `refine()` and `split()` give a
/// cluster's children, the cells one level down (a face alone as its whole face), and the union test
/// is not tried on clusters. The other faces are roots as above. The index costs a sort of the faces,
/// made the first time a distance needs it (see design.md, "Clusters of small faces").
///
/// `sample_triangle_mesh()` and `sample_polygon_soup()` build this model; use it directly with
/// `sample_surface()` to sample triangles from another source.
class Triangle_fragment_traits_3
{
public:
  /// \name Types
  /// @{

  /// a point, as the engine computes with it
  typedef std::array<double, 3> Point;

  /// a triangle of one root piece of a face: corners (u, v), (u, v) + 2^-level e[0] and
  /// (u, v) + 2^-level e[1] in the piece's parameter space
  struct Fragment
  {
    double u;                      ///< corner 0 in the piece's parameter space
    double v;                      ///< (for a whole face, the face's (u, v))
    std::uint32_t face;            ///< index of the face, in the order of `add_triangle()`
    std::uint32_t level : 6;       ///< the lattice of the corners: multiples of 2^-level
    std::uint32_t piece : 25;      ///< which root piece of the face; 0 for the whole face
    std::int16_t e[2][2];          ///< corners 1 and 2 from corner 0, in units of 2^-level
  };

  /// a sample: its point and where it lies
  struct Sample
  {
    Point point;          ///< the sample
    std::uint32_t face;   ///< index of the face, in the order of `add_triangle()`
    double u;             ///< parameter along the first edge of the rotated face (see `barycentric_coordinates()`)
    double v;             ///< parameter along the last edge of the rotated face
  };

  /// @}

  /// adds the triangle (`q0`, `q1`, `q2`) and returns its face index; a triangle of zero area is
  /// kept (so that face indices follow the input) but has no fragment.
  /// \throws Invalid_input if a coordinate is not finite, or if the area is above the largest double
  std::uint32_t add_triangle(const Point& q0, const Point& q1, const Point& q2)
  {
    const std::size_t i = faces_.size();
    return add_triangle(q0, q1, q2, [i] { return "triangle " + std::to_string(i); });
  }

  /// the same, with the messages of its exceptions naming the triangle by `name()`, a callable that
  /// returns a `std::string` (called only to throw): "face 7 of the mesh" rather than "triangle 7"
  template <class Name>
  std::uint32_t add_triangle(const Point& q0, const Point& q1, const Point& q2, const Name& name)
  {
    const Point* q[3] = {&q0, &q1, &q2};
    for(const Point* p : q)
      for(double c : *p)
        if(!std::isfinite(c)) throw Invalid_input(std::string(name()) + " has a coordinate that is not finite");
    if(faces_.size() >= std::numeric_limits<std::uint32_t>::max())
      throw Invalid_input("too many triangles (at most 2^32 - 1)");
    Face f;
    Point thin_normal{{0, 0, 0}};
    f.first = std::uint8_t(q1 < q0 ? (q2 < q1 ? 2 : 1) : (q2 < q0 ? 2 : 0));
    const Point& p0 = *q[f.first];
    const Point& p1 = *q[(f.first + 1) % 3];
    const Point& p2 = *q[(f.first + 2) % 3];
    f.v0 = p0;
    double scale = 0;
    for(int i = 0; i < 3; ++i) {
      f.e1[i] = p1[i] - p0[i];
      f.e2[i] = p2[i] - p0[i];
      scale = (std::max)(scale, std::abs(p0[i]) + std::abs(f.e1[i]) + std::abs(f.e2[i]));
    }
    f.area = face_area(f.e1, f.e2);
    if(f.area == 0) {
      // The edges as rounded are on one line, but the corners may not be: a face about 1e-16 of its
      // length wide, or less, whose corners differ in magnitude (corners (0, 1), (1, 2^-60) and
      // (2, -1), 2.8 long and 9e-19 wide, were skipped by the sampler and by the certificate, which
      // called a set maximal that left the face 13 from every sample). Its computed points lie
      // within position_error() of it, as for any face; its area and its normal come from the
      // corners (the area at least the smallest positive double), the normal kept aside.
      double area = 0;
      thin_normal = exact_unit_normal(p0, p1, p2, area);
      if(area > 0) f.area = area;
    }
    if(!(f.area <= (std::numeric_limits<double>::max)()))
      throw Invalid_input(std::string(name()) + " has an area above the largest double; scale the input");
    classify(f);
    // corners V0 + u E1 + v E2 are off the exact sub-triangle by less than this, per coordinate (a face
    // of zero area is neither sampled nor certified: its coordinates do not limit the distance)
    if(f.area > 0)
      position_error_ = (std::max)(position_error_, 4 * std::numeric_limits<double>::epsilon() * scale);
    faces_.push_back(f);
    if(f.area > 0) {
      ++positive_faces_, area_sum_ += f.area;
      count_reach(f);
    }
    if(clusters_.use_count() != 1 || clusters_->built) clusters_ = std::make_shared<Clusters>();
    if(thin_normal[0] != 0 || thin_normal[1] != 0 || thin_normal[2] != 0)
      thin_face_normals_.emplace_back(std::uint32_t(faces_.size() - 1), thin_normal);
    return std::uint32_t(faces_.size() - 1);
  }

  /// makes room for `n` triangles in all, so that adding them does not move the ones added before
  void reserve(std::size_t n) { faces_.reserve(n); }

  /// number of triangles added
  std::size_t number_of_triangles() const { return faces_.size(); }

  /// area of a triangle
  double triangle_area(std::uint32_t face) const { return faces_[face].area; }

  /// barycentric coordinates of a sample with respect to its triangle's corners, in the order they
  /// were given to `add_triangle()`
  std::array<double, 3> barycentric_coordinates(const Sample& s) const
  {
    const int k = faces_[s.face].first;
    std::array<double, 3> w;
    w[k] = 1 - s.u - s.v;
    w[(k + 1) % 3] = s.u;
    w[(k + 2) % 3] = s.v;
    return w;
  }

  /// unit normal of a triangle (right-hand rule on its vertex order), or the zero vector if it has no
  /// area; computed on the edges scaled to unit size, so that a triangle 1e-160 wide, whose cross
  /// product underflows, has one too, and from the corners in exact arithmetic for a triangle whose
  /// edges, as rounded, are on one line
  Point triangle_normal(std::uint32_t face) const
  {
    const Face& f = faces_[face];
    int k;
    Point n = scaled_cross(f.e1, f.e2, k);
    const double l = length(n);
    if(l > 0) {
      for(double& c : n) c /= l;
    } else if(f.area > 0) {
      const auto it = std::lower_bound(thin_face_normals_.begin(), thin_face_normals_.end(), face,
                                       [](const std::pair<std::uint32_t, Point>& e, std::uint32_t i) {
                                         return e.first < i;
                                       });
      if(it != thin_face_normals_.end() && it->first == face) n = it->second;
    }
    return n;
  }

  /// \name Operations of SurfaceFragmentTraits_3
  /// @{

  /// a bound on the distance between a computed point of a triangle and the exact one
  double position_error() const { return position_error_; }

  /// writes one fragment per triangle of positive area: the whole triangle
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out) const
  {
    for(std::uint32_t i = 0; i < faces_.size(); ++i)
      if(faces_[i].area > 0) *out++ = make_fragment(i, 0);
    return out;
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the root pieces for the minimum distance
  /// `minimum_distance`, which tile the triangles of positive area: whole triangles, for the long
  /// thin ones one or two blocks of rows (see "Long thin triangles"), at most two per triangle, and
  /// where the faces are much smaller than the distance, clusters of them (see "Clusters of small
  /// faces"). The engine and the maximality certificate use it.
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out, double minimum_distance) const
  {
    const internal::Face_clusters* c = clusters_for(minimum_distance);
    if(c == nullptr) {
      for(std::uint32_t i = 0; i < faces_.size(); ++i)
        if(faces_[i].area > 0) face_roots(i, minimum_distance, out);
      return out;
    }
    // in the order of the curve: runs of faces that can be clustered, in one cell of the root level,
    // and the other faces one by one
    const double max_reach = cluster_reach * minimum_distance;
    const int shift = 3 * (internal::Face_clusters::bits - c->level_for(cluster_side * minimum_distance));
    auto clustered = [&](std::size_t p) { return double(c->reach(p)) <= max_reach && c->weight(p) >= cluster_weight; };
    for(std::size_t a = 0; a < c->size();) {
      if(!clustered(a)) {
        face_roots(c->face(a), minimum_distance, out);
        ++a;
        continue;
      }
      std::size_t b = a + 1;
      while(b < c->size() && clustered(b) && (c->code(b) >> shift) == (c->code(a) >> shift)) ++b;
      *out++ = cluster(a, b, c->max_reach(a, b));
      a = b;
    }
    return out;
  }

  /// whether `f` is a block of rows of a long thin face (a trapezoid, see "Long thin triangles") rather
  /// than a triangle
  static bool is_block(const Fragment& f) { return (f.piece >> 20 & 15) != 0; }

  /// whether `f` is a cluster of small faces (see "Clusters of small faces") rather than a triangle
  static bool is_cluster(const Fragment& f) { return f.piece == cluster_piece; }

  /// area of a fragment: its face's times the share of its piece and of its triangle in the piece
  /// (a child of the subdivision has a quarter of its parent's)
  double area(const Fragment& f) const
  {
    if(is_cluster(f)) return clusters().area(f.face, cluster_end(f));
    const Face& face = faces_[f.face];
    const double det = double(f.e[0][0]) * f.e[1][1] - double(f.e[1][0]) * f.e[0][1];
    double a = face.area * std::abs(det) * internal::power_of_half(2 * std::size_t(f.level));
    if(f.piece != 0) a *= piece_share(face, f.piece);
    // A fragment of a triangle of positive area, and of positive area itself (det != 0), must stay in
    // the pool until it is covered, however small the double of its area: on a sliver, a fragment
    // 1e-3 long and 1e-320 wide has an area below the doubles, and dropping it as a fragment of zero
    // area left a part of the sliver 1e-3 long uncovered. The smallest positive double stands in for
    // it: such a fragment gets its darts after the others, which is what an area that small means.
    if(a > 0 || det == 0 || !(face.area > 0)) return a;
    return std::numeric_limits<double>::denorm_min();
  }

  /// a point uniformly distributed on the fragment, never refused
  template <class RandomGenerator>
  std::optional<Sample> random_sample(const Fragment& f, RandomGenerator& rng) const
  {
    if(is_cluster(f)) { // a face in proportion to its area, then a point on it
      const internal::Face_clusters& c = clusters();
      return random_sample(make_fragment(c.face(c.pick(f.face, cluster_end(f), rng.uniform())), 0), rng);
    }
    double a = rng.uniform(), b = rng.uniform();
    if(is_block(f)) return block_point(f, a, b);
    if(a + b > 1) { a = 1 - a; b = 1 - b; }
    const double w = unit(f);
    std::array<double, 2> uv{{f.u + w * (a * f.e[0][0] + b * f.e[1][0]), f.v + w * (a * f.e[0][1] + b * f.e[1][1])}};
    if(f.piece != 0) uv = frame(faces_[f.face], f.piece)(uv[0], uv[1]);
    Sample s;
    s.face = f.face;
    s.u = uv[0];
    s.v = uv[1];
    s.point = at(faces_[f.face], s.u, s.v);
    return s;
  }

  /// the point of a sample
  const Point& point(const Sample& s) const { return s.point; }

  /// the centroid of the fragment; of a cluster, the centroid of its middle face
  Point reference_point(const Fragment& f) const
  {
    if(is_cluster(f)) return reference_point(make_fragment(clusters().face((f.face + cluster_end(f)) / 2), 0));
    if(is_block(f)) return block_point(f, 0.5, 0.5).point;
    const double w = unit(f);
    std::array<double, 2> uv{{f.u + w * (f.e[0][0] + f.e[1][0]) / 3, f.v + w * (f.e[0][1] + f.e[1][1]) / 3}};
    if(f.piece != 0) uv = frame(faces_[f.face], f.piece)(uv[0], uv[1]);
    return at(faces_[f.face], uv[0], uv[1]);
  }

  /// true only if the three corners (a block's four) are within `radius` of `center` by more than their
  /// rounding error, so that the exact sub-triangle (or trapezoid) lies in the ball (computed relative
  /// to the face's first corner: see `local_error()`)
  bool is_covered(const Fragment& f, const Point& center, double radius) const
  {
    if(is_cluster(f)) return cluster_is_covered(f, center, radius);
    const Face& face = faces_[f.face];
    // negative: no squared distance is below it
    const double r2 = covering_squared_radius(radius, local_error(face, radius));
    const Point o = relative(center, face.v0);
    if(is_block(f)) {
      const Block b(face, f.piece);
      for(int j = 0; j < 4; ++j)
        if(!(squared_distance(b.point(face, j), o) <= r2)) return false;
      return true;
    }
    const std::array<Point, 3> c = local_corners(f);
    return squared_distance(c[0], o) <= r2 && squared_distance(c[1], o) <= r2 && squared_distance(c[2], o) <= r2;
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: true only if the union of the balls of radius
  /// `radius` around `centers` holds the fragment, proven with a bound on every rounding error (see
  /// `internal/Triangle_in_ball_union.h`). Covers the fragments that straddle the boundary between
  /// two balls, which no single ball holds. A block is tested as its two triangles.
  template <class PointRange>
  bool is_covered_by_union(const Fragment& f, const PointRange& centers, double radius) const
  {
    if(is_cluster(f)) return false; // (split, its faces get the test)
    const Face& face = faces_[f.face];
    // local_error() bounds each coordinate; twice it bounds the distance
    const double error = 2 * local_error(face, radius);
    typedef internal::Triangle_in_ball_union Union;
    if(is_block(f)) { // its triangles (p_a, q_a, p_b) and (q_a, q_b, p_b), the second empty at the end
      const Block b(face, f.piece);
      const Point t0[3] = {b.point(face, 0), b.point(face, 1), b.point(face, 3)};
      const Point t1[3] = {b.point(face, 1), b.point(face, 2), b.point(face, 3)};
      return Union::covers(t0, centers, radius, error, face.v0) &&
             (b.tip || Union::covers(t1, centers, radius, error, face.v0));
    }
    const std::array<Point, 3> c = local_corners(f);
    const Point corner[3] = {c[0], c[1], c[2]};
    return Union::covers(corner, centers, radius, error, face.v0);
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the depth of the fragment, counted from its whole
  /// face, by its size: the largest L such that its area is at most 4^-L times its root piece's, plus
  /// k for a piece (a row is about 2^-k of the face's length; 0 for a whole face). For the children
  /// of midpoint subdivision, the level of the corners' lattice plus k. For a block of 2^m rows,
  /// k - m: one more for each halving, k for the rows' triangles.
  /// A chord cut puts its pieces on a lattice up to 6 levels finer than their size alone would need
  /// (the cut points are multiples of 1/64 of their edges): the lattice level exceeds the depth by
  /// `lattice_excess()`, which `refine()` keeps at most 12 (less the bits of a cap's rows), so that
  /// a fragment can always be split down to the engine's floor, depth 40, with its corners' parameters
  /// exact in double precision (52 bits). Below it, in the maximality certificate's last levels, a
  /// parameter is off by a few 2^-53 at most, which moves a corner by a few units in the last place
  /// of the face's extent, within the margin of `is_covered()`.
  int level(const Fragment& f) const
  {
    if(is_cluster(f)) return 0;
    if(is_block(f)) return piece_k(f) - Piece(f.piece).m;
    return int(f.level) + piece_k(f) - lattice_excess(f);
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: starts loading what `random_sample(f, rng)`
  /// reads (the face's record) into the cache, without waiting. A hint: it changes no result.
  void prefetch(const Fragment& f) const
  {
    if(is_cluster(f)) return clusters().prefetch(f.face);
    internal::prefetch_object(&faces_[f.face]); // 88 bytes: two or three cache lines
  }

  /// the four children of the midpoint subdivision; for a block, its halves (see the class description)
  template <class OutputIterator>
  OutputIterator split(const Fragment& f, OutputIterator out) const
  {
    CGAL_precondition(f.level < 63);
    if(is_cluster(f)) {
      cluster_children(f, [&](std::size_t a, std::size_t b, double reach) { *out++ = cluster(a, b, reach); });
      return out;
    }
    if(is_block(f)) {
      Fragment halves[4];
      const int n = block_halves(f, halves);
      return std::copy(halves, halves + n, out);
    }
    for(int c = 0; c < 4; ++c) *out++ = child(f, c);
    return out;
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the engine's step for a fragment that got a dart.
  /// Returns `true` if one point of `near` covers `f`, as `is_covered()` decides it (and writes
  /// nothing). Otherwise cuts off what one ball holds along a chord (see "Chord cuts" above), or, if
  /// no ball takes a quarter of `f`, splits it as `split()` does; and writes the pieces or children
  /// that neither one point of `near` nor the union of the balls around `around` covers, as
  /// `is_covered()` and `is_covered_by_union()` decide it (a block's halves, the first test only).
  /// The points the triangles share are computed once, and each ball is tested against each of them
  /// once; the union test gets only the balls that can meet `f`.
  template <class PointRange, class OutputIterator>
  bool refine(const Fragment& f, const PointRange& near, const PointRange& around, double radius,
              OutputIterator children) const
  {
    if(f.piece == 0) return refine(f, Whole_face(), near, around, radius, children);
    if(is_cluster(f)) { // (a face alone is tested as the cluster of its own cell: no read of its record)
      if(covers_range(near, f.face, cluster_end(f), f.v, radius)) return true;
      cluster_children(f, [&](std::size_t a, std::size_t b, double reach) {
        if(!covers_range(near, a, b, reach, radius)) *children++ = cluster(a, b, reach);
      });
      return false;
    }
    if(is_block(f)) return refine_block(f, near, radius, children);
    return refine(f, frame(faces_[f.face], f.piece), near, around, radius, children);
  }

  /// @}

private:
  // Clusters of small faces (see the class description): faces whose reach (the largest distance from
  // the centroid to a corner) is at most a quarter of D are clustered, in cells of the root level at
  // most D / 2 across, where the faces' mean area is at most D^2 / 64 and at least half of them reach at
  // most D / 4 (counted by powers of two, reach_count_; long thin faces of small area do not cluster,
  // and the index is not made for them); faces of less than 2^20 units
  // of their weight (2^-32 of the surface's area) stay single, so that a weight rounds by at most 2^-20
  // of it.
  static constexpr double cluster_reach = 0.25, cluster_side = 0.5, cluster_mean_area = 1.0 / 64;
  static constexpr std::uint64_t cluster_weight = std::uint64_t(1) << 20;
  static constexpr std::uint32_t cluster_piece = std::uint32_t(1) << 24; // piece of a cluster
  // A cluster: its positions [face, u) in the index, and v the largest reach of its faces.
  static Fragment make_cluster(std::size_t a, std::size_t b, double reach)
  {
    Fragment f = make_fragment(std::uint32_t(a), cluster_piece);
    f.u = double(b);
    f.v = reach;
    f.e[0][0] = f.e[1][1] = 0;
    return f;
  }
  static std::size_t cluster_end(const Fragment& f) { return std::size_t(f.u); }
  // the faces at positions [a, b) of the index: a cluster, or a face alone as its whole face
  Fragment cluster(std::size_t a, std::size_t b, double reach) const
  {
    return b - a == 1 ? make_fragment(clusters().face(a), 0) : make_cluster(a, b, reach);
  }
  const internal::Face_clusters& clusters() const { return clusters_->index; }

  // the index of the clusters if the faces are small enough at distance d to cluster them (made then)
  const internal::Face_clusters* clusters_for(double d) const
  {
    if(!clusters_ || positive_faces_ < 64 || !(area_sum_ <= cluster_mean_area * d * d * double(positive_faces_)) ||
       2 * faces_within_reach(cluster_reach * d) < positive_faces_)
      return nullptr;
    Clusters& c = *clusters_;
    std::call_once(c.once, [this, &c] {
      c.index.build(
          faces_.size(),
          [this](std::size_t i, Point& centroid, double& reach) {
            const Face& f = faces_[i];
            // the centroid rounds by eps of |v0| + the face's extent, which position_error() bounds
            // (the index's slack)
            Point g;
            reach = face_reach(f, g);
            for(int j = 0; j < 3; ++j) centroid[j] = f.v0[j] + g[j];
            return f.area;
          },
          2 * position_error_);
      c.built = true;
    });
    return &c.index;
  }

  // true only if the ball of `radius` around `center` holds the ball that holds the cluster's faces,
  // rounding included
  bool cluster_is_covered(const Fragment& f, const Point& center, double radius) const
  {
    const Point* c = &center;
    return covers_range(Points_view{c, c + 1}, f.face, cluster_end(f), f.v, radius);
  }
  // true only if the ball of `radius` around some point of `centers` holds the ball that holds the
  // faces at positions [a, b) of the index, whose reach is at most `reach`, rounding included
  template <class PointRange>
  bool covers_range(const PointRange& centers, std::size_t a, std::size_t b, double reach, double radius) const
  {
    const internal::Face_clusters& c = clusters();
    Point m;
    double r;
    c.bounding_ball(a, b, reach, m, r);
    const double room = radius - r - 4 * c.slack();
    if(!(room > 0)) return false;
    const double room2 = room * room * (1 - 16 * std::numeric_limits<double>::epsilon());
    for(const auto& x : centers)
      if(squared_distance(x, m) <= room2) return true;
    return false;
  }

  // calls visit(a, b, reach) with the positions [a, b) of each child of a cluster, the cells one level
  // down, and their faces' largest reach (see cluster())
  template <class Visit>
  void cluster_children(const Fragment& f, const Visit& visit) const
  {
    const internal::Face_clusters& c = clusters();
    c.children(f.face, cluster_end(f), [&](std::size_t a, std::size_t b) { visit(a, b, c.max_reach(a, b)); });
  }

  // writes the roots of face i at distance d: the whole face, or its blocks of rows (see "Long thin
  // triangles")
  template <class OutputIterator>
  void face_roots(std::uint32_t i, double d, OutputIterator& out) const
  {
    const Face& f = faces_[i];
    const int k = cut_level(f, d);
    if(k == 0) {
      *out++ = make_fragment(i, 0);
      return;
    }
    for(int kind = f.cap ? 2 : 1; kind <= (f.cap ? 3 : 1); ++kind) {
      double P[2], Q[2], R[2];
      const int rows_log2 = needle(f, kind, k, P, Q, R);
      if(rows_log2 < 0) continue; // the cap's split point is a corner: no second needle
      // the block of all its rows, or its one row (the last row is one triangle)
      *out++ = make_fragment(i, piece_code(kind, k, 0, 0, rows_log2));
    }
  }

  // the k of f's piece: its rows are 2^k (a cap's split point a multiple of 2^-k); 0 for a whole face
  static int piece_k(const Fragment& f) { return f.piece == 0 ? 0 : Piece(f.piece).k; }

  // How many levels f's lattice is finer than its size needs: ceil(log2 |det e| / 2), for the cells of
  // its lattice that f spans, |det e| / 2 (0 for the children of midpoint subdivision, whose offsets
  // are their root's). level() is the lattice level less this: the floor of log4 of the area ratio.
  static int lattice_excess(const Fragment& f)
  {
    const std::int64_t det = std::int64_t(f.e[0][0]) * f.e[1][1] - std::int64_t(f.e[1][0]) * f.e[0][1];
    const std::uint64_t cells = std::uint64_t(det < 0 ? -det : det); // below 2^31: offsets of 16 bits
    return cells <= 1 ? 0 : (floor_log2(std::uint32_t(cells - 1)) + 2) / 2;
  }

  // the parameters of corner j of f, exactly (dyadic, within the bits of its level)
  static std::array<double, 2> corner_uv(const Fragment& f, int j)
  {
    if(j == 0) return {{f.u, f.v}};
    const double w = unit(f);
    return {{f.u + w * f.e[j - 1][0], f.v + w * f.e[j - 1][1]}};
  }

  // child c of the midpoint subdivision: 0 at corner 0, 1 at corner 1, 2 at corner 2, 3 the middle
  // one, flipped; its lattice is one level finer, and its offsets are f's (negated for the middle one)
  static Fragment child(const Fragment& f, int c)
  {
    CGAL_precondition(f.level < 63);
    Fragment r = f;
    r.level = (f.level + 1) & 63u;
    const double w = 0.5 * unit(f);
    if(c == 1 || c == 3) r.u += w * f.e[0][0], r.v += w * f.e[0][1];
    if(c == 2 || c == 3) r.u += w * f.e[1][0], r.v += w * f.e[1][1];
    if(c == 3)
      for(auto& e : r.e) e[0] = std::int16_t(-e[0]), e[1] = std::int16_t(-e[1]);
    return r;
  }

  // the fragment with corners q0, q1, q2 on the lattice of level l (each coordinate a multiple of
  // 2^-l), in the coarsest lattice that holds them; false if the offsets do not fit
  static bool make_piece(const double (&q)[3][2], int l, std::uint32_t face, std::uint32_t piece, Fragment& r)
  {
    // in units of 2^-l, all integers below 2^53 in magnitude (l <= 52, parameters in [0, 1])
    const double scale = double(std::uint64_t(1) << l);
    std::int64_t e[2][2];
    std::uint64_t bits = std::uint64_t(std::int64_t(q[0][0] * scale)) | std::uint64_t(std::int64_t(q[0][1] * scale));
    for(int j = 0; j < 2; ++j)
      for(int i = 0; i < 2; ++i) {
        const double x = (q[j + 1][i] - q[0][i]) * scale;
        if(!(std::abs(x) < 0x1.0p52)) return false; // (an int64_t holds it exactly)
        e[j][i] = std::int64_t(x);
        bits |= std::uint64_t(e[j][i]);
      }
    // the coarsest lattice: as many levels fewer as all of them have trailing zero bits
    int z = 0;
    while(z < l && (bits >> z & 1) == 0) ++z;
    for(auto& x : e)
      for(auto& c : x) {
        c /= std::int64_t(1) << z;
        if(c > 32767 || c < -32767) return false;
      }
    r.u = q[0][0];
    r.v = q[0][1];
    r.face = face;
    r.level = std::uint32_t(l - z) & 63u;
    r.piece = piece;
    for(int j = 0; j < 2; ++j)
      for(int i = 0; i < 2; ++i) r.e[j][i] = std::int16_t(e[j][i]);
    return true;
  }

  template <class Map, class PointRange, class OutputIterator>
  bool refine(const Fragment& f, const Map& map, const PointRange& near, const PointRange& around, double radius,
              OutputIterator children) const
  {
    const Face& face = faces_[f.face];
    // points and centres relative to the face's first corner (local_error())
    const double error = local_error(face, radius);
    auto point = [&](const double (&q)[2]) {
      const std::array<double, 2> uv = map(q[0], q[1]);
      return at_local(face, uv[0], uv[1]);
    };
    // parameters and points: the corners of f, then either the midpoints of its edges or two cut points
    double q[6][2];
    Point p[6];
    for(int j = 0; j < 3; ++j) {
      const std::array<double, 2> c = corner_uv(f, j);
      q[j][0] = c[0], q[j][1] = c[1];
      p[j] = point(q[j]);
    }

    // bit i of in[j]: point j is covered by ball i of `near`, as is_covered() decides it
    const double r2 = covering_squared_radius(radius, error);
    // (64 is more than the engine ever passes: balls of radius D / 2 around samples at least D apart
    // are disjoint, so at most 27 samples lie within D of a point; and a subset is still sound)
    Point centres[64]; // the balls of `near`, relative to v0
    const std::size_t n = load_centres(near, face.v0, centres);
    std::uint64_t in[6] = {0, 0, 0, 0, 0, 0};
    auto test = [&](int first, int last) { cover_bits(p, first, last, centres, n, r2, in); };
    test(0, 3);
    if(in[0] & in[1] & in[2]) return true;

    // the triangles to keep, as indices into p: the pieces that a chord cut leaves (the class
    // description, "Chord cuts"), or f's children
    int tri[4][3];
    int count = 0;
    Fragment out[4];
    // The corners' parameters in the face have f.level + k + frame_bits bits, at most 52 to be exact.
    // A cut puts its pieces on a lattice s levels finer than f's (the cut points are multiples of
    // 2^-s of their edges), and split down to the engine's floor (level() 40) a piece reaches the
    // lattice level 40 - k + its lattice_excess: the cut is made only if that excess stays at most
    // `spare` (52 bits in all). s is lowered where f's own excess leaves less room than 6 levels; the
    // pieces of a cut leave about s levels more excess than f had, less what they shrink.
    const int frame = frame_bits(face, f.piece);
    const int spare = 12 - frame;
    const int s = (std::min)({6, 52 - int(f.level) - piece_k(f) - frame, spare + 1 - lattice_excess(f)});
    auto small = [&]() { // at most 4 D across
      for(int j = 0; j < 3; ++j)
        if(!(squared_distance(p[j], p[(j + 1) % 3]) <= 16 * radius * radius)) return false;
      return true;
    };
    if(s >= 2 && (in[0] | in[1] | in[2]) != 0 && small()) {
      // the ball that holds one or two corners and cuts off the most along a chord between two edges
      const double steps = double(1 << s);
      auto chord = [&](int x, int y, const Point& c) { // steps of the edge from x (in the ball) to y
        double d[3], w[3], A = 0, B = 0, C = -r2;
        for(int i = 0; i < 3; ++i) {
          d[i] = p[y][i] - p[x][i];
          w[i] = p[x][i] - c[i];
          A += d[i] * d[i], B += w[i] * d[i], C += w[i] * w[i];
        }
        // where the edge leaves the ball, in steps, rounded down (by truncation: std::floor is a call
        // without SSE4.1); the cut points are checked below, so this needs no more precision. Divided
        // by A first: B^2 and A C are fourth powers of the size, out of the range of doubles for
        // surfaces scaled by 2^-300 or 2^300, and b and c are the same for any power-of-two scale.
        const double b = B / A, c0 = C / A;
        const double k = (-b + std::sqrt((std::max)(0., b * b - c0))) * steps;
        return k >= 1 ? (k < steps ? double(int(k)) : steps - 1) : 0.;
      };
      double best = 0.25 * steps * steps;
      int best_i = -1, best_x[2] = {0, 0}, best_y[2] = {0, 0};
      double best_k[2] = {0, 0};
      for(std::size_t i = 0; i < n; ++i) {
        const int m = int(in[0] >> i & 1) | int(in[1] >> i & 1) << 1 | int(in[2] >> i & 1) << 2;
        if(m == 0) continue;
        int x[2], y[2];
        if(m == 1 || m == 2 || m == 4) { // one corner in the ball: the chord across it
          const int a = m == 1 ? 0 : m == 2 ? 1 : 2;
          x[0] = x[1] = a, y[0] = (a + 1) % 3, y[1] = (a + 2) % 3;
        } else { // two corners: the chord across the third
          const int b = m == 6 ? 0 : m == 5 ? 1 : 2;
          x[0] = (b + 1) % 3, x[1] = (b + 2) % 3, y[0] = y[1] = b;
        }
        const double k0 = chord(x[0], y[0], centres[i]), k1 = chord(x[1], y[1], centres[i]);
        const double removed = x[0] == x[1] ? k0 * k1 : steps * steps - (steps - k0) * (steps - k1);
        if(removed > best) {
          best = removed, best_i = int(i);
          best_x[0] = x[0], best_x[1] = x[1], best_y[0] = y[0], best_y[1] = y[1], best_k[0] = k0, best_k[1] = k1;
        }
      }
      if(best_i >= 0) {
        // the cut points, moved towards the ball's corners until the computed points are in the ball
        const Point& centre = centres[best_i];
        for(int e = 0; e < 2; ++e) {
          for(;; best_k[e] -= 1) {
            const double t = best_k[e] / steps;
            for(int i = 0; i < 2; ++i) q[3 + e][i] = q[best_x[e]][i] + t * (q[best_y[e]][i] - q[best_x[e]][i]);
            p[3 + e] = point(q[3 + e]);
            if(best_k[e] == 0 || squared_distance(p[3 + e], centre) <= r2) break;
          }
        }
        const double removed = best_x[0] == best_x[1] ? best_k[0] * best_k[1]
                                                      : steps * steps - (steps - best_k[0]) * (steps - best_k[1]);
        if(removed >= 0.25 * steps * steps) {
          if(best_x[0] == best_x[1]) { // what is left is the quadrilateral (P3, y0, y1, P4)
            count = 2;
            const int t0[3] = {3, best_y[0], best_y[1]}, t1[3] = {3, best_y[1], 4};
            std::copy(t0, t0 + 3, tri[0]);
            std::copy(t1, t1 + 3, tri[1]);
          } else { // the triangle (P3, P4, y)
            count = 1;
            const int t0[3] = {3, 4, best_y[0]};
            std::copy(t0, t0 + 3, tri[0]);
          }
          for(int t = 0; t < count; ++t) {
            const double qt[3][2] = {{q[tri[t][0]][0], q[tri[t][0]][1]},
                                     {q[tri[t][1]][0], q[tri[t][1]][1]},
                                     {q[tri[t][2]][0], q[tri[t][2]][1]}};
            if(!make_piece(qt, int(f.level) + s, f.face, f.piece, out[t]) || lattice_excess(out[t]) > spare)
              count = 0; // then split
          }
          if(count > 0) test(3, 5);
        }
      }
    }
    if(count == 0) {
      // f's children are (0 3 4), (3 1 5), (4 5 2) and the flipped (5 4 3), each listed as corners()
      // lists it: the midpoints 3, 4 and 5 are the first corners of children 1, 2 and 3
      static constexpr int table[4][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}, {5, 4, 3}};
      count = 4;
      for(int c = 0; c < 4; ++c) {
        std::copy(table[c], table[c] + 3, tri[c]);
        out[c] = child(f, c);
        if(c > 0) {
          q[2 + c][0] = out[c].u, q[2 + c][1] = out[c].v;
          p[2 + c] = point(q[2 + c]);
        }
      }
      test(3, 6);
    }

    // A ball that meets f, which lies within R of its centroid (R being the farthest corner's
    // distance), has its centre within radius + R of it; 1.5 R and 4 position errors leave room for
    // the rounding of the centroid and of the distances.
    double g[3], reach2 = 0;
    for(int i = 0; i < 3; ++i) g[i] = (p[0][i] + p[1][i] + p[2][i]) / 3;
    for(int j = 0; j < 3; ++j) reach2 = (std::max)(reach2, squared_distance(p[j], Point{{g[0], g[1], g[2]}}));
    const double reach = (radius + 1.5 * std::sqrt(reach2) + 4 * error) * (1 + 1e-9);
    typedef internal::Triangle_in_ball_union Union;
    Point meeting[Union::max_balls + 2];
    std::size_t k = Union::balls_near(around, g, reach, meeting, face.v0);
    const bool all_kept = k <= Union::max_balls; // whether `meeting` holds every ball of `around` that can meet f
    k = (std::min)(k, Union::max_balls);

    // which of the points are strictly inside a ball of `meeting`, shrunk as the union test shrinks
    // them: a piece with a corner outside is not covered by the union
    const double corner_error = 2 * error; // error bounds each coordinate
    const Points_view balls{meeting, meeting + k};
    signed char inside[6] = {-1, -1, -1, -1, -1, -1}; // not known yet
    auto is_inside = [&](int j) {
      if(inside[j] < 0) inside[j] = Union::is_inside_one(p[j], balls, radius - corner_error);
      return inside[j] == 1;
    };

    for(int c = 0; c < count; ++c) {
      const int* t = tri[c];
      if(!(area(out[c]) > 0)) continue;
      if(in[t[0]] & in[t[1]] & in[t[2]]) continue;
      const Point corner[3] = {p[t[0]], p[t[1]], p[t[2]]};
      const bool by_union =
          all_kept ? radius > corner_error && is_inside(t[0]) && is_inside(t[1]) && is_inside(t[2]) &&
                         Union::covers_with_corners_inside(corner, balls, radius, corner_error)
                   : Union::covers(corner, around, radius, corner_error, face.v0);
      if(!by_union) *children++ = out[c];
    }
    return false;
  }

  // the first 64 balls of `near` (see refine()), relative to `origin`; returns how many
  template <class PointRange>
  static std::size_t load_centres(const PointRange& near, const Point& origin, Point (&centres)[64])
  {
    std::size_t n = 0;
    for(auto c = near.begin(); c != near.end() && n < 64; ++c) centres[n++] = relative(*c, origin);
    return n;
  }

  // bit i of in[j], for j in [first, last): p[j] is within the square root of r2 of centre i
  static void cover_bits(const Point* p, int first, int last, const Point* centres, std::size_t n, double r2,
                         std::uint64_t* in)
  {
    for(std::size_t i = 0; i < n; ++i)
      for(int j = first; j < last; ++j) in[j] |= std::uint64_t(squared_distance(p[j], centres[i]) <= r2) << i;
  }

  static Fragment make_fragment(std::uint32_t face, std::uint32_t piece)
  {
    Fragment f;
    f.u = 0;
    f.v = 0;
    f.face = face;
    f.level = 0;
    f.piece = piece;
    f.e[0][0] = 1, f.e[0][1] = 0, f.e[1][0] = 0, f.e[1][1] = 1;
    return f;
  }

  struct Points_view
  {
    const Point *first, *last;
    const Point* begin() const { return first; }
    const Point* end() const { return last; }
  };

  struct Face
  {
    Point v0, e1, e2;   // the rotated triangle: v0, v0 + e1, v0 + e2
    double area;
    std::uint8_t first; // which given corner is v0
    bool cap;           // the largest angle is 120 degrees or more
    std::uint8_t apex;  // corner (0: v0, 1: v0 + e1, 2: v0 + e2) of a cap's largest angle, else
                        // the corner opposite the shortest edge
    float foot;         // a cap: where the altitude from the apex meets the opposite edge, from 0
                        // at the next corner to 1 at the one after
  };

  // the corners of the face in its parameter space, and an affine map from a piece's parameters
  // (s, t) to the face's (u, v) = c + s a + t b
  static constexpr double corner_u[3] = {0, 1, 0}, corner_v[3] = {0, 0, 1};
  struct Frame
  {
    double cu, cv, au, av, bu, bv;
    std::array<double, 2> operator()(double s, double t) const
    {
      return {{cu + s * au + t * bu, cv + s * av + t * bv}};
    }
  };
  struct Whole_face // the frame of piece 0: (u, v) = (s, t)
  {
    std::array<double, 2> operator()(double s, double t) const { return {{s, t}}; }
  };

  // Pieces: bits 0-1 the kind (0 the whole face, 1 a row of a needle, 2 and 3 a row of the first or
  // second needle of a cap), 2-5 k (a needle's rows are 2^k; a cap's split point is a multiple of
  // 2^-k along the edge), 6 which triangle of the row, 7-19 the row, 20-23 m: 0 for a triangle of a
  // row, else the block of the 2^m rows from the row on (see `Block`).
  static constexpr int max_k = 12;
  static std::uint32_t piece_code(int kind, int k, int half, std::uint32_t row, int m = 0)
  {
    return std::uint32_t(kind) | std::uint32_t(k) << 2 | std::uint32_t(half) << 6 | row << 7 | std::uint32_t(m) << 20;
  }
  struct Piece // a piece code, decoded
  {
    int kind, k, half, m;
    double row;
    explicit Piece(std::uint32_t code)
        : kind(int(code & 3)), k(int(code >> 2 & 15)), half(int(code >> 6 & 1)), m(int(code >> 20 & 15)),
          row(double(code >> 7 & 0x1FFF))
    {}
  };

  // A block: the rows [a, b) of a needle (P, Q, R) of 2^r rows, b = a + 2^m: the part between the
  // lines from p_t = P + t (R - P) to q_t = Q + t (R - Q) at t = a h and t = b h, h = 2^-r. It is the
  // trapezoid (p_a, q_a, q_b, p_b), a triangle at the needle's end (b = 2^r: q_b = p_b = R). Its
  // corners and the ends of its middle line, at c = a + 2^(m - 1), are computed in the face's
  // parameters as frame() computes the corners of the rows' triangles, so that they are the same
  // numbers (dyadic: exact).
  struct Block
  {
    double P[2], Q[2], R[2];
    double t0, t1;  // a h and b h
    bool tip;       // b is the needle's end
    double q[6][2]; // p_a, q_a, q_b, p_b, p_c, q_c
    Block(const Face& face, std::uint32_t code)
    {
      const Piece piece(code);
      const int rows_log2 = needle(face, piece.kind, piece.k, P, Q, R);
      const double h = internal::power_of_half(std::size_t(rows_log2));
      const double span = double(std::uint32_t(1) << piece.m);
      const double t[3] = {piece.row * h, (piece.row + span) * h, (piece.row + 0.5 * span) * h};
      t0 = t[0], t1 = t[1];
      tip = piece.row + span == double(std::uint32_t(1) << rows_log2);
      const int at_p[3] = {0, 3, 4}, at_q[3] = {1, 2, 5};
      for(int j = 0; j < 3; ++j)
        for(int i = 0; i < 2; ++i) {
          q[at_p[j]][i] = P[i] + t[j] * (R[i] - P[i]);
          q[at_q[j]][i] = Q[i] + t[j] * (R[i] - Q[i]);
        }
    }
    // point j of q, relative to the face's first corner
    Point point(const Face& face, int j) const { return at_local(face, q[j][0], q[j][1]); }
  };

  // The point of block f at (x, y) in [0, 1]^2, uniformly distributed for x and y uniform: x is the
  // share of the block's area between the line at a and the point's line (the needle's area from
  // t = 0 to t is 1 - (1 - t)^2 of it), y the share of the way from p_t to q_t.
  Sample block_point(const Fragment& f, double x, double y) const
  {
    const Face& face = faces_[f.face];
    const Block b(face, f.piece);
    const double w0 = 1 - b.t0, w1 = 1 - b.t1;
    const double t = (std::min)(b.t1, (std::max)(b.t0, 1 - std::sqrt(w0 * w0 - x * (w0 * w0 - w1 * w1))));
    Sample s;
    s.face = f.face;
    s.u = b.P[0] + t * (b.R[0] - b.P[0]) + y * (1 - t) * (b.Q[0] - b.P[0]);
    s.v = b.P[1] + t * (b.R[1] - b.P[1]) + y * (1 - t) * (b.Q[1] - b.P[1]);
    s.point = at(face, s.u, s.v);
    return s;
  }

  // The halves of a block, which tile it: two blocks of half as many rows, or, for a block of two
  // rows, the rows' triangles (three where the second row is the needle's last, one triangle).
  // Writes them and returns how many.
  int block_halves(const Fragment& f, Fragment (&halves)[4]) const
  {
    const Piece p(f.piece);
    const std::uint32_t row = std::uint32_t(p.row), span = std::uint32_t(1) << p.m;
    if(p.m >= 2) {
      halves[0] = make_fragment(f.face, piece_code(p.kind, p.k, 0, row, p.m - 1));
      halves[1] = make_fragment(f.face, piece_code(p.kind, p.k, 0, row + span / 2, p.m - 1));
      return 2;
    }
    halves[0] = make_fragment(f.face, piece_code(p.kind, p.k, 0, row));
    halves[1] = make_fragment(f.face, piece_code(p.kind, p.k, 1, row));
    halves[2] = make_fragment(f.face, piece_code(p.kind, p.k, 0, row + 1));
    if(row + span == std::uint32_t(1) << rows_log2(faces_[f.face], p.kind, p.k)) return 3; // the needle's end
    halves[3] = make_fragment(f.face, piece_code(p.kind, p.k, 1, row + 1));
    return 4;
  }

  // refine() for a block: its halves that no ball of `near` covers (the union test is not tried on
  // them: see the class description)
  template <class PointRange, class OutputIterator>
  bool refine_block(const Fragment& f, const PointRange& near, double radius, OutputIterator children) const
  {
    const Face& face = faces_[f.face];
    const Block b(face, f.piece);
    Point p[6];
    for(int j = 0; j < 6; ++j) p[j] = b.point(face, j);
    Point centres[64];
    const std::size_t n = load_centres(near, face.v0, centres);
    std::uint64_t in[6] = {0, 0, 0, 0, 0, 0};
    cover_bits(p, 0, 6, centres, n, covering_squared_radius(radius, local_error(face, radius)), in);
    if(in[0] & in[1] & in[2] & in[3]) return true;
    // the points of each half: (p_a, q_a, q_c, p_c) and (p_c, q_c, q_b, p_b), or the rows' triangles
    // as frame() makes them, (p_j, q_j, p_j+1) and (q_j, q_j+1, p_j+1)
    static constexpr int blocks[2][4] = {{0, 1, 5, 4}, {4, 5, 2, 3}};
    static constexpr int rows[4][4] = {{0, 1, 4, 4}, {1, 5, 4, 4}, {4, 5, 3, 3}, {5, 2, 3, 3}};
    Fragment halves[4];
    const int count = block_halves(f, halves);
    for(int c = 0; c < count; ++c) {
      const int* x = count == 2 ? blocks[c] : rows[c];
      if(!(in[x[0]] & in[x[1]] & in[x[2]] & in[x[3]])) *children++ = halves[c];
    }
    return false;
  }
  static int floor_log2(std::uint32_t n) // n >= 1
  {
#if defined(__GNUC__) || defined(__clang__)
    return 31 - __builtin_clz(n);
#else
    int l = 0;
    while(n >>= 1) ++l;
    return l;
#endif
  }
  // a cap's split point: the multiple m / 2^k of the edge opposite its apex nearest to the foot
  static std::uint32_t cap_split(const Face& f, int k)
  {
    const double n = double(std::uint32_t(1) << k);
    return std::uint32_t((std::min)(n, (std::max)(0., std::floor(double(f.foot) * n + 0.5))));
  }
  // the same as a fraction of the edge, m 2^-k, exactly
  static double cap_split_fraction(const Face& f, int k)
  {
    return double(cap_split(f, k)) * internal::power_of_half(std::size_t(k));
  }

  // the number of rows of a piece's needle, as a power of two, or -1 if the needle is empty (a cap
  // split at a corner)
  static int rows_log2(const Face& f, int kind, int k)
  {
    if(kind == 1) return k;
    const std::uint32_t m = cap_split(f, k), length = kind == 2 ? m : (std::uint32_t(1) << k) - m;
    return length == 0 ? -1 : floor_log2(length);
  }

  // a piece's area over its face's: its needle's share of the face (all of it, or the cap's part on
  // one side of the split point), times its row's share of the needle, which is h (1 - j h) for the
  // first triangle of row j, h (1 - (j + 1) h) for the second, h = 2^-rows
  CGAL_PDS_NOINLINE static double piece_share(const Face& f, std::uint32_t piece)
  {
    const Piece p(piece);
    double side = 1;
    if(p.kind != 1) {
      const double t = cap_split_fraction(f, p.k);
      side = p.kind == 2 ? t : 1 - t;
    }
    const double h = internal::power_of_half(std::size_t(rows_log2(f, p.kind, p.k)));
    if(p.m != 0) { // a block: rows [a, b), where the needle is 1 - t wide
      const double a = 1 - p.row * h, b = 1 - (p.row + double(std::uint32_t(1) << p.m)) * h;
      return side * (a * a - b * b);
    }
    return side * h * (1 - (p.row + p.half) * h);
  }

  // a cap's two needles (P, Q, R): (apex, split point, next corner) and (apex, split point, corner
  // after); a needle face is (corner after the apex, the next one, apex), PQ its shortest edge.
  // Writes P, Q, R and returns the number of rows of the needle, as a power of two, or -1 if the
  // needle is empty.
  static int needle(const Face& f, int kind, int k, double P[2], double Q[2], double R[2])
  {
    const int a = f.apex, b = (a + 1) % 3, c = (a + 2) % 3;
    if(kind == 1) {
      P[0] = corner_u[b], P[1] = corner_v[b];
      Q[0] = corner_u[c], Q[1] = corner_v[c];
      R[0] = corner_u[a], R[1] = corner_v[a];
      return k;
    }
    const double t = cap_split_fraction(f, k);
    P[0] = corner_u[a], P[1] = corner_v[a];
    Q[0] = corner_u[b] + t * (corner_u[c] - corner_u[b]);
    Q[1] = corner_v[b] + t * (corner_v[c] - corner_v[b]);
    const int r = kind == 2 ? b : c;
    R[0] = corner_u[r], R[1] = corner_v[r];
    return rows_log2(f, kind, k);
  }

  // the bits that a piece's frame adds to the parameters of its fragments' corners beyond their
  // lattice level plus k: a cap's rows (k counts its split point's bits, or a needle's rows)
  static int frame_bits(const Face& face, std::uint32_t piece)
  {
    if(piece == 0) return 0;
    const Piece p(piece);
    return p.kind == 1 ? 0 : (std::max)(0, rows_log2(face, p.kind, p.k));
  }

  // the frame of a piece other than 0; its corners' parameters have the bits of the fragment's level
  // plus those of the rows of its needle, plus for a cap those of its split point (see level())
  CGAL_PDS_NOINLINE static Frame frame(const Face& f, std::uint32_t piece)
  {
    const Piece p(piece);
    const double j = p.row;
    double P[2], Q[2], R[2];
    const int rows = needle(f, p.kind, p.k, P, Q, R);
    const double h = internal::power_of_half(std::size_t(rows));
    double p0[2], p1[2], q0[2], q1[2]; // the row's corners: P and Q moved j and j + 1 rows towards R
    for(int i = 0; i < 2; ++i) {
      p0[i] = P[i] + j * h * (R[i] - P[i]);
      p1[i] = P[i] + (j + 1) * h * (R[i] - P[i]);
      q0[i] = Q[i] + j * h * (R[i] - Q[i]);
      q1[i] = Q[i] + (j + 1) * h * (R[i] - Q[i]);
    }
    if(p.half == 0) return Frame{p0[0], p0[1], q0[0] - p0[0], q0[1] - p0[1], p1[0] - p0[0], p1[1] - p0[1]};
    return Frame{q0[0], q0[1], q1[0] - q0[0], q1[1] - q0[1], p1[0] - q0[0], p1[1] - q0[1]};
  }

  // 0 if the face stays whole at minimum distance d; otherwise k for its pieces (piece_code())
  static int cut_level(const Face& f, double d)
  {
    // lengths of the edges opposite corners 0, 1, 2
    const double l[3] = {distance(f.e1, f.e2), length(f.e2), length(f.e1)};
    double ratio;
    if(f.cap) { // the opposite edge against the height over it, or D
      const double a = l[f.apex];
      ratio = a / (std::max)(d, 2 * f.area / a);
    } else { // the longest edge against the shortest, or D
      ratio = (std::max)({l[0], l[1], l[2]}) / (std::max)(d, l[f.apex]);
    }
    if(!(ratio >= 4)) return 0;
    return ratio >= 0x1.0p12 ? max_k : floor_log2(std::uint32_t(ratio));
  }
  // the cap test and the apex, from the shape of the face only
  static void classify(Face& f)
  {
    // edges opposite corners 0, 1, 2, scaled by the power of two that brings the largest coordinate to
    // [1, 2) (exactly, and cheaper than a division), so that squares neither underflow nor overflow
    Point e[3];
    for(int i = 0; i < 3; ++i) {
      e[0][i] = f.e2[i] - f.e1[i];
      e[1][i] = f.e2[i];
      e[2][i] = f.e1[i];
    }
    double m = 0;
    for(const Point& x : e)
      for(double c : x) m = (std::max)(m, std::abs(c));
    f.cap = false;
    f.apex = 0;
    f.foot = 0.5f;
    if(!(m > 0) || !std::isfinite(m)) return;
    double l2[3];
    const int k = -internal::binary_exponent(m);
    for(int i = 0; i < 3; ++i) {
      for(double& c : e[i]) c = internal::times_power_of_two(c, k);
      l2[i] = dot(e[i], e[i]);
    }
    const int longest = l2[0] >= l2[1] ? (l2[0] >= l2[2] ? 0 : 2) : (l2[1] >= l2[2] ? 1 : 2);
    const int shortest = l2[0] <= l2[1] ? (l2[0] <= l2[2] ? 0 : 2) : (l2[1] <= l2[2] ? 1 : 2);
    const double b2 = l2[(longest + 1) % 3], c2 = l2[(longest + 2) % 3];
    // the angle opposite the longest edge a is 120 degrees or more: a^2 >= b^2 + c^2 + b c
    f.cap = l2[longest] >= b2 + c2 + std::sqrt(b2 * c2);
    f.apex = std::uint8_t(f.cap ? longest : shortest);
    if(f.cap) {
      // the foot of the altitude on the edge from corner apex + 1 to apex + 2
      const int a = f.apex, b = (a + 1) % 3;
      const Point corner[3] = {{{0, 0, 0}}, e[2], e[1]}; // scaled, relative to v0
      Point ba, bc;
      for(int i = 0; i < 3; ++i) {
        ba[i] = corner[a][i] - corner[b][i];
        bc[i] = corner[(a + 2) % 3][i] - corner[b][i];
      }
      f.foot = float(dot(ba, bc) / dot(bc, bc));
    }
  }

  // A ball of `radius` covers a fragment if the computed corners are within the square root of this
  // of its centre; negative if no fragment can be proven covered. The margin is more than the
  // rounding of the corners and the centre (4 times `error`, which bounds each coordinate's) and of
  // the squared distances (8 eps relative).
  static double covering_squared_radius(double radius, double error)
  {
    const double r = radius - 4 * error;
    return r > 0 ? r * r * (1 - 8 * std::numeric_limits<double>::epsilon()) : -1.;
  }

  // The coverage tests compute relative to the face's first corner v0: a fragment's corner is
  // u e1 + v e2, a ball's centre c - v0. Their rounding is then relative to the face's size and the
  // radius, not to the coordinates: far from the origin, position_error() is much larger, and its
  // margin left a band along the balls' boundaries, wider than the fragments at the depth floor,
  // which no test could decide (a cube 10^6 times its size from the origin, at 100,000 points,
  // dropped 49 million fragments there). This bounds the error of each coordinate of a corner,
  // 4 eps (|e1| + |e2|) as for position_error() without v0, plus that of c - v0 for a centre that can
  // cover a point of the face (within radius of it): eps / 2 (radius + |e1| + |e2|) per coordinate.
  static double local_error(const Face& f, double radius)
  {
    double extent = 0;
    for(int i = 0; i < 3; ++i) extent = (std::max)(extent, std::abs(f.e1[i]) + std::abs(f.e2[i]));
    return 5 * std::numeric_limits<double>::epsilon() * (extent + radius);
  }

  // the computed corners of a fragment relative to its face's first corner, in the order of its
  // offsets
  std::array<Point, 3> local_corners(const Fragment& f) const
  {
    const Face& face = faces_[f.face];
    std::array<double, 2> q[3] = {corner_uv(f, 0), corner_uv(f, 1), corner_uv(f, 2)};
    if(f.piece != 0) {
      const Frame m = frame(face, f.piece);
      for(auto& x : q) x = m(x[0], x[1]);
    }
    return {{at_local(face, q[0][0], q[0][1]), at_local(face, q[1][0], q[1][1]), at_local(face, q[2][0], q[2][1])}};
  }

  // the unit of the lattice of a fragment's corners, in its piece's parameters
  static double unit(const Fragment& f) { return internal::power_of_half(f.level); }

  static Point at(const Face& f, double u, double v)
  {
    return Point{{f.v0[0] + u * f.e1[0] + v * f.e2[0], f.v0[1] + u * f.e1[1] + v * f.e2[1],
                  f.v0[2] + u * f.e1[2] + v * f.e2[2]}};
  }
  // at() less v0
  static Point at_local(const Face& f, double u, double v)
  {
    return Point{{u * f.e1[0] + v * f.e2[0], u * f.e1[1] + v * f.e2[1], u * f.e1[2] + v * f.e2[2]}};
  }
  static Point relative(const Point& c, const Point& origin)
  {
    return Point{{c[0] - origin[0], c[1] - origin[1], c[2] - origin[2]}};
  }
  static Point cross(const Point& a, const Point& b)
  {
    return Point{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  }
  static double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  // the area of the triangle of edges e1 and e2: half the length of their cross product, computed on
  // the edges scaled by the power of two that brings their largest coordinate to [1, 2), which is
  // exact, then scaled back. Zero only for edges on one line, decided exactly on the edges as given
  // (add_triangle() decides again on the corners): where the cross product rounds to zero, it is
  // computed again in rationals. (Of 200,000 random triples of points on one
  // line in decimal, a fifth were not on one line as doubles and had a cross product that rounded to
  // zero: such slivers were skipped, by the sampler and by the certificate alike.) A positive area
  // below the doubles comes out as the smallest positive double, as in area() (the cross product of
  // edges 1e-162 long underflows).
  static double face_area(const Point& e1, const Point& e2)
  {
    int k = 0;
    const Point c = scaled_cross(e1, e2, k);
    const double scaled = 0.5 * length(c);
    if(!(scaled > 0) || k == 0) return scaled;
    const double area = internal::times_power_of_two(scaled, 2 * k);
    return area > 0 ? area : std::numeric_limits<double>::denorm_min();
  }
  // the cross product of e1 and e2 divided by 2^(2k), computed on the edges scaled by 2^-k, which
  // brings their largest coordinate to [1, 2), exactly; zero only for edges on one line, decided
  // exactly (see face_area()). k is 0 where the largest coordinate is 0 or not finite.
  static Point scaled_cross(const Point& e1, const Point& e2, int& k)
  {
    double m = 0;
    for(int i = 0; i < 3; ++i) m = (std::max)({m, std::abs(e1[i]), std::abs(e2[i])});
    k = 0;
    if(!(m > 0) || !std::isfinite(m)) return cross(e1, e2);
    k = internal::binary_exponent(m);
    Point a, b;
    for(int i = 0; i < 3; ++i) {
      a[i] = internal::times_power_of_two(e1[i], -k);
      b[i] = internal::times_power_of_two(e2[i], -k);
    }
    Point c = cross(a, b);
    if(c[0] == 0 && c[1] == 0 && c[2] == 0) {
      typedef CGAL::Exact_rational ET;
      for(int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        c[i] = CGAL::to_double(ET(a[j]) * ET(b[l]) - ET(a[l]) * ET(b[j]));
      }
    }
    return c;
  }
  // the unit normal of the triangle (p0, p1, p2), from the cross product of its edges computed in
  // rationals on the corners and divided by its largest coordinate there, and its area (at least the
  // smallest positive double); zero for corners on one line
  static Point exact_unit_normal(const Point& p0, const Point& p1, const Point& p2, double& area)
  {
    typedef CGAL::Exact_rational ET;
    ET a[3], b[3], c[3];
    for(int i = 0; i < 3; ++i) {
      a[i] = ET(p1[i]) - ET(p0[i]);
      b[i] = ET(p2[i]) - ET(p0[i]);
    }
    ET m = 0;
    for(int i = 0; i < 3; ++i) {
      c[i] = a[(i + 1) % 3] * b[(i + 2) % 3] - a[(i + 2) % 3] * b[(i + 1) % 3];
      if(CGAL::abs(c[i]) > m) m = CGAL::abs(c[i]);
    }
    Point n{{0, 0, 0}};
    area = 0;
    if(m == 0) return n;
    for(int i = 0; i < 3; ++i) n[i] = CGAL::to_double(c[i] / m);
    const double l = length(n);
    area = (std::max)(0.5 * CGAL::to_double(m) * l, std::numeric_limits<double>::denorm_min());
    for(double& x : n) x /= l;
    return n;
  }
  // |a|; where its square is not a normal double (a cross product below about 1e-150 or above about
  // 1e150: a triangle smaller than 1e-75 or larger than 1e75), computed on a divided by its largest
  // coordinate, since the square underflows to zero or overflows
  static double length(const Point& a)
  {
    const double l2 = dot(a, a);
    if(l2 >= 0x1.0p-1000 && l2 <= 0x1.0p+1000) return std::sqrt(l2);
    const double m = (std::max)({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
    if(!(m > 0) || !std::isfinite(m)) return m;
    const Point b{{a[0] / m, a[1] / m, a[2] / m}};
    return m * std::sqrt(dot(b, b));
  }
  static double distance(const Point& a, const Point& b)
  {
    return length(Point{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}});
  }
  static double squared_distance(const Point& a, const Point& b)
  {
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return x * x + y * y + z * z;
  }

  // the index of the clusters of small faces, made when a distance first needs it (see "Clusters of
  // small faces"); copies of the model share it, and adding a triangle makes a new one
  struct Clusters
  {
    std::once_flag once;
    std::atomic<bool> built{false};
    internal::Face_clusters index;
  };
  std::shared_ptr<Clusters> clusters_ = std::make_shared<Clusters>();
  double area_sum_ = 0;          // the faces' areas, summed in the order they were added
  std::size_t positive_faces_ = 0; // the faces of positive area
  // reach_count_[k] faces of positive area have a reach (largest distance from the centroid to a
  // corner) in [2^(k + reach_exponent_), 2^(k + 1 + reach_exponent_)), over the powers of two met:
  // whether enough faces are small enough to cluster them at a distance, without the index
  std::vector<std::uint32_t> reach_count_;
  int reach_exponent_ = 0;

  // the reach of a face, rounded up (a distance rounds by a few eps of itself), and its centroid
  // relative to v0 in g: the largest distance from g to a corner
  static double face_reach(const Face& f, Point& g)
  {
    g = Point{{(f.e1[0] + f.e2[0]) / 3, (f.e1[1] + f.e2[1]) / 3, (f.e1[2] + f.e2[2]) / 3}};
    const double r2 = (std::max)({dot(g, g), squared_distance(f.e1, g), squared_distance(f.e2, g)});
    const double reach = r2 >= 0x1.0p-1000 && r2 <= 0x1.0p+1000
                             ? std::sqrt(r2) // the largest of length()'s three square roots
                             : (std::max)({length(g), distance(f.e1, g), distance(f.e2, g)});
    return reach * (1 + 0x1.0p-40);
  }
  void count_reach(const Face& f)
  {
    Point g;
    const double reach = face_reach(f, g);
    if(!(reach > 0) || !std::isfinite(reach)) return;
    const int e = internal::binary_exponent(reach);
    if(reach_count_.empty()) reach_exponent_ = e;
    if(e < reach_exponent_) {
      reach_count_.insert(reach_count_.begin(), std::size_t(reach_exponent_ - e), 0);
      reach_exponent_ = e;
    }
    if(std::size_t(e - reach_exponent_) >= reach_count_.size()) reach_count_.resize(std::size_t(e - reach_exponent_) + 1, 0);
    ++reach_count_[std::size_t(e - reach_exponent_)];
  }
  // a lower bound on the number of faces of positive area whose reach is at most r
  std::size_t faces_within_reach(double r) const
  {
    std::size_t n = 0;
    for(std::size_t k = 0; k < reach_count_.size() && std::ldexp(1.0, reach_exponent_ + int(k) + 1) <= r; ++k)
      n += reach_count_[k];
    return n;
  }

  std::vector<Face> faces_;
  // the normals of the faces of positive area whose edges, as rounded, are on one line, by face index
  std::vector<std::pair<std::uint32_t, Point>> thin_face_normals_;
  double position_error_ = 0;
};

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_TRIANGLE_FRAGMENT_TRAITS_3_H
