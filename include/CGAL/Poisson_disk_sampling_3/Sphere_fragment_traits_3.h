// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_SPHERE_FRAGMENT_TRAITS_3_H
#define CGAL_POISSON_DISK_SAMPLING_3_SPHERE_FRAGMENT_TRAITS_3_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/power_of_half.h>
#include <CGAL/Poisson_disk_sampling_3/internal/sin_cos.h>
#include <CGAL/Poisson_disk_sampling_3/internal/weights_of_three.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Concepts
/// \cgalModels `SurfaceFragmentTraits_3`
///
/// The sphere (paper Section 5.1). Fragments are spherical rectangles [theta0, theta1] x [z0, z1] in
/// longitude theta and height z = cos(phi) above the centre: the paper's rectangles in (theta, phi),
/// bounded by the cosines of their polar angles. The area is the paper's Equation 1,
/// R^2 (theta1 - theta0)(cos phi0 - cos phi1), and a uniform point is the paper's inverse CDF:
/// theta uniform, cos(phi) uniform.
///
/// Splitting: a rectangle is halved across its longer side on the sphere, into two children of equal
/// area. (The paper does not say how a rectangle is split; four children, both ranges halved, as for
/// triangles, make cells near the poles thin slivers, (pi / 2) rho^2 as wide as they are long at
/// distance rho from the axis, since a range of heights is long and a range of longitudes short there:
/// on the unit sphere at about a million points, a fifth of the darts went to the thousandth of the
/// area within 2.6 degrees of the poles.)
///
/// The rectangles are cells of dyadic grids over the eight octants: a fragment stores its two
/// indices and the two numbers of halvings of its ranges (16 bytes; four bounds and a depth would take
/// 40 in the engine's pool of active fragments). `rectangle()` computes its bounds, each from its own
/// index, so that neighbouring cells share their bounds to the bit and the children of a cell tile it
/// exactly.
///
/// Coverage: the paper tests the four corners of a rectangle against the ball, which fails near the
/// poles (the paper says so, and gives no test for them), where the edges of constant phi are not great
/// circles and bulge out of the ball between two inside corners. `is_covered()` instead finds the
/// minimum over the whole rectangle of the distance criterion in closed form (corners, the extreme
/// point of each edge, the antipode), so it is right everywhere.
class Sphere_fragment_traits_3
{
public:
  /// \name Types
  /// @{

  /// a point, as the engine computes with it
  typedef std::array<double, 3> Point;

  /// a spherical rectangle, by its bounds
  struct Rectangle
  {
    double theta0;  ///< smallest longitude, in [0, 2 pi]
    double theta1;  ///< largest longitude, in [0, 2 pi]
    double z0;      ///< smallest height cos(phi), in [-1, 1]
    double z1;      ///< largest height cos(phi), in [-1, 1]
  };

  /// a cell: the rectangle [i, i + 1] x pi / 2^(halvings_theta + 1) in longitude by
  /// [j, j + 1] / 2^halvings_z - 1 in height (see `rectangle()`)
  struct Fragment
  {
    std::uint64_t i;                  ///< index in longitude, below 2^(halvings_theta + 2)
    std::uint64_t j : 52;             ///< index in height, below 2^(halvings_z + 1)
    std::uint64_t halvings_theta : 6; ///< how many times an octant's range of longitudes was halved
    std::uint64_t halvings_z : 6;     ///< how many times an octant's range of heights was halved
  };

  /// the deepest `level()` of a fragment: `split()` requires a shallower one (the engine stops at 40,
  /// the certificate at 48)
  static constexpr int max_level = 50;

  /// a sample
  struct Sample
  {
    Point point;    ///< the sample
  };

  /// @}

  /// the sphere of centre `center` and radius `radius`
  /// \throws Invalid_input if the radius is not positive and finite or the centre not finite
  Sphere_fragment_traits_3(const Point& center, double radius) : c_(center), r_(radius)
  {
    if(!(radius > 0) || !std::isfinite(radius))
      throw Invalid_input("the sphere's radius must be positive and finite");
    double scale = radius;
    for(double x : center) {
      if(!std::isfinite(x)) throw Invalid_input("the sphere's centre has a coordinate that is not finite");
      scale = (std::max)(scale, std::abs(x));
    }
    error_ = 64 * std::numeric_limits<double>::epsilon() * scale;
  }

