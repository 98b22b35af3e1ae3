// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_IS_MAXIMAL_H
#define CGAL_POISSON_DISK_SAMPLING_3_IS_MAXIMAL_H

#include <CGAL/Poisson_disk_sampling_3/is_poisson_disk_set.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Coverage_certifier.h>
#include <CGAL/Poisson_disk_sampling_3/sample_sphere.h>
#include <CGAL/Poisson_disk_sampling_3/sample_triangle_mesh.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Ref
/// The answer of `is_maximal()`: converts to `true` when every point of the surface is proven to lie
/// within the minimum distance of a sample.
/// @tparam Point_3 the point type of the surface
template <class Point_3>
struct Maximality_check
{
  bool maximal = true;  ///< every point of the surface is within the minimum distance of a sample
  /// when not maximal: total area of the pieces of the surface that could not be proven covered, an
  /// upper bound of the uncovered area (pieces are refined down to area max(d^2 / 64, 2^-20 of the
  /// surface's area) before being counted)
  double uncovered_area = 0;
  /// when not maximal, a point of the surface, up to the rounding of its coordinates, proven farther
  /// than the minimum distance from every sample, with a margin for that rounding (a place where one
  /// more sample fits), if one was found. `maximal` false and no point means undecided: the
  /// certificate's bounds on work, memory or depth ran out before it could prove the pieces left
  /// either covered or uncovered, or those pieces filled a region within rounding of the distance
  /// from the samples (see the user manual, "Validation")
  std::optional<Point_3> uncovered_point;
  /// `maximal`
  explicit operator bool() const { return maximal; }
};

namespace internal {

/// the points of `xyz` (three coordinates each) with each copy of a point but one left out, in
/// lexicographic order: each sample is tested wherever it reaches (until one's ball holds the piece),
/// and copies would only repeat the tests (10,000 copies of one point on 20 copies of a face took 22 s
/// to certify). O(n log n).
inline std::vector<double> distinct_coordinates(std::vector<double> xyz)
{
  std::vector<std::array<double, 3>> points(xyz.size() / 3);
  for(std::size_t i = 0; i < points.size(); ++i) points[i] = {{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}};
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  // written back into `xyz`, whose memory is reused: two copies of the coordinates at most
  xyz.resize(3 * points.size());
  for(std::size_t i = 0; i < points.size(); ++i) std::copy(points[i].begin(), points[i].end(), xyz.begin() + 3 * i);
  return xyz;
}

template <class Point_3, class Traits, class PointRange>
Maximality_check<Point_3> check_maximal(const Traits& traits, const PointRange& samples, double d)
{
  check_distance(d);
  check_distance_range(d);
  check_distance_precision(d, traits.position_error());
  const std::vector<double> xyz = distinct_coordinates(coordinates_of(samples));
  const Point_hash_grid grid = grid_of(xyz, d);
  const Certificate c = certify_coverage(traits, grid, d);
  Maximality_check<Point_3> result;
  result.maximal = c.maximal;
  result.uncovered_area = c.uncovered_area;
  if constexpr(std::is_same<Point_3, std::array<double, 3>>::value) {
    if(c.has_witness) result.uncovered_point = c.witness;
  } else {
    if(c.has_witness) result.uncovered_point = Point_3(c.witness[0], c.witness[1], c.witness[2]);
  }
  return result;
}

/// whether `NamedParameters` holds none of the sampling functions' own parameters, which `is_maximal()`
/// would ignore (it takes the distance as an argument: `radius(r)` there asked for nothing)
template <class NamedParameters>
constexpr bool has_no_sampling_parameter()
{
  using CGAL::parameters::is_default_parameter;
  return is_default_parameter<NamedParameters, internal_np::radius_t>::value &&
         is_default_parameter<NamedParameters, internal_np::minimum_distance_t>::value &&
         is_default_parameter<NamedParameters, internal_np::number_of_points_t>::value &&
         is_default_parameter<NamedParameters, internal_np::maximum_number_of_points_t>::value &&
         is_default_parameter<NamedParameters, internal_np::statistics_t>::value &&
         is_default_parameter<NamedParameters, internal_np::concurrency_t>::value &&
         is_default_parameter<NamedParameters, CGAL::internal_np::random_seed_t>::value;
}

} // namespace internal

/// \ingroup PkgPoissonDiskSampling3Ref
/// Certifies that `samples` is maximal on a triangle mesh for the minimum distance d: no point of the
/// surface is farther than d from every sample, so no sample can be added.
///
/// Each face is split by midpoints (a face much longer than d is first cut into blocks of rows, which
/// are halved) until the ball of radius d around one sample holds the corners of each piece, with a
/// margin larger than the rounding error of the corners, down to pieces 2^-48 the size of their face. A
/// `true` answer is a proof. A piece whose reference point (a triangle's centroid, a block's middle),
/// as computed, is farther than d from every sample by more than twice the rounding of the surface's
/// points (`Triangle_fragment_traits_3::position_error()`, decided exactly) is a proven gap, so that
/// the exact point is farther than d; the computed one is reported as `uncovered_point`. The work and
/// the memory are bounded (10 million pieces in the last phase, 10 million and 256 per sample and per
/// face in the first, a sample tested on a piece counting a sixteenth of one, 2.5 million waiting at a
/// time, and pieces that fill a region within rounding of d from the samples are not refined further;
/// copies of a sample are tested once): on slivers far thinner than d, which midpoint subdivision must
/// cut across as often as along, and on sets maximal with no margin (a point of the surface at
/// distance d from the samples), the answer may be `false` with no `uncovered_point`, undecided.
/// Coordinates are read as the nearest doubles. The samples are not required to lie on the surface (any
/// points may be certified), and faces of zero area (corners on one line) are skipped, as the sampler
/// skips them.
///
/// @tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// @tparam PointRange a range of `Point_3` of any CGAL kernel
/// @tparam NamedParameters accepts `vertex_point_map` and `geom_traits`, as `sample_triangle_mesh()`; the
/// sampling parameters (`radius`, `random_seed`, ...) do not compile here
///
/// @param tm the mesh
/// @param samples the samples to certify
/// @param minimum_distance the distance d = 2r they were sampled for
/// @param np the named parameters `vertex_point_map` and `geom_traits`
///
/// \throws Invalid_input for bad input, as `sample_triangle_mesh()`, and for samples that
/// `is_poisson_disk_set()` refuses (a coordinate of magnitude above 2^44 d, for one)
/// \returns `Maximality_check<Point_3>`, with the point type of the mesh's kernel
template <class TriangleMesh, class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto is_maximal(const TriangleMesh& tm, const PointRange& samples, double minimum_distance,
           const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_given_once<NamedParameters>();
  static_assert(internal::has_no_sampling_parameter<NamedParameters>(),
                "is_maximal() takes the minimum distance as its third argument, and of the named parameters "
                "only vertex_point_map and geom_traits: it would ignore radius, random_seed and the other "
                "sampling parameters");
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_of;
  return internal::check_maximal<typename GT::Point_3>(internal::triangles_of_mesh(tm, np, face_of), samples,
                                                       minimum_distance);
}

