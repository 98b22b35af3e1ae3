// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_TRIANGLE_IN_BALL_UNION_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_TRIANGLE_IN_BALL_UNION_H

#include <CGAL/Poisson_disk_sampling_3/internal/power_of_half.h>
#include <CGAL/Poisson_disk_sampling_3/internal/weights_of_three.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// Whether a triangle lies in the union of equal balls, decided so that a `true` answer is a proof.
///
/// Why the test works: the triangle T is covered iff f(x) = min_i |x - c_i|^2 - r^2 is <= 0 on T.
/// On the part of T in the Voronoi cell of c_i, f is the convex |x - c_i|^2 - r^2, whose maximum
/// over that convex polygon is at one of its vertices: a corner of T, a point where an edge of T
/// meets the bisector plane of two centres, or a point of T's plane equidistant from three centres.
/// So T is covered iff every such point that lies in T is strictly inside some ball. The test
/// computes all these candidate points (linear solves only: no square roots, no tangencies) and
/// checks each one; checking candidates that are not Voronoi vertices, or that lie just outside T,
/// can only turn a `true` into a `false`, never the reverse. (With balls of different radii the
/// bisector planes become radical planes and the same argument holds.)
///
/// Where it cannot be sure, a second proof follows (`by_convexity`): it settles tiny covered
/// triangles, whose candidate points the rounding bounds below cannot decide.
///
/// Rigour: the test divides nowhere (a point is kept as a numerator and a denominator), and computes
/// on `Bounded` numbers, doubles that carry a bound of their rounding error: the answer is `true`
/// only if every comparison is certain; near-degenerate configurations (an edge parallel to a
/// bisector plane through it, three centres whose bisectors do not meet in one point) answer
/// `false`, and the engine then splits the fragment, which is always safe. Points are taken relative
/// to the first corner, which keeps the bounds small far from the origin.
///
/// The triangle is given by the double corners computed by the model; the exact triangle's corners
/// are within `corner_error` of them, so every point of the exact triangle is within `corner_error`
/// of the same barycentric point of the computed one: the balls are shrunk by `corner_error`.
class Triangle_in_ball_union
{
public:
  typedef std::array<double, 3> Point;
  static constexpr std::size_t max_balls = 16; // the triple loop is cubic; a subset is always correct

  /// `centers` may hold any samples: the ones that cannot meet the triangle are dropped here, and
  /// any subset of the balls gives a correct (perhaps more often negative) answer. The corners may be
  /// given relative to a point `origin`: the centres are then taken relative to it too (c - origin,
  /// rounded; `corner_error` must cover that rounding as well).
  template <class PointRange>
  static bool covers(const Point (&corner)[3], const PointRange& centers, double radius, double corner_error,
                     const Point& origin = Point{{0, 0, 0}})
  {
    const double r = radius - corner_error;
    if(!(r > 0)) return false;
    // most triangles that reach this test have a corner outside every ball: find out first
    for(const Point& p : corner)
      if(!is_inside_one(p, centers, r, origin)) return false;
    return covers_with_corners_inside(corner, centers, radius, corner_error, origin);
  }

  /// whether p is strictly inside one of the balls of radius r (computed as `covers()` decides it
  /// for the corners), with p and the centres taken relative to `origin` as in `covers()`
  template <class PointRange>
  static bool is_inside_one(const Point& p, const PointRange& centers, double r,
                            const Point& origin = Point{{0, 0, 0}})
  {
    bool inside = false;
    for(const auto& c : centers) {
      const double x = p[0] - (c[0] - origin[0]), y = p[1] - (c[1] - origin[1]), z = p[2] - (c[2] - origin[2]);
      inside |= x * x + y * y + z * z < r * r;
    }
    return inside;
  }