  /// the centre
  const Point& center() const { return c_; }
  /// the radius
  double radius() const { return r_; }
  /// a bound on the distance between a computed point of the sphere and the exact one
  double position_error() const { return error_; }

  /// \name Operations of SurfaceFragmentTraits_3
  /// @{

  /// the eight octants: the cells of level 0
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out) const
  {
    for(std::uint64_t i = 0; i < 4; ++i)
      for(std::uint64_t j = 0; j < 2; ++j) *out++ = Fragment{i, j, 0, 0};
    return out;
  }

  /// the bounds of a cell: theta_k = k (pi / 2) / 2^halvings_theta and z_k = k / 2^halvings_z - 1,
  /// each rounded once (z exactly), so that a bound does not depend on the cell it is computed for.
  /// The four octants of a hemisphere end at 2 fl(pi), 2.4e-16 below 2 pi: the band of longitudes
  /// left out lies within 2.4e-16 R of the last cells, far inside the margin of every coverage test
  /// (64 eps R or more), so that what covers these cells covers it too
  static Rectangle rectangle(const Fragment& f)
  {
    const double tw = quarter_turn() * internal::power_of_half(f.halvings_theta);
    const double zw = internal::power_of_half(f.halvings_z);
    return Rectangle{double(f.i) * tw, double(f.i + 1) * tw, double(f.j) * zw - 1, double(f.j + 1) * zw - 1};
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the larger of the numbers of halvings of the
  /// two ranges. 0 for an octant; a split raises it by one or leaves it, and since every split halves
  /// one of the ranges, it grows along any chain of splits
  int level(const Fragment& f) const { return int((std::max)(f.halvings_theta, f.halvings_z)); }

  /// paper Equation 1, from the widths of the cell's ranges, R^2 (pi / 2) 2^-halvings_theta
  /// 2^-halvings_z, not from its bounds: the difference of two bounds, each a product, is one
  /// instruction where the compiler fuses a product and a difference (FMA) and two where it does not,
  /// so it could differ by a unit in the last place from one call to the next, and the engine needs
  /// the same area for a fragment every time (its pool files a fragment by its area)
  double area(const Fragment& f) const
  {
    return r_ * r_ * quarter_turn() * internal::power_of_half(f.halvings_theta) *
           internal::power_of_half(f.halvings_z);
  }
  /// paper Equation 1, for any rectangle
  double area(const Rectangle& f) const { return r_ * r_ * (f.theta1 - f.theta0) * (f.z1 - f.z0); }

  /// the paper's inverse CDF: theta and cos(phi) uniform; never refused
  template <class RandomGenerator>
  std::optional<Sample> random_sample(const Fragment& fragment, RandomGenerator& rng) const
  {
    const Rectangle f = rectangle(fragment);
    const double theta = f.theta0 + rng.uniform() * (f.theta1 - f.theta0);
    const double z = f.z0 + rng.uniform() * (f.z1 - f.z0);
    return Sample{at(theta, z)};
  }

  /// the point of a sample
  const Point& point(const Sample& s) const { return s.point; }

  /// the point at the middle of the parameter ranges
  Point reference_point(const Fragment& fragment) const
  {
    const Rectangle f = rectangle(fragment);
    return at(0.5 * (f.theta0 + f.theta1), 0.5 * (f.z0 + f.z1));
  }

  /// true only if every point of the rectangle is within `radius` of `center`, with a margin larger
  /// than the rounding error
  bool is_covered(const Fragment& f, const Point& center, double radius) const
  {
    return is_covered(rectangle(f), center, radius);
  }

  /// the same for any rectangle with theta1 - theta0 in [0, 2 pi] and -1 <= z0 <= z1 <= 1
  bool is_covered(const Rectangle& f, const Point& center, double radius) const
  {
    const Ball b = ball(center, radius);
    double cos0, sin0, cos1, sin1;
    internal::sin_cos(f.theta0, sin0, cos0);
    internal::sin_cos(f.theta1, sin1, cos1);
    return min_dot(f, b, cos0, sin0, cos1, sin1) >= b.threshold;
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: true only if every point of the rectangle is
  /// strictly within `radius` of some point of `centers`, with a margin larger than the rounding
  /// error. Covers the rectangles that straddle the boundary between two or three balls, which no
  /// single ball holds (and those that one ball of `centers` holds: the engine tries single balls
  /// only among the samples near the dart).
  ///
  /// Why a `true` is a proof: with x = c + R u on the sphere and w_i = s_i - c, the criterion of
  /// ball i, g_i(x) = |x - s_i|^2 - radius^2 = R^2 + |w_i|^2 - radius^2 - 2 R u . w_i, is linear in
  /// u. For weights m_i >= 0, sum_i m_i g_i = A - 2 R u . W with W = sum_i m_i w_i and
  /// A = sum_i m_i (R^2 + |w_i|^2 - radius^2); if it is negative on the whole rectangle, then at
  /// every point some g_i is negative. It is negative everywhere iff `min_dot(f, W)` > A / (2 R),
  /// the test of `is_covered()` with W in place of w: one exact minimum per weight vector. (Seen in
  /// space, with weights of sum 1: the weighted sum is the criterion of one virtual ball, centred at
  /// the weighted mean of the centres, with squared radius radius^2 minus the weighted variance of
  /// the centres, and that ball lies in the union. The test asks whether the rectangle lies in such
  /// a ball.)
  ///
  /// The weights are searched on proxies, not with `min_dot()` (trigonometry): the four corners and
  /// the middles of the four edges. The test answers `false` at once if a proxy is in no ball (about
  /// half of the engine's calls end at the corners), and keeps only the balls that hold a proxy. It
  /// then tries each ball alone, each pair of balls with the weight that minimises the largest proxy
  /// sum, and each triple with the weights that equalise the sums at three corners. Only a weight
  /// vector whose proxy sums are all negative is checked exactly, and the first that passes answers.
  /// A subset of the balls always gives a correct answer, so the cheap filters need no care for
  /// rounding.
  ///
  /// Limits: every virtual ball of a pair passes through the circle where the pair's two spheres
  /// cross, so a rectangle that holds a point of that circle (covered there by a third ball) needs a
  /// triple, and a rectangle that only four or more balls cover together is never proven; the engine
  /// then splits it. Near the samples of a maximal set, about a quarter of the covered rectangles that
  /// no single ball covers are not proven (72 of 270 in test_sphere.cpp,
  /// `UnionCoverageProvesMostCoveredRectanglesAmongSamples`).
  template <class PointRange>
  bool is_covered_by_union(const Fragment& f, const PointRange& centers, double radius) const
  {
    return is_covered_by_union(rectangle(f), centers, radius);
  }

  /// the same for any rectangle with theta1 - theta0 in [0, pi] and -1 <= z0 <= z1 <= 1
  template <class PointRange>
  bool is_covered_by_union(const Rectangle& f, const PointRange& centers, double radius) const
  {
    double cos0, sin0, cos1, sin1;
    internal::sin_cos(f.theta0, sin0, cos0);
    internal::sin_cos(f.theta1, sin1, cos1);
    return is_covered_by_union(f, centers, radius, cos0, sin0, cos1, sin1);
  }

  /// Optional operation of `SurfaceFragmentTraits_3`: the engine's step for a fragment that got a
  /// dart, with the same answers as `is_covered()`, `split()` and `is_covered_by_union()` called one
  /// by one, in less time: the cosines and sines of the longitudes the three rectangles share are
  /// computed once. Returns `true` if one point of `near` covers `f` (and writes nothing);
  /// otherwise writes the children of `f` that neither one point of `near` nor the union of the balls
  /// around `around` covers.
  template <class PointRange, class OutputIterator>
  bool refine(const Fragment& fragment, const PointRange& near, const PointRange& around, double radius,
              OutputIterator children) const
  {
    CGAL_precondition(level(fragment) < max_level);
    const Rectangle f = rectangle(fragment);
    const bool across_theta = halves_longitudes(f);
    const Fragment cell[2] = {child(fragment, across_theta, 0), child(fragment, across_theta, 1)};
    const Rectangle half[2] = {rectangle(cell[0]), rectangle(cell[1])};
    // longitudes 0 and 2 are f's, 1 the middle if the longitudes are halved
    double cs[3], sn[3];
    internal::sin_cos(f.theta0, sn[0], cs[0]);
    internal::sin_cos(f.theta1, sn[2], cs[2]);
    if(across_theta) internal::sin_cos(half[1].theta0, sn[1], cs[1]);
    // (64 is more than the engine ever passes: balls of radius D / 2 around samples at least D apart
    // are disjoint, so at most 27 samples lie within D of a point; and a subset is still sound)
    Ball balls[64];
    std::size_t n = 0;
    for(const auto& c : near) {
      if(n == 64) break;
      balls[n++] = ball(c, radius);
    }
    // whether one ball covers g, whose longitudes are number i0 and i1
    auto covered_by_one = [&](const Rectangle& g, int i0, int i1) {
      for(std::size_t i = 0; i < n; ++i)
        if(min_dot(g, balls[i], cs[i0], sn[i0], cs[i1], sn[i1]) >= balls[i].threshold) return true;
      return false;
    };
    if(covered_by_one(f, 0, 2)) return true;
    for(int c = 0; c < 2; ++c) {
      const int i0 = across_theta ? c : 0, i1 = across_theta ? c + 1 : 2;
      const Rectangle& g = half[c];
      if(area(g) > 0 && !covered_by_one(g, i0, i1) &&
         !is_covered_by_union(g, around, radius, cs[i0], sn[i0], cs[i1], sn[i1]))
        *children++ = cell[c];
    }
    return false;
  }

private:
  // is_covered_by_union(), given the cosines and sines of f's longitudes
  template <class PointRange>
  bool is_covered_by_union(const Rectangle& f, const PointRange& centers, double radius, double cos0, double sin0,
                           double cos1, double sin1) const
  {
    const double rad2 = radius * radius, base = r_ * r_ - rad2;
    // the proxies, as points minus the sphere's centre: corners 0 to 3, then the middles of the
    // edges, computed only if every corner is in a ball
    double ct[3] = {cos0, cos1, 0}, st[3] = {sin0, sin1, 0};
    double zs[3] = {f.z0, f.z1, 0.5 * (f.z0 + f.z1)}, rs[3];
    for(int j = 0; j < 2; ++j) rs[j] = rho_of(zs[j]);
    static constexpr int at_theta[proxies] = {0, 1, 0, 1, 2, 2, 0, 1}; // 2 is the middle
    static constexpr int at_z[proxies] = {0, 0, 1, 1, 0, 1, 2, 2};
    Point prox[proxies];
    auto make = [&](int p) {
      const int i = at_theta[p], j = at_z[p];
      prox[p] = Point{{r_ * rs[j] * ct[i], r_ * rs[j] * st[i], r_ * zs[j]}};
    };
    for(int p = 0; p < 4; ++p) make(p);

    // The centres minus the sphere's centre. For a proxy x = c + R u, g(x) = |x - s|^2 - radius^2 is
    // R^2 + |w|^2 - radius^2 - 2 R u . w: a constant per ball and a dot product per proxy. (The
    // proxies only guide the search, so that this form loses digits to cancellation does not matter.)
    Point wc[max_union_centers];
    double kc[max_union_centers];
    std::size_t n = 0;
    for(const auto& s : centers) {
      if(n == max_union_centers) break; // fewer balls only make a `false` more likely
      wc[n] = Point{{s[0] - c_[0], s[1] - c_[1], s[2] - c_[2]}};
      kc[n] = base + squared_length(wc[n]);
      ++n;
    }
    auto g = [&](std::size_t i, int p) { return kc[i] - 2 * dot(prox[p], wc[i]); };

    // Most rectangles that reach this test have a corner in no ball: find out first.
    double a[max_union_centers][proxies]; // g_i at the proxies
    unsigned holds[max_union_centers];    // which proxies ball i holds, one bit each
    for(std::size_t i = 0; i < n; ++i) {
      holds[i] = 0;
      for(int p = 0; p < 4; ++p) {
        a[i][p] = g(i, p);
        holds[i] |= unsigned(a[i][p] < 0) << p;
      }
    }
    unsigned any = 0;
    for(std::size_t i = 0; i < n; ++i) any |= holds[i];
    if(any != 15) return false;

    // The middles of the edges; the bisector of two longitudes less than pi apart is the direction
    // of the sum of their unit vectors.
    const double cx = ct[0] + ct[1], sy = st[0] + st[1], norm = std::sqrt(cx * cx + sy * sy);
    ct[2] = cx / norm;
    st[2] = sy / norm;
    rs[2] = rho_of(zs[2]);
    for(int p = 4; p < proxies; ++p) make(p);
    // Only balls that reach near a corner can hold a middle of an edge: its centre is within radius
    // plus e, the longest chord between corners, of a corner (with some room for the bulge of the
    // edge), so g < 2 radius e + e^2 there.
    double e2 = 0;
    for(int p = 0; p < 4; ++p)
      for(int q = p + 1; q < 4; ++q) e2 = (std::max)(e2, squared_length(Point{{prox[p][0] - prox[q][0],
                                                          prox[p][1] - prox[q][1], prox[p][2] - prox[q][2]}}));
    const double e = 1.5 * std::sqrt(e2), reach = 2 * radius * e + e * e;
    // Keep the balls that hold a proxy: a ball that holds none only raises the proxy sums of any
    // weight vector it enters. A weight vector can make the sum negative at a proxy only if one of
    // its balls holds the proxy.
    const unsigned all = (1u << proxies) - 1;
    Point w[max_union_balls];
    std::size_t k = 0;
    any = 0;
    for(std::size_t i = 0; i < n && k < max_union_balls; ++i) {
      if(!((std::min)({a[i][0], a[i][1], a[i][2], a[i][3]}) < reach)) continue;
      for(int p = 4; p < proxies; ++p) {
        a[i][p] = g(i, p);
        holds[i] |= unsigned(a[i][p] < 0) << p;
      }
      if(holds[i] == 0) continue;
      w[k] = wc[i];
      std::copy(a[i], a[i] + proxies, a[k]);
      holds[k++] = holds[i];
      any |= holds[k - 1];
    }
    if(any != all) return false; // a middle of an edge is in no ball

    // The exact check of the weights m (>= 0) of the balls idx. Rounding, with u = eps / 2 the unit
    // roundoff, S = sum m_i |w_i| and B = sum m_i (R^2 + |w_i|^2 + radius^2), in units of u . W:
    // - w_i = s_i - c is computed within u |w_i|, which moves A / (2 R) and u . W by at most
    //   u (S + B / R) together;
    // - the sums W and A, of at most three products, are within 5 u S and 9 u B of their exact
    //   values computed from the rounded w_i; the minimum of u . W over unit vectors moves by at most
    //   the error of W;
    // - min_dot() evaluates cos, sin (within 2^-52 = 4 u, `internal::sin_cos`) and
    //   rho = sqrt((1 - z)(1 + z)) (`rho_of`, within 3 u relative; computed as sqrt(1 - z^2) it would
    //   be off by up to 2^-42 absolute near a pole, about 1024 eps); with the products and the choice
    //   between an end and the trough (which errs towards the smaller value, or off by the square of a
    //   rounding error), the computed minimum is within 20 u |W| <= 20 u S of the exact one over the
    //   exact rectangle;
    // - the final sum and division add 2 u B / (2 R).
    // That is at most about (16 S + 4 B / R) eps; the margin takes 4096 eps (S + B / R), far more:
    // a too large margin only costs a few `false` answers near tangency.
    const double eps = std::numeric_limits<double>::epsilon();
    auto proves = [&](const std::size_t* idx, const double* m, int count) {
      Point W{{0, 0, 0}};
      double A = 0, S = 0, B = 0;
      for(int t = 0; t < count; ++t) {
        const Point& wi = w[idx[t]];
        const double wi2 = squared_length(wi);
        for(int d = 0; d < 3; ++d) W[d] += m[t] * wi[d];
        A += m[t] * (r_ * r_ + wi2 - rad2);
        S += m[t] * std::sqrt(wi2);
        B += m[t] * (r_ * r_ + wi2 + rad2);
      }
      const double margin = 4096 * eps * (S + B / r_);
      return min_dot(f, W, ct[0], st[0], ct[1], st[1]) > A / (2 * r_) + margin;
    };

    // One ball may be enough: the engine tries single balls only among the samples near the dart,
    // and a child that does not hold the dart can be covered by one of the others.
    for(std::size_t i = 0; i < k; ++i) {
      const double one = 1;
      if(holds[i] == all && proves(&i, &one, 1)) return true;
    }

    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j) {
        if((holds[i] | holds[j]) != all) continue;
        // With weights (x, 1 - x), the sum at proxy p is the line a_j(p) + x (a_i(p) - a_j(p)); the
        // largest of them is convex in x, smallest where a rising line crosses a falling one, and the
        // value there is the largest of these crossings.
        double best = -std::numeric_limits<double>::infinity(), x = -1;
        for(int p = 0; p < proxies; ++p) {
          const double up = a[i][p] - a[j][p];
          if(!(up > 0)) continue;
          for(int q = 0; q < proxies; ++q) {
            const double down = a[i][q] - a[j][q];
            if(!(down < 0)) continue;
            const double xc = (a[j][q] - a[j][p]) / (up - down);
            const double v = a[j][p] + xc * up;
            if(v > best) { best = v; x = xc; }
          }
        }
        if(!(x > 0 && x < 1)) continue; // the best weights use one ball, tried above
        double worst = -std::numeric_limits<double>::infinity();
        for(int p = 0; p < proxies; ++p) worst = (std::max)(worst, x * a[i][p] + (1 - x) * a[j][p]);
        if(!(worst < 0)) continue;
        const std::size_t idx[2] = {i, j};
        const double m[2] = {x, 1 - x};
        if(proves(idx, m, 2)) return true;
      }

    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j)
        for(std::size_t l = j + 1; l < k; ++l) {
          if((holds[i] | holds[j] | holds[l]) != all) continue;
          const std::size_t idx[3] = {i, j, l};
          // the weights that make the sums -1 at three corners (all but corner `skip`)
          for(int skip = 0; skip < 4; ++skip) {
            double M[3][3], m[3];
            for(int c = 0, row = 0; c < 4; ++c) {
              if(c == skip) continue;
              for(int t = 0; t < 3; ++t) M[row][t] = a[idx[t]][c];
              ++row;
            }
            if(!internal::weights_of_three(M, m) || !(m[0] > 0 && m[1] > 0 && m[2] > 0)) continue;
            const double sum = m[0] + m[1] + m[2]; // scale to sum 1, for the reader: the proof needs no scale
            for(double& x : m) x /= sum;
            double worst = -std::numeric_limits<double>::infinity();
            for(int p = 0; p < proxies; ++p)
              worst = (std::max)(worst, m[0] * a[i][p] + m[1] * a[j][p] + m[2] * a[l][p]);
            if(!(worst < 0)) continue;
            if(proves(idx, m, 3)) return true;
          }
        }
    return false;
  }

