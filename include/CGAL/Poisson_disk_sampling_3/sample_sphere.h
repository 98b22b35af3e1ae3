// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_SPHERE_H
#define CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_SPHERE_H

#include <CGAL/Poisson_disk_sampling_3/Sphere_fragment_traits_3.h>
#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/nearest_double.h>
#include <CGAL/Poisson_disk_sampling_3/parameters.h>
#include <CGAL/Poisson_disk_sampling_3/sample_surface.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Sphere_3.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

template <class K>
Sphere_fragment_traits_3 sphere_traits(const CGAL::Sphere_3<K>& sphere)
{
  // a sphere is given by its squared radius, whose double may overflow (radii from about 1e154 up) or
  // underflow (below about 1e-162) where the radius would not: that is the number to name
  const double squared_radius = nearest_double(sphere.squared_radius());
  if(!(squared_radius > 0) || !std::isfinite(squared_radius))
    throw Invalid_input("the sphere's squared radius (" + number_text(squared_radius) +
                        " as a double) must be positive and finite");
  return Sphere_fragment_traits_3(nearest_doubles(sphere.center()), std::sqrt(squared_radius));
}

/// Whether the ball of radius `d` around `p` holds the whole sphere of `traits`, or leaves out of it
/// only a cap within the rounding of the coverage tests: the point of the sphere farthest from p is
/// |p - c| + R away, and the test is |p - c| + R <= d + 2^-48 R, exact. Samples are the sphere's
/// points rounded to doubles, so |p - c| is R within that rounding: about 2^-52 R near the origin,
/// but half a unit in the last place of the centre's coordinates far from it (7.5 10^-9 a coordinate
/// at 10^8, up to about 1.3 10^-8 in all), which leaves a cap of the sphere farther than d from p,
/// a gap, at distances well above 2R.
inline bool one_sample_holds_sphere(const Sphere_fragment_traits_3& traits, const Sphere_fragment_traits_3::Point& p,
                                    double d)
{
  const double R = traits.radius();
  if(!(d >= 2 * R)) return false;
  typedef CGAL::Exact_rational ET;
  ET w2(0);
  for(int i = 0; i < 3; ++i) {
    const ET wi = ET(p[i]) - ET(traits.center()[i]);
    w2 += wi * wi;
  }
  const ET reach = ET(d) - ET(R) + ET(0x1.0p-48 * R); // positive: d >= 2R
  return w2 <= reach * reach;
}

} // namespace internal

/// \ingroup PkgPoissonDiskSampling3Ref
/// Generates a maximal Poisson-disk sample set on a sphere (paper Section 5.1), with Euclidean
/// (chordal) distances between samples.
///
/// @tparam K a CGAL kernel
/// @tparam PointOutputIterator an output iterator accepting `K::Point_3`
/// @tparam NamedParameters a sequence of named parameters, as for `sample_surface()`
///
/// @param sphere the sphere (its orientation is ignored)
/// @param out where the points are written
/// @param np exactly one of `radius`, `minimum_distance` and `number_of_points`, and the options of
///        `sample_surface()`
///
/// A minimum distance of the diameter 2R or more gives one uniform point, or more far from the
/// origin (below): every point of the sphere is within 2R of it. Up to about 2R (1 + 2 10^-15), the
/// antipode's distance 2R is within the rounding of d, and `is_maximal()` answers such a set
/// undecided. (From 2R up, `sample_sphere()` stops the engine after its first sample p if the
/// farthest point of the sphere, |p - c| + R away, is at most d + 2^-48 R away, decided exactly,
/// without the engine's coverage tests; `sample_surface()` with the sphere's model does not, and
/// from 2R to about 2R (1 + 2 10^-15) it can stop with `Point_limit_exceeded`. On a sphere far from
/// the origin, p, rounded to the centre's unit in the last place, can lie farther outside the
/// sphere, and its ball leave a cap out: the run then goes on, and gives two points or more. A
/// one-point set whose |p - c| + R is within about 2^-48 R of d is answered undecided by
/// `is_maximal()`, at any d: rare far from the origin, about once in a million runs.)
///
/// \returns the output iterator past the last point
/// \throws Invalid_input for a sphere whose squared radius is not positive and finite as a double, a
///         non-finite centre or a bad size
/// \throws Point_limit_exceeded when the request exceeds `maximum_number_of_points`
/// \throws Target_not_reached when `number_of_points` cannot be met
template <class K, class PointOutputIterator, class NamedParameters = CGAL::parameters::Default_named_parameters>
PointOutputIterator sample_sphere(const CGAL::Sphere_3<K>& sphere, PointOutputIterator out,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  Sampling_statistics local; // (if not given)
  // cleared before the sphere is checked, which may throw
  Sampling_statistics& stats = internal::clear_statistics(np, local);
  const Sphere_fragment_traits_3 traits = internal::sphere_traits(sphere);
  auto emit = [&](const Sphere_fragment_traits_3::Sample& s) {
    *out++ = internal::output_point<typename K::Point_3>(s.point);
  };
  // From the diameter up, one point covers the sphere, but the point of the sphere farthest from it,
  // its antipode, is 2R away, within the rounding of the coverage tests of d from d = 2R to about
  // 2R (1 + 2 10^-15): there the engine could prove no fragment around the antipode covered, and
  // refined a cap around it down to its depth floor, until the bound on the fragments in wait
  // stopped it (Point_limit_exceeded, after 1.5 s); far above, the tests overflowed. So a run at 2R
  // or more returns after its first sample where that sample's ball holds the sphere, up to that
  // rounding; where it leaves a larger cap out (a sphere far from the origin, whose points are
  // rounded far more than R's unit in the last place), the run goes on and fills it.
  internal::sample_request(traits, np, stats, emit,
                           internal::Holds_surface<Sphere_fragment_traits_3>(
                               [&traits](const Sphere_fragment_traits_3::Sample& s, double d) {
                                 return internal::one_sample_holds_sphere(traits, s.point, d);
                               }));
  return out;
}

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_SPHERE_H
