// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_SPHERE_FRAGMENT_TRAITS_3_H
#define CGAL_POISSON_DISK_SAMPLING_3_SPHERE_FRAGMENT_TRAITS_3_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Concepts
/// \cgalModels `SurfaceFragmentTraits_3`
///
/// The sphere (paper Section 5.1). Fragments are spherical rectangles [theta0, theta1] x [z0, z1] in
/// longitude theta and height z = cos(phi) above the centre: the paper's rectangles in (theta, phi),
/// stored by the cosines of their polar angles. The area is the paper's Equation 1,
/// R^2 (theta1 - theta0)(cos phi0 - cos phi1), and a uniform point is the paper's inverse CDF:
/// theta uniform, cos(phi) uniform. Children split both ranges at their middle, so the four children
/// have equal areas.
///
/// Coverage: the paper tests the four corners of a rectangle against the ball, which fails near the
/// poles, where the edges of constant phi are not great circles and bulge out of the ball between two
/// inside corners. `is_covered()` instead finds the minimum over the whole rectangle of the distance
/// criterion in closed form (corners, the extreme point of each edge, the antipode), so it is right
/// everywhere.
class Sphere_fragment_traits_3
{
public:
  /// \name Types
  /// @{

  /// a point, as the engine computes with it
  typedef std::array<double, 3> Point;

  /// a spherical rectangle
  struct Fragment
  {
    double theta0;  ///< smallest longitude, in [0, 2 pi]
    double theta1;  ///< largest longitude, in [0, 2 pi]
    double z0;      ///< smallest height cos(phi), in [-1, 1]
    double z1;      ///< largest height cos(phi), in [-1, 1]
  };

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

  /// the eight octants
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out) const
  {
    const double q = 0.5 * pi();
    for(int i = 0; i < 4; ++i)
      for(int j = 0; j < 2; ++j)
        *out++ = Fragment{i * q, i == 3 ? 2 * pi() : (i + 1) * q, j - 1., double(j)};
    return out;
  }

  /// paper Equation 1
  double area(const Fragment& f) const { return r_ * r_ * (f.theta1 - f.theta0) * (f.z1 - f.z0); }

  /// the paper's inverse CDF: theta and cos(phi) uniform; never refused
  template <class RandomGenerator>
  std::optional<Sample> random_sample(const Fragment& f, RandomGenerator& rng) const
  {
    const double theta = f.theta0 + rng.uniform() * (f.theta1 - f.theta0);
    const double z = f.z0 + rng.uniform() * (f.z1 - f.z0);
    return Sample{at(theta, z)};
  }

  /// the point of a sample
  const Point& point(const Sample& s) const { return s.point; }

  /// the point at the middle of the parameter ranges
  Point reference_point(const Fragment& f) const { return at(0.5 * (f.theta0 + f.theta1), 0.5 * (f.z0 + f.z1)); }

  /// true only if every point of the rectangle is within `radius` of `center`, with a margin larger
  /// than the rounding error
  bool is_covered(const Fragment& f, const Point& center, double radius) const
  {
    // |x - s|^2 = R^2 + |w|^2 - 2 R (u . w) for x = c + R u on the sphere and w = s - c, so the
    // rectangle is in the ball iff the minimum of u . w over it is at least t.
    const Point w{{center[0] - c_[0], center[1] - c_[1], center[2] - c_[2]}};
    const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    const double t = (r_ * r_ + w2 - radius * radius) / (2 * r_);
    const double margin = error_ * (1 + (std::sqrt(w2) + radius) / r_) * (1 + radius / r_);
    return min_dot(f, w) >= t + margin;
  }

  /// the paper's test, kept to show where it fails: true if the four corners are in the ball
  bool are_corners_covered(const Fragment& f, const Point& center, double radius) const
  {
    for(double theta : {f.theta0, f.theta1})
      for(double z : {f.z0, f.z1}) {
        const Point p = at(theta, z);
        const double x = p[0] - center[0], y = p[1] - center[1], zz = p[2] - center[2];
        if(x * x + y * y + zz * zz > radius * radius) return false;
      }
    return true;
  }

  /// the four children: both ranges split at their middle
  template <class OutputIterator>
  OutputIterator split(const Fragment& f, OutputIterator out) const
  {
    const double tm = 0.5 * (f.theta0 + f.theta1), zm = 0.5 * (f.z0 + f.z1);
    *out++ = Fragment{f.theta0, tm, f.z0, zm};
    *out++ = Fragment{tm, f.theta1, f.z0, zm};
    *out++ = Fragment{f.theta0, tm, zm, f.z1};
    *out++ = Fragment{tm, f.theta1, zm, f.z1};
    return out;
  }

  /// @}

private:
  static double pi() { return 3.14159265358979323846; }

  Point at(double theta, double z) const
  {
    const double rho = std::sqrt((std::max)(0., 1 - z * z));
    return Point{{c_[0] + r_ * rho * std::cos(theta), c_[1] + r_ * rho * std::sin(theta), c_[2] + r_ * z}};
  }

  // Minimum of u . w over the rectangle, u = (rho cos theta, rho sin theta, z), rho = sqrt(1 - z^2).
  // For fixed z the theta part rho (wx cos theta + wy sin theta) is smallest at the same theta for
  // every z (rho >= 0), so the minimum is g(z) = m rho(z) + wz z with m the smallest value of
  // wx cos theta + wy sin theta on [theta0, theta1]. In phi, g = m sin phi + wz cos phi is a sinusoid:
  // its minimum on an interval is at an end, or at its trough when the trough is inside.
  static double min_dot(const Fragment& f, const Point& w)
  {
    const double wxy = std::sqrt(w[0] * w[0] + w[1] * w[1]);
    double m = (std::min)(w[0] * std::cos(f.theta0) + w[1] * std::sin(f.theta0),
                          w[0] * std::cos(f.theta1) + w[1] * std::sin(f.theta1));
    if(wxy > 0) {
      double away = std::atan2(-w[1], -w[0]); // longitude of -w, where the theta part is smallest
      if(away < 0) away += 2 * pi();
      if(f.theta0 <= away && away <= f.theta1) m = -wxy;
    }
    auto g = [&](double z) { return m * std::sqrt((std::max)(0., 1 - z * z)) + w[2] * z; };
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