public:
  /// the paper's test, kept to show where it fails: true if the four corners are in the ball
  bool are_corners_covered(const Rectangle& f, const Point& center, double radius) const
  {
    for(double theta : {f.theta0, f.theta1})
      for(double z : {f.z0, f.z1}) {
        const Point p = at(theta, z);
        const double x = p[0] - center[0], y = p[1] - center[1], zz = p[2] - center[2];
        if(x * x + y * y + zz * zz > radius * radius) return false;
      }
    return true;
  }

  /// the two halves of `f` across its longer side on the sphere (see the class comment), the lower
  /// longitudes or heights first; precondition: `level(f) < max_level`
  template <class OutputIterator>
  OutputIterator split(const Fragment& f, OutputIterator out) const
  {
    CGAL_precondition(level(f) < max_level);
    const bool across_theta = halves_longitudes(rectangle(f));
    *out++ = child(f, across_theta, 0);
    *out++ = child(f, across_theta, 1);
    return out;
  }

  /// whether `split()` halves the longitudes of `f` (else its heights): whether its wider edge of
  /// constant height, R rho dtheta, is longer than the chord between its two heights in a meridian
  /// plane, R sqrt(drho^2 + dz^2) (any rule gives children that tile `f`; this one keeps cells about
  /// as wide as long, and near the poles, where no rectangle can be, wedges no wider than long)
  bool halves_longitudes(const Rectangle& f) const
  {
    const double rho0 = rho_of(f.z0), rho1 = rho_of(f.z1);
    const double width = (std::max)(rho0, rho1) * (f.theta1 - f.theta0);
    const double drho = rho0 - rho1, dz = f.z1 - f.z0;
    return width * width > drho * drho + dz * dz;
  }

  /// @}