  /// Writes to `out` the balls of `centers`, in their order, whose centres are closer than `reach` to
  /// g, up to max_balls + 1 of them (`out` has room for max_balls + 2), and returns how many: max_balls
  /// + 1 means that more than max_balls are. Every ball is written, and the count passes it only if
  /// it is that close: no branch on which balls are, a coin toss for the branch predictor. g and the
  /// centres written are relative to `origin` (c - origin, rounded).
  template <class PointRange>
  static std::size_t balls_near(const PointRange& centers, const double (&g)[3], double reach, Point* out,
                                const Point& origin = Point{{0, 0, 0}})
  {
    std::size_t k = 0;
    for(const auto& c : centers) {
      out[k] = Point{{c[0] - origin[0], c[1] - origin[1], c[2] - origin[2]}};
      const double x = out[k][0] - g[0], y = out[k][1] - g[1], z = out[k][2] - g[2];
      k += std::size_t(x * x + y * y + z * z < reach * reach) & std::size_t(k <= max_balls);
    }
    return k;
  }

  /// `covers()` without its first step, for a triangle whose corners `is_inside_one()` has found
  /// inside the balls shrunk by `corner_error` (with radius - corner_error > 0). It is as sound for
  /// any triangle: the candidate points it checks include the corners.
  template <class PointRange>
  static bool covers_with_corners_inside(const Point (&corner)[3], const PointRange& centers, double radius,
                                         double corner_error, const Point& origin = Point{{0, 0, 0}})
  {
    const double r = radius - corner_error;
    // Only the balls that meet T matter: the union of the others misses T. Keep the balls that meet
    // T's circumscribing ball around its centroid; the test is cubic in their number, and this keeps
    // two or three for a small fragment instead of the dozen a box would. (Rounding here only drops
    // or keeps a ball: any subset of the balls gives a correct answer, so the first max_balls are
    // enough.)
    double g[3], reach2 = 0;
    for(int i = 0; i < 3; ++i) g[i] = (corner[0][i] + corner[1][i] + corner[2][i]) / 3;
    for(const Point& p : corner) {
      const double x = p[0] - g[0], y = p[1] - g[1], z = p[2] - g[2];
      reach2 = (std::max)(reach2, x * x + y * y + z * z);
    }
    const double reach = (r + std::sqrt(reach2)) * (1 + 1e-9);
    Point kept[max_balls + 2];
    const std::size_t k = (std::min)(balls_near(centers, g, reach, kept, origin), max_balls);
    if(k == 0) return false;
    // (Nothing cheaper comes first: a `Bounded` operation costs about what a double one does, and a
    // triangle that is not covered fails at one of the first candidate points.)
    const Verdict verdict = decide(corner, kept, k, radius, corner_error);
    return verdict == covered || (verdict == unsure && by_convexity(corner, kept, k, r));
  }

private:
  // The proof for what the candidate-point test is unsure of. g_i(x) = |x - c_i|^2 - r^2 is convex,
  // so on T, g_i(x) <= sum_k l_k g_i(v_k) for the barycentric coordinates l of x. If weights m_i >= 0
  // make sum_i m_i g_i(v_k) < 0 at the three corners v_k, then sum_i m_i g_i(x) < 0 on all of T, so
  // some g_i(x) < 0: every point of T is strictly inside a ball. The best weights solve a linear
  // program whose optimum has at most three positive weights (three corner constraints and the
  // normalisation), so trying every pair and triple of balls finds them; a weight vector is accepted
  // only if the corner sums are negative by more than a bound on their rounding error. Blind only
  // where T's points are within about diameter(T)^2 / 2r of the union's boundary (3 in 10 of the
  // covered triangles that reach the union test on lion.off), but its rounding bounds do not grow as
  // T shrinks, where those of the candidate points do: it proves the tiny covered triangles that the
  // candidate-point test cannot.
  static bool by_convexity(const Point (&corner)[3], const Point* centers, std::size_t k, double r)
  {
    const double r2 = r * r;
    double a[max_balls][3], m2[max_balls][3]; // g_i(v_k) and |v_k - c_i|^2
    for(std::size_t i = 0; i < k; ++i)
      for(int c = 0; c < 3; ++c) {
        const double x = corner[c][0] - centers[i][0], y = corner[c][1] - centers[i][1],
                     z = corner[c][2] - centers[i][2];
        m2[i][c] = x * x + y * y + z * z;
        a[i][c] = m2[i][c] - r2;
      }
    // sum_i w_i a_i(v_c) < 0 at every corner, by more than the rounding of a and of the sums: each a
    // is within 6 units in the last place of |v - c|^2 + r^2, each sum of at most 3 weighted terms
    // within 4 more; 1e-14 is more than twice what that makes.
    auto proves = [&](const std::size_t* idx, const double* w, std::size_t n) {
      for(int c = 0; c < 3; ++c) {
        double sum = 0, bound = 0;
        for(std::size_t t = 0; t < n; ++t) {
          sum += w[t] * a[idx[t]][c];
          bound += w[t] * (m2[idx[t]][c] + r2);
        }
        if(!(sum + 1e-14 * bound < 0)) return false;
      }
      return true;
    };
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j) {
        // w a_i + (1 - w) a_j at corner c is a line in w; the best w is where two of them cross
        const std::size_t idx[2] = {i, j};
        for(int c = 0; c < 3; ++c)
          for(int e = c + 1; e < 3; ++e) {
            const double den = (a[i][c] - a[j][c]) - (a[i][e] - a[j][e]);
            if(!(den != 0)) continue;
            const double w = (a[j][e] - a[j][c]) / den;
            if(!(w > 0 && w < 1)) continue;
            const double ws[2] = {w, 1 - w};
            if(proves(idx, ws, 2)) return true;
          }
        for(std::size_t l = j + 1; l < k; ++l) {
          // the weights that make the three corner sums -1; if one is negative, the best weights, if
          // any, use fewer balls (the pairs above)
          const std::size_t idx3[3] = {i, j, l};
          double A[3][3], w[3];
          for(int c = 0; c < 3; ++c)
            for(int t = 0; t < 3; ++t) A[c][t] = a[idx3[t]][c];
          if(!weights_of_three(A, w) || !(w[0] > 0 && w[1] > 0 && w[2] > 0)) continue;
          if(proves(idx3, w, 3)) return true;
        }
      }
    return false;
  }

  // A number computed from the inputs by additions, subtractions and multiplications only, with `a`
  // the same computation on the absolute values of the inputs. Expanded into monomials, the computed
  // v is the exact value with each monomial multiplied by at most n factors (1 + delta), |delta| <= u
  // = 2^-53, where n counts the roundings on the way: an input's own rounding counts 1, a sum one more
  // than the larger count of its terms, a product one more than the sum of the counts of its factors.
  // So |v - exact| <= gamma_n a, gamma_n = n u / (1 - n u) (Higham, Accuracy and Stability of
  // Numerical Algorithms, 2nd ed., Lemma 3.1 and 3.4), and the computed a is at least (1 - gamma_n)
  // times the exact one. The largest count in `decide` is 42 (whether the point equidistant from
  // three centres is inside a ball): gamma_42 < 4.7e-15, and 1e-13 a bounds the
  // error with room to spare. The coordinates are scaled by a power of two near 1 / radius, so that
  // values stay far from underflow and overflow; the 1e-280 covers what a subnormal could lose.
  // Where the compiler has vectors of two doubles, v and a are one, so that each operation is one
  // instruction (a difference two: the sign of o.v is flipped by an exact product).