/// \ingroup PkgPoissonDiskSampling3Ref
/// Certifies that `samples` is maximal on a polygon soup of triangles, as `is_maximal()` for meshes.
/// @tparam PointRange a range of `Point_3`
/// @tparam PolygonRange a range of ranges of three integer indices into `points` (floating-point ones
///         do not compile)
/// @tparam SampleRange a range of `Point_3` of any CGAL kernel
///
/// @param points the points of the soup
/// @param polygons the triangles, as indices into `points`
/// @param samples the samples to certify
/// @param minimum_distance the distance d = 2r they were sampled for
///
/// \returns `Maximality_check<Point_3>`, with the point type of `points`
/// \throws Invalid_input as `is_maximal()` for meshes
template <class PointRange, class PolygonRange, class SampleRange>
Maximality_check<typename std::iterator_traits<typename PointRange::const_iterator>::value_type>
is_maximal_on_polygon_soup(const PointRange& points, const PolygonRange& polygons, const SampleRange& samples,
                           double minimum_distance)
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Point;
  return internal::check_maximal<Point>(internal::triangles_of_soup(points, polygons), samples, minimum_distance);
}

/// \ingroup PkgPoissonDiskSampling3Ref
/// Certifies that `samples` is maximal on a sphere: spherical rectangles are split until one sample's
/// ball holds each of them entirely, with the exact closed-form test of `Sphere_fragment_traits_3`
/// (right near the poles) and a margin larger than its rounding error, with the bounds and answers
/// of `is_maximal()` for meshes. The sphere is the one `sample_sphere()` samples: its centre's
/// coordinates and its radius (the square root of its squared radius) as the nearest doubles, so that
/// for an exact kernel the answer is about that sphere.
/// @tparam K a CGAL kernel
/// @tparam PointRange a range of `Point_3` of any CGAL kernel
///
/// @param sphere the sphere
/// @param samples the samples to certify
/// @param minimum_distance the distance d = 2r they were sampled for
///
/// \returns `Maximality_check<K::Point_3>`
/// \throws Invalid_input for a sphere or distance that `sample_sphere()` refuses, and for samples that
/// `is_poisson_disk_set()` refuses
template <class K, class PointRange>
Maximality_check<typename K::Point_3> is_maximal(const CGAL::Sphere_3<K>& sphere, const PointRange& samples,
                                                 double minimum_distance)
{
  return internal::check_maximal<typename K::Point_3>(internal::sphere_traits(sphere), samples, minimum_distance);
}

/// \ingroup PkgPoissonDiskSampling3Ref
/// Certifies that `samples` is maximal on the surface of any model of `SurfaceFragmentTraits_3`, as
/// `is_maximal()` does for meshes: the model's initial fragments (for the distance, where the model
/// defines `initial_fragments(out, d)`) are split with its `split()` until its `is_covered()` proves
/// one sample's ball holds each piece, down to depth 48 (`level()` where the model defines it), with
/// the same bounds on work and memory. The model's `reference_point()` finds the samples near a piece
/// and stands for the gaps proven. The certificate uses none of the sampler's union tests and
/// `refine()`, so it checks them; but it relies on the model's `split()` tiling each fragment and its
/// `is_covered()` being conservative: a `true` answer is a proof on the surface that they describe.
/// @tparam SurfaceFragmentTraits a model of `SurfaceFragmentTraits_3`
/// @tparam PointRange a range of `Point_3` of any CGAL kernel, or of `std::array<double, 3>` (the
/// model's points)
///
/// @param traits the surface
/// @param samples the samples to certify, for instance the points of the samples of `sample_surface()`
/// @param minimum_distance the distance d = 2r they were sampled for
///
/// \returns `Maximality_check<Point_3>`, with the value type of `PointRange` (`uncovered_point`
/// converts to `bool` and is dereferenced as for any point type)
/// \throws Invalid_input for a distance that `sample_surface()` refuses for the model, a surface with
/// no area, and samples that `is_poisson_disk_set()` refuses
template <class SurfaceFragmentTraits, class PointRange>
Maximality_check<typename std::iterator_traits<typename PointRange::const_iterator>::value_type>
is_maximal_on_surface(const SurfaceFragmentTraits& traits, const PointRange& samples, double minimum_distance)
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Point;
  return internal::check_maximal<Point>(traits, samples, minimum_distance);
}

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_IS_MAXIMAL_H