private:
  static constexpr std::size_t max_union_balls = 16;   // the triple loop is cubic; a subset is always correct
  static constexpr std::size_t max_union_centers = 64; // the engine passes a dozen or so
  static constexpr int proxies = 8;                    // corners and middles of edges

  static double pi() { return 3.14159265358979323846; }
  static double quarter_turn() { return 0.5 * pi(); }

  // half c (0 the lower, 1 the upper) of f, across its longitudes or its heights
  static Fragment child(const Fragment& f, bool across_theta, int c)
  {
    Fragment g = f;
    if(across_theta) {
      g.i = 2 * f.i + std::uint64_t(c);
      g.halvings_theta = f.halvings_theta + 1;
    } else {
      g.j = 2 * f.j + std::uint64_t(c);
      g.halvings_z = f.halvings_z + 1;
    }
    return g;
  }

  static double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static double squared_length(const Point& a) { return dot(a, a); }

  // sqrt(1 - z^2) within 3 units of rounding, relative, for z in [-1, 1]: one of 1 - z and 1 + z is
  // exact (Sterbenz) where the other is near 2, and both are within one unit elsewhere. (1 - z * z
  // loses the rounding of z * z, which near a pole the square root turns into an absolute error of
  // up to 2^-42.)
  static double rho_of(double z) { return std::sqrt((std::max)(0., (1 - z) * (1 + z))); }

  Point at(double theta, double z) const
  {
    const double rho = rho_of(z);
    double s, c;
    internal::sin_cos(theta, s, c);
    return Point{{c_[0] + r_ * rho * c, c_[1] + r_ * rho * s, c_[2] + r_ * z}};
  }

  // Minimum of u . w over the rectangle, u = (rho cos theta, rho sin theta, z), rho = sqrt(1 - z^2).
  // For fixed z the theta part rho (wx cos theta + wy sin theta) is smallest at the same theta for
  // every z (rho >= 0), so the minimum is g(z) = m rho(z) + wz z with m the smallest value of
  // wx cos theta + wy sin theta on [theta0, theta1]. In phi, g = m sin phi + wz cos phi is a sinusoid:
  // its minimum on an interval is at an end, or at its trough when the trough is inside.
  // Given the cosines and sines of theta0 and theta1.
  static double min_dot(const Rectangle& f, const Point& w, double cos0, double sin0, double cos1, double sin1)
  {
    Ball b;
    b.w = w;
    b.wxy = length_xy(w);
    return min_dot(f, b, cos0, sin0, cos1, sin1);
  }

  // what is_covered() and min_dot() need of a ball, computed once for all the rectangles tested
  struct Ball
  {
    Point w;          // centre minus the sphere's centre
    double wxy;       // the length of (wx, wy)
    double threshold; // the rectangle is in the ball if min_dot() is at least this
  };
  static double length_xy(const Point& w) { return std::sqrt(w[0] * w[0] + w[1] * w[1]); }
  Ball ball(const Point& center, double radius) const
  {
    // |x - s|^2 = R^2 + |w|^2 - 2 R (u . w) for x = c + R u on the sphere and w = s - c, so the
    // rectangle is in the ball iff the minimum of u . w over it is at least t.
    Ball b;
    b.w = Point{{center[0] - c_[0], center[1] - c_[1], center[2] - c_[2]}};
    const double w2 = b.w[0] * b.w[0] + b.w[1] * b.w[1] + b.w[2] * b.w[2];
    b.wxy = length_xy(b.w);
    const double w_length = std::sqrt(w2);
    // A ball that holds the whole sphere, |w| + R < radius with the rounding of |w| (a few units in
    // the last place; 8 eps taken), covers every rectangle. Decided first: below, t and the margin
    // overflow where radius^2 / R does (radius above about 1e322 R made the threshold NaN, and no
    // rectangle was covered), and near radius = 2R the margin alone, 768 eps R, asks for a radius
    // above 2R (1 + 4e-14) where this asks for 2R (1 + 2e-15).
    if((w_length + r_) * (1 + 8 * std::numeric_limits<double>::epsilon()) < radius) {
      b.threshold = -std::numeric_limits<double>::infinity();
      return b;
    }
    const double t = (r_ * r_ + w2 - radius * radius) / (2 * r_);
    // The margin is relative to the sphere's radius, not to its centre's coordinates: no point of the
    // sphere is computed here, and w, a difference, is within u |w| of its exact value (u = eps / 2).
    // That moves u . w by u |w| and t by about 3 u |w|^2 / R; t's own rounding adds
    // 3 u (R^2 + |w|^2 + radius^2) / R, and min_dot() is within 20 u |w| of the exact minimum (see
    // is_covered_by_union()). For a ball that reaches the sphere, |w| <= R + radius, all of it is below
    // the margin, 64 eps R (1 + (|w| + radius) / R) (1 + radius / R); a ball that does not reach it
    // fails by far more than its rounding. (Far from the origin, position_error() includes the
    // rounding of the centre's coordinates: as a margin, it left a band along the balls' boundaries
    // that no single ball decided, where the union test, local, had proven coverage.)
    const double margin = 64 * std::numeric_limits<double>::epsilon() * (r_ + w_length + radius) *
                          (1 + radius / r_);
    b.threshold = t + margin;
    return b;
  }

  static double min_dot(const Rectangle& f, const Ball& b, double cos0, double sin0, double cos1, double sin1)
  {
    const Point& w = b.w;
    double m = (std::min)(w[0] * cos0 + w[1] * sin0, w[0] * cos1 + w[1] * sin1);
    if(b.wxy > 0) {
      // whether the longitude of -w is in [theta0, theta1], by the signs of the cross products of
      // -w with the directions of the ends: no arctangent. (Where rounding decides, -w is within a
      // few rounding errors of an end, and the two values of m differ by their square.)
      const double after0 = w[0] * sin0 - w[1] * cos0;  // -w is counterclockwise of theta0
      const double before1 = w[1] * cos1 - w[0] * sin1; // -w is clockwise of theta1
      m = (f.theta1 - f.theta0 <= pi() ? after0 >= 0 && before1 >= 0 : after0 >= 0 || before1 >= 0) ? -b.wxy : m;
    }
    auto g = [&](double z) { return m * rho_of(z) + w[2] * z; };
    double result = (std::min)(g(f.z0), g(f.z1));
    const double k = std::sqrt(m * m + w[2] * w[2]);
    if(m < 0 && k > 0) {
      const double z_trough = -w[2] / k; // where (sin phi, cos phi) = -(m, wz) / k
      if(f.z0 <= z_trough && z_trough <= f.z1) result = -k;
    }
    return result;
  }

  Point c_;
  double r_;
  double error_;
};

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_SPHERE_FRAGMENT_TRAITS_3_H