#if defined(__GNUC__)
  typedef double Pair __attribute__((vector_size(16)));
  struct Bounded
  {
    Pair p; // {v, a}
    double v() const { return p[0]; }
    double a() const { return p[1]; }
    static Bounded of(double v, double a) { return {Pair{v, a}}; }
    Bounded operator+(const Bounded& o) const { return {p + o.p}; }
    Bounded operator-(const Bounded& o) const { return {p + o.p * Pair{-1., 1.}}; }
    Bounded operator*(const Bounded& o) const { return {p * o.p}; }
  };
#else
  struct Bounded
  {
    double v_, a_;
    double v() const { return v_; }
    double a() const { return a_; }
    static Bounded of(double v, double a) { return {v, a}; }
    Bounded operator+(const Bounded& o) const { return {v_ + o.v_, a_ + o.a_}; }
    Bounded operator-(const Bounded& o) const { return {v_ - o.v_, a_ + o.a_}; }
    Bounded operator*(const Bounded& o) const { return {v_ * o.v_, a_ * o.a_}; }
  };
#endif

  // Inputs and constants, and the sign tests: only what the error bound makes certain.
  static Bounded number(double x) { return Bounded::of(x, std::abs(x)); }
  static bool negative(const Bounded& x) { return x.v() < -(1e-13 * x.a() + 1e-280); }
  static bool positive(const Bounded& x) { return x.v() > 1e-13 * x.a() + 1e-280; }

  struct V
  {
    Bounded x, y, z;
    Bounded dot(const V& o) const { return x * o.x + y * o.y + z * o.z; }
  };

  // `covered` is a proof. `not_covered`: a candidate point was found outside every ball beyond the
  // rounding bounds, so no other proof can succeed (a hint, used only to skip `by_convexity`).
  // `unsure`: some comparison was within the rounding bounds.
  enum Verdict { covered, not_covered, unsure };

  // The candidate-point test of the class comment, in the parameters (s, t) of T's plane: with T's
  // corners o, o + a and o + b, its points are x = o + s a + t b with s, t >= 0 and s + t <= 1, and for
  // a centre c (taken relative to o)
  //   |x - c|^2 - r^2 = Q(s, t) - s 2 a.c - t 2 b.c + |c|^2 - r^2,  Q(s, t) = |s a + t b|^2,
  // so the bisector plane of centres i and j meets T's plane in the line where the linear
  // L(s, t) = s (2 a.c_j - 2 a.c_i) + t (2 b.c_j - 2 b.c_i) - (|c_j|^2 - |c_i|^2) is zero (L is the
  // difference of the two squared distances), and a point equidistant from three centres solves two
  // such equations. Every candidate point is kept as (S / D, T / D): it is strictly inside ball m iff
  //   Q(S, T) - D (S 2 a.c_m + T 2 b.c_m) + D^2 (|c_m|^2 - r^2) < 0,
  // where Q(S, T) is the same for all balls; and it is outside T by the signs of S, T and D - S - T
  // times the sign of D. No division, no normal vector; the largest rounding count (the test above
  // for a point equidistant from three centres) is 42.
  static Verdict decide(const Point (&corner)[3], const Point* centers, std::size_t k, double radius,
                        double shrink)
  {
    const Point& o = corner[0];
    // 2^-e for radius = m 2^e, m in [1/2, 1) (std::frexp's e, without a call of the library): the
    // scaled radius is m, exactly
    const double scale = times_power_of_two(1., -(binary_exponent(radius) + 1));
    auto rel = [&](const Point& p) {
      return V{number((p[0] - o[0]) * scale), number((p[1] - o[1]) * scale), number((p[2] - o[2]) * scale)};
    };
    const Bounded rr = number((radius - shrink) * scale);
    const Bounded r2 = rr * rr;
    const Bounded zero = number(0), one = number(1);
    const V a = rel(corner[1]), b = rel(corner[2]);
    const Bounded aa = a.dot(a), bb = b.dot(b), ab = a.dot(b), ab2 = ab + ab;
    Bounded pa[max_balls], pb[max_balls], c2[max_balls], g[max_balls]; // 2 a.c, 2 b.c, |c|^2, |c|^2 - r^2
    for(std::size_t i = 0; i < k; ++i) {
      const V c = rel(centers[i]);
      const Bounded ac = a.dot(c), bc = b.dot(c);
      pa[i] = ac + ac;
      pb[i] = bc + bc;
      c2[i] = c.dot(c);
      g[i] = c2[i] - r2;
    }

    // strictly inside some ball: every ball is tried, with no branch on the answers (which ball
    // holds a point, if any, is a coin toss for the branch predictor)
    bool sure = true; // after `inside` returned false: whether every ball was certainly outside
    auto inside = [&](const Bounded& S, const Bounded& T, const Bounded& D) {
      const Bounded q = S * (aa * S + ab2 * T) + bb * T * T, dd = D * D;
      bool in = false, out = true;
      for(std::size_t m = 0; m < k; ++m) {
        const Bounded excess = q - D * (S * pa[m] + T * pb[m]) + dd * g[m];
        in |= negative(excess);
        out &= positive(excess);
      }
      sure = out;
      return in;
    };

    if(!inside(zero, zero, one) || !inside(one, zero, one) || !inside(zero, one, one))
      return sure ? not_covered : unsure;

    // edges meet the lines L = 0; with the values s0, s1, s2 of L at the corners (0, 0), (1, 0) and
    // (0, 1), the line meets the edge from corner e to corner e + 1 where L is zero: at (s0, 0) / D
    // on the first, (-s2, s1) / D on the second and (0, -s0) / D on the third, D = s_e - s_e+1.
    // Bit j of misses[i]: L certainly has one sign on T, so the bisector plane of i and j misses T,
    // and so does every point equidistant from i, j and a third centre (it is on that plane): the
    // loop below skips them.
    std::uint32_t misses[max_balls] = {};
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j) {
        const Bounded h = c2[j] - c2[i];
        const Bounded s[3] = {zero - h, (pa[j] - pa[i]) - h, (pb[j] - pb[i]) - h};
        const bool above = positive(s[0]) && positive(s[1]) && positive(s[2]);
        if(above || (negative(s[0]) && negative(s[1]) && negative(s[2]))) {
          misses[i] |= std::uint32_t(1) << j;
          continue;
        }
        for(int ed = 0; ed < 3; ++ed) {
          // no crossing if both ends are strictly on one side
          const Bounded &s0 = s[ed], &s1 = s[(ed + 1) % 3];
          if((positive(s0) && positive(s1)) || (negative(s0) && negative(s1))) continue;
          const Bounded den = s0 - s1;
          if(!positive(den) && !negative(den)) return unsure; // the edge may lie in the plane
          const bool in = ed == 0 ? inside(s[0], zero, den)
                                  : ed == 1 ? inside(zero - s[2], s[1], den) : inside(zero, zero - s[0], den);
          if(!in) return sure ? not_covered : unsure;
        }
      }

    // points of T's plane equidistant from three centres, but for those on a plane that misses T:
    // L_ij = L_il = 0, that is s P1 + t Q1 = H1 and s P2 + t Q2 = H2
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j) {
        if(misses[i] >> j & 1) continue;
        const Bounded P1 = pa[j] - pa[i], Q1 = pb[j] - pb[i], H1 = c2[j] - c2[i];
        for(std::size_t l = j + 1; l < k; ++l) {
          if((misses[i] >> l & 1) || (misses[j] >> l & 1)) continue;
          const Bounded P2 = pa[l] - pa[i], Q2 = pb[l] - pb[i], H2 = c2[l] - c2[i];
          const Bounded det = P1 * Q2 - Q1 * P2;
          const bool up = positive(det);
          if(!up && !negative(det)) return unsure; // the three bisectors may not meet in one point
          const Bounded S = H1 * Q2 - Q1 * H2, T = P1 * H2 - H1 * P2; // the point is (S, T) / det
          const Bounded rest = det - S - T;
          const bool outside = up ? negative(S) || negative(T) || negative(rest)
                                  : positive(S) || positive(T) || positive(rest);
          if(outside) continue;
          if(!inside(S, T, det)) return sure ? not_covered : unsure;
        }
      }
    return covered;
  }
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_TRIANGLE_IN_BALL_UNION_H
