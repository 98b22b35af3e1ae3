// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_TRIANGLE_FRAGMENT_TRAITS_3_H
#define CGAL_POISSON_DISK_SAMPLING_3_TRIANGLE_FRAGMENT_TRAITS_3_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Triangle_in_ball_union.h>
#include <CGAL/Poisson_disk_sampling_3/internal/power_of_half.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Concepts
/// \cgalModels `SurfaceFragmentTraits_3`
///
/// Triangles as surface fragments (paper Section 4). The surface is a set of triangles added with
/// `add_triangle()`; the fragments are the sub-triangles of the regular 4-to-1 midpoint subdivision
/// of each one. A fragment is stored as its face, its subdivision level and one corner in the face's
/// parameter space (u, v), where the face is V0 + u (V1 - V0) + v (V2 - V0): corners and samples keep
/// exact dyadic parameters. Each triangle is rotated to start at its lexicographically smallest corner,
/// so that the samples depend on the geometry only, not on which corner a mesh data structure lists
/// first (`Surface_mesh` and `Polyhedron_3` give the same points); `barycentric_coordinates()` maps
/// back to the order in which the corners were given.
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

  /// a sub-triangle of one face
  struct Fragment
  {
    double u;             ///< parameter of the corner at the right angle in parameter space
    double v;             ///< parameter of the corner at the right angle in parameter space
    std::uint32_t face;   ///< index of the face, in the order of `add_triangle()`
    std::uint8_t level;   ///< subdivision level: the legs in parameter space are 2^-level long
    bool inverted;        ///< the legs point towards -u and -v instead of +u and +v
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

  /// adds the triangle (`p0`, `p1`, `p2`) and returns its face index; a triangle of zero area is
  /// kept (so that face indices follow the input) but has no fragment.
  /// \throws Invalid_input if a coordinate is not finite
  std::uint32_t add_triangle(const Point& q0, const Point& q1, const Point& q2)
  {
    const Point* q[3] = {&q0, &q1, &q2};
    for(const Point* p : q)
      for(double c : *p)
        if(!std::isfinite(c))
          throw Invalid_input("triangle " + std::to_string(faces_.size()) + " has a coordinate that is not finite");
    if(faces_.size() >= std::numeric_limits<std::uint32_t>::max())
      throw Invalid_input("too many triangles (at most 2^32 - 1)");
    Face f;
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
    f.area = 0.5 * length(cross(f.e1, f.e2));
    // corners V0 + u E1 + v E2 are off the exact sub-triangle by less than this, per coordinate
    position_error_ = (std::max)(position_error_, 4 * std::numeric_limits<double>::epsilon() * scale);
    faces_.push_back(f);
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

  /// unit normal of a triangle (right-hand rule on its vertex order), or the zero vector if it has no area
  Point triangle_normal(std::uint32_t face) const
  {
    const Face& f = faces_[face];
    Point n = cross(f.e1, f.e2);
    const double l = length(n);
    if(l > 0)
      for(double& c : n) c /= l;
    return n;
  }

  /// \name Operations of SurfaceFragmentTraits_3
  /// @{

  /// a bound on the distance between a computed point of a triangle and the exact one
  double position_error() const { return position_error_; }

  /// writes one fragment per triangle of positive area
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out) const
  {
    for(std::uint32_t i = 0; i < faces_.size(); ++i)
      if(faces_[i].area > 0) *out++ = Fragment{0., 0., i, 0, false};
    return out;
  }

  /// area of a fragment: a quarter of its parent's
  double area(const Fragment& f) const { return faces_[f.face].area * internal::power_of_half(2 * std::size_t(f.level)); }

  /// a point uniformly distributed on the fragment, never refused
  template <class RandomGenerator>
  std::optional<Sample> random_sample(const Fragment& f, RandomGenerator& rng) const
  {
    double a = rng.uniform(), b = rng.uniform();
    if(a + b > 1) { a = 1 - a; b = 1 - b; }
    const double h = leg(f);
    Sample s;
    s.face = f.face;
    s.u = f.u + h * a;
    s.v = f.v + h * b;
    s.point = at(faces_[f.face], s.u, s.v);
    return s;
  }

  /// the point of a sample
  const Point& point(const Sample& s) const { return s.point; }

  /// the centroid of the fragment
  Point reference_point(const Fragment& f) const
  {
    const double t = leg(f) / 3;
    return at(faces_[f.face], f.u + t, f.v + t);
  }

  /// true only if the three corners are within `radius` of `center` by more than their rounding error,
  /// so that the exact sub-triangle lies in the ball
  bool is_covered(const Fragment& f, const Point& center, double radius) const
  {
    const double r2 = covering_squared_radius(radius); // negative: no squared distance is below it
    const std::array<Point, 3> c = corners(f);
    return squared_distance(c[0], center) <= r2 && squared_distance(c[1], center) <= r2 &&
           squared_distance(c[2], center) <= r2;
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: true only if the union of the balls of radius
  /// `radius` around `centers` holds the fragment, proven with a bound on every rounding error (see
  /// `internal/Triangle_in_ball_union.h`). Covers the fragments that straddle the boundary between
  /// two balls, which no single ball holds.
  template <class PointRange>
  bool is_covered_by_union(const Fragment& f, const PointRange& centers, double radius) const
  {
    const std::array<Point, 3> c = corners(f);
    const Point corner[3] = {c[0], c[1], c[2]};
    // position_error_ bounds each coordinate; twice it bounds the distance
    return internal::Triangle_in_ball_union::covers(corner, centers, radius, 2 * position_error_);
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the number of splits from the fragment's root
  int level(const Fragment& f) const { return f.level; }

  /// Optional operation of `SurfaceFragmentTraits_3`: starts loading what `random_sample(f, rng)`
  /// reads (the face's record) into the cache, without waiting. A hint: it changes no result.
  void prefetch(const Fragment& f) const
  {
    const Face* face = &faces_[f.face];
    internal::prefetch(face);
    internal::prefetch(&face->e2); // the record spans two cache lines
  }

  /// the four children of the midpoint subdivision
  template <class OutputIterator>
  OutputIterator split(const Fragment& f, OutputIterator out) const
  {
    const std::uint8_t l = std::uint8_t(f.level + 1);
    const double h = 0.5 * leg(f); // signed, like leg()
    *out++ = Fragment{f.u, f.v, f.face, l, f.inverted};
    *out++ = Fragment{f.u + h, f.v, f.face, l, f.inverted};
    *out++ = Fragment{f.u, f.v + h, f.face, l, f.inverted};
    *out++ = Fragment{f.u + h, f.v + h, f.face, l, !f.inverted}; // the middle one is flipped
    return out;
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the engine's step for a fragment that got a dart,
  /// with the same answers as `is_covered()`, `split()` and `is_covered_by_union()` called one by
  /// one, in less time. Returns `true` if one point of `near` covers `f` (and writes nothing);
  /// otherwise writes the children of `f` that neither one point of `near` nor the union of the balls
  /// around `around` covers. The six points the five triangles share (corners and edge midpoints of
  /// `f`) are computed once, and each ball is tested against each of them once; the union test gets
  /// only the balls that can meet `f`.
  template <class PointRange, class OutputIterator>
  bool refine(const Fragment& f, const PointRange& near, const PointRange& around, double radius,
              OutputIterator children) const
  {
    const Face& face = faces_[f.face];
    const double h = leg(f), m = 0.5 * h;
    // corners of f, then the midpoints of its edges: f's children are (0 3 4), (3 1 5), (4 5 2) and
    // the flipped (5 4 3), each listed as corners() lists it (right-angle corner, along u, along v)
    Point p[6] = {at(face, f.u, f.v), at(face, f.u + h, f.v), at(face, f.u, f.v + h)};
    static constexpr int child[4][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}, {5, 4, 3}};

    // bit i of in[j]: point j is covered by ball i of `near`, as is_covered() decides it
    const double r2 = covering_squared_radius(radius);
    // (64 is more than the engine ever passes: balls of radius D / 2 around samples at least D apart
    // are disjoint, so at most 27 samples lie within D of a point; and a subset is still sound)
    const std::size_t n = (std::min)(std::size_t(64), std::size_t(std::distance(near.begin(), near.end())));
    std::uint64_t in[6] = {0, 0, 0, 0, 0, 0};
    auto test = [&](int first, int last) {
      auto c = near.begin();
      for(std::size_t i = 0; i < n; ++i, ++c)
        for(int j = first; j < last; ++j) in[j] |= std::uint64_t(squared_distance(p[j], *c) <= r2) << i;
    };
    test(0, 3);
    if(in[0] & in[1] & in[2]) return true;
    p[3] = at(face, f.u + m, f.v);
    p[4] = at(face, f.u, f.v + m);
    p[5] = at(face, f.u + m, f.v + m);
    test(3, 6);

    // The balls a child's union test keeps meet the child's circumscribing ball: about its centroid,
    // which is within R / 2 of f's centroid, of radius R / 2, R being f's (children are f halved).
    // So they lie within radius + R of f's centroid; 1.5 R and 4 position errors leave room for the
    // rounding of the centroids and of the distances.
    double g[3], reach2 = 0;
    for(int i = 0; i < 3; ++i) g[i] = (p[0][i] + p[1][i] + p[2][i]) / 3;
    for(int j = 0; j < 3; ++j) reach2 = (std::max)(reach2, squared_distance(p[j], Point{{g[0], g[1], g[2]}}));
    const double reach = (radius + 1.5 * std::sqrt(reach2) + 4 * position_error_) * (1 + 1e-9);
    Point meeting[internal::Triangle_in_ball_union::max_balls];
    std::size_t k = 0;
    bool all_kept = true; // whether `meeting` holds every ball of `around` that can meet f
    for(const auto& c : around) {
      const double x = c[0] - g[0], y = c[1] - g[1], z = c[2] - g[2];
      if(x * x + y * y + z * z >= reach * reach) continue;
      if(k == internal::Triangle_in_ball_union::max_balls) {
        all_kept = false;
        break;
      }
      meeting[k++] = Point{{c[0], c[1], c[2]}};
    }

    // which of the six points are strictly inside a ball of `meeting`, shrunk as the union test
    // shrinks them: a child with a corner outside is not covered by the union
    typedef internal::Triangle_in_ball_union Union;
    const double corner_error = 2 * position_error_; // position_error_ bounds each coordinate
    const Points_view balls{meeting, meeting + k};
    signed char inside[6] = {-1, -1, -1, -1, -1, -1}; // not known yet
    auto is_inside = [&](int j) {
      if(inside[j] < 0) inside[j] = Union::is_inside_one(p[j], balls, radius - corner_error);
      return inside[j] == 1;
    };

    const std::uint8_t l = std::uint8_t(f.level + 1);
    for(int c = 0; c < 4; ++c) {
      const int* t = child[c];
      // as split() makes them
      const Fragment fc = c == 3 ? Fragment{f.u + m, f.v + m, f.face, l, !f.inverted}
                                 : Fragment{c == 1 ? f.u + m : f.u, c == 2 ? f.v + m : f.v, f.face, l,
                                            f.inverted};
      if(!(area(fc) > 0)) continue;
      if(in[t[0]] & in[t[1]] & in[t[2]]) continue;
      const Point corner[3] = {p[t[0]], p[t[1]], p[t[2]]};
      const bool by_union =
          all_kept ? radius > corner_error && is_inside(t[0]) && is_inside(t[1]) && is_inside(t[2]) &&
                         Union::covers_with_corners_inside(corner, balls, radius, corner_error)
                   : Union::covers(corner, around, radius, corner_error);
      if(!by_union) *children++ = fc;
    }
    return false;
  }

  /// @}

private:
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
  };

  // A ball of `radius` covers a fragment if the computed corners are within the square root of this
  // of its centre; negative if no fragment can be proven covered. The margin is more than the
  // rounding of the corners (4 position errors) and of the squared distances (8 eps relative).
  double covering_squared_radius(double radius) const
  {
    const double r = radius - 4 * position_error_;
    return r > 0 ? r * r * (1 - 8 * std::numeric_limits<double>::epsilon()) : -1.;
  }

  // the computed corners of a fragment: the right-angle corner, then along u, then along v
  std::array<Point, 3> corners(const Fragment& f) const
  {
    const Face& face = faces_[f.face];
    const double h = leg(f);
    return {{at(face, f.u, f.v), at(face, f.u + h, f.v), at(face, f.u, f.v + h)}};
  }

  // the signed leg length in parameter space
  static double leg(const Fragment& f) { return (f.inverted ? -1. : 1.) * internal::power_of_half(f.level); }

  static Point at(const Face& f, double u, double v)
  {
    return Point{{f.v0[0] + u * f.e1[0] + v * f.e2[0], f.v0[1] + u * f.e1[1] + v * f.e2[1],
                  f.v0[2] + u * f.e1[2] + v * f.e2[2]}};
  }
  static Point cross(const Point& a, const Point& b)
  {
    return Point{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  }
  static double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
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
  static double squared_distance(const Point& a, const Point& b)
  {
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return x * x + y * y + z * z;
  }

  std::vector<Face> faces_;
  double position_error_ = 0;
};

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_TRIANGLE_FRAGMENT_TRAITS_3_H
