// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_EXCEPTIONS_H
#define CGAL_POISSON_DISK_SAMPLING_3_EXCEPTIONS_H

#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Ref
/// Thrown for input that cannot be sampled: an empty surface, a face that is not a triangle,
/// NaN or infinite coordinates, a radius, minimum distance or point count that is not positive and
/// finite, a minimum distance outside 2^-400 to 2^400 or not above 2^20 times the coordinates'
/// rounding error, contradictory size parameters, among others (the user manual lists them all under
/// "Bad input": a parameter given twice, a negative seed, an area above the largest double, ...). The
/// message says which.
class Invalid_input : public std::invalid_argument
{
public:
  /// constructs the exception with a message
  explicit Invalid_input(const std::string& what) : std::invalid_argument("Poisson_disk_sampling_3: " + what) {}
};

/// \ingroup PkgPoissonDiskSampling3Ref
/// Thrown before any large allocation when a request would produce more points than the bound
/// `maximum_number_of_points` (default 100 million): the estimate area / (pi r^2) of a radius request,
/// or the target of a `number_of_points` request, is checked first, and the actual count while sampling
/// a radius request (thin or scattered surfaces can exceed the estimate; the runs of a
/// `number_of_points` search stop at the bound instead, see `Target_not_reached`). A `number_of_points`
/// search throws it too when it would try a distance at which area / (pi r^2) exceeds four times the
/// bound plus 64 (faces that overlap, or lie closer to each other than the distance, each count in
/// the area, and a run's time and memory follow it). Also thrown, before
/// any piece is stored, when a model's roots for the distance (the optional `initial_fragments(out, d)`
/// of `SurfaceFragmentTraits_3`) would outnumber its faces by more than four times that bound plus six
/// per face, the memory those take; and while sampling, when a model's fragments in wait outnumber 64
/// times its samples so far, its expected points and its initial fragments, plus 2^20 (a model whose
/// coverage tests never succeed: see `SurfaceFragmentTraits_3`), or 2^32 or more fragments of about the
/// same area would be in wait at once.
class Point_limit_exceeded : public std::length_error
{
public:
  /// constructs the exception with a message
  explicit Point_limit_exceeded(const std::string& what) : std::length_error("Poisson_disk_sampling_3: " + what) {}
};

/// \ingroup PkgPoissonDiskSampling3Ref
/// Thrown by the `number_of_points` mode when no minimum distance found within its iteration budget
/// gives the requested count within the tolerance (1%, at least one point), among which when every run
/// of its search was stopped, at twice the target and 64 or at `maximum_number_of_points` (more
/// far-apart components than that, for instance).
class Target_not_reached : public std::runtime_error
{
public:
  /// constructs the exception with a message
  explicit Target_not_reached(const std::string& what) : std::runtime_error("Poisson_disk_sampling_3: " + what) {}
};

namespace internal {

/// a number for a message, with six significant digits at any magnitude (`std::to_string` gives
/// "0.000000" for 1e-7)
inline std::string number_text(double x)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", x);
  return text;
}

/// throws `Invalid_input` unless the total area of a surface is positive and finite; `purpose` ends
/// the message ("sample", "certify")
inline void check_surface_area(double area, const char* purpose)
{
  if(!(area > 0))
    throw Invalid_input(std::string("the surface has no part of positive area to ") + purpose);
  if(!(area <= std::numeric_limits<double>::max()))
    throw Invalid_input(std::string("the surface's area overflows a double (above about 1.8e308); scale the "
                                    "input to ") + purpose);
}

} // namespace internal

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_EXCEPTIONS_H
