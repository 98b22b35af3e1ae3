// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_TRIANGLE_MESH_H
#define CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_TRIANGLE_MESH_H

#include <CGAL/Poisson_disk_sampling_3/Triangle_fragment_traits_3.h>
#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/nearest_double.h>
#include <CGAL/Poisson_disk_sampling_3/parameters.h>
#include <CGAL/Poisson_disk_sampling_3/sample_surface.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <iterator>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \ingroup PkgPoissonDiskSampling3Ref
/// A sample on a triangle and where it lies: what hair, fur and mosaic placement need.
/// @tparam GeomTraits a CGAL kernel
/// @tparam Face the face handle: a `face_descriptor` for meshes, the polygon's index for soups
template <class GeomTraits, class Face>
struct Triangle_sample
{
  typename GeomTraits::Point_3 point;  ///< the sample
  Face face;                          ///< the face it lies on
  /// barycentric coordinates with respect to the face's vertices, in the order of
  /// `CGAL::Polygon_mesh_processing::Face_location` for meshes (`source(halfedge(f))`,
  /// `target(halfedge(f))`, `target(next(halfedge(f)))`), in the polygon's order for soups
  std::array<typename GeomTraits::FT, 3> barycentric_coordinates;
  typename GeomTraits::Vector_3 normal; ///< the face's unit normal (right-hand rule on that order)
};

namespace internal {

template <class T, class = void>
struct Is_printable : std::false_type
{};
template <class T>
struct Is_printable<T, std::void_t<decltype(std::declval<std::ostream&>() << std::declval<const T&>())>>
    : std::true_type
{};

/// how a message names a face of a mesh: its place in the order of faces(tm), and its descriptor
/// where that prints (a `Surface_mesh` index, "f2", differs from the place where removed faces were
/// not collected)
template <class Face>
std::string face_name(const Face& f, std::size_t place)
{
  std::string name = "face " + std::to_string(place) + " in the order of faces(tm)";
  if constexpr(Is_printable<Face>::value) {
    std::ostringstream text;
    text << f;
    name += " (" + text.str() + ")";
  }
  return name;
}

/// the faces of a FaceListGraph as a triangle set; rejects faces that are not triangles
template <class TriangleMesh, class NamedParameters>
Triangle_fragment_traits_3
triangles_of_mesh(const TriangleMesh& tm, const NamedParameters& np,
                  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of)
{
  const auto vpm = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_const_property_map(CGAL::vertex_point, tm));
  Triangle_fragment_traits_3 traits;
  traits.reserve(std::size_t(num_faces(tm)));
  face_of.clear();
  face_of.reserve(std::size_t(num_faces(tm)));
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto n = next(h, tm);
    // three halfedges: the one after the next is the one before h (prev is the inverse of next), which
    // a Surface_mesh stores with h, one dependent load fewer than walking around the face
    if(next(n, tm) != prev(h, tm))
      throw Invalid_input(face_name(f, face_of.size()) + " is not a triangle; "
                          "triangulate it first, e.g. with CGAL::Polygon_mesh_processing::triangulate_faces()");
    const std::array<double, 3> q[3] = {nearest_doubles(get(vpm, source(h, tm))),
                                        nearest_doubles(get(vpm, target(h, tm))),
                                        nearest_doubles(get(vpm, target(n, tm)))};
    traits.add_triangle(q[0], q[1], q[2], [&] { return face_name(f, face_of.size()); });
    face_of.push_back(f);
  }
  if(face_of.empty()) throw Invalid_input("the mesh has no faces");
  return traits;
}

/// the triangles of a polygon soup; rejects polygons that are not triangles and bad indices
template <class PointRange, class PolygonRange>
Triangle_fragment_traits_3 triangles_of_soup(const PointRange& points, const PolygonRange& polygons)
{
  std::vector<std::array<double, 3>> p;
  for(const auto& q : points) p.push_back(nearest_doubles(q));
  Triangle_fragment_traits_3 traits;
  std::size_t i = 0;
  // an index as it was given: a negative one is not written as the size_t it converts to
  auto refuse_index = [&](const auto& v) {
    throw Invalid_input("polygon " + std::to_string(i) + " refers to point " + std::to_string(v) + " of " +
                        std::to_string(p.size()));
  };
  for(const auto& polygon : polygons) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for(const auto& v : polygon) {
      // (converted, a fraction would be dropped, and NaN or a value of 2^64 or more is undefined)
      static_assert(!std::is_floating_point<std::decay_t<decltype(v)>>::value,
                    "a polygon soup's polygons hold integer indices into its points, not floating-point ones");
      if constexpr(std::is_signed<std::decay_t<decltype(v)>>::value) {
        if(v < 0) refuse_index(v);
      }
      if(k < 3) t[k] = std::size_t(v);
      ++k;
    }
    if(k != 3)
      throw Invalid_input("polygon " + std::to_string(i) + " has " + std::to_string(k) +
                          " vertices; only triangles are sampled (make a mesh of the soup with "
                          "CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh() and triangulate it "
                          "with triangulate_faces(), or, from CGAL 6.0, use triangulate_polygons())");
    for(std::size_t v : t)
      if(v >= p.size()) refuse_index(v);
    traits.add_triangle(p[t[0]], p[t[1]], p[t[2]], [i] { return "polygon " + std::to_string(i); });
    ++i;
  }
  if(i == 0) throw Invalid_input("the polygon soup has no polygons");
  return traits;
}

// a soup's points are its positions: a vertex_point_map, which the mesh functions take, would be ignored
template <class NamedParameters>
void check_no_vertex_point_map()
{
  static_assert(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value,
                "the polygon soup functions take no vertex_point_map: the soup's points are its positions");
}

template <class GeomTraits, class Face, class FaceOf>
Triangle_sample<GeomTraits, Face> located_sample(const Triangle_fragment_traits_3& traits,
                                                 const Triangle_fragment_traits_3::Sample& s, const FaceOf& face_of)
{
  typedef typename GeomTraits::FT FT;
  const auto n = traits.triangle_normal(s.face);
  const auto w = traits.barycentric_coordinates(s);
  return Triangle_sample<GeomTraits, Face>{
      internal::output_point<typename GeomTraits::Point_3>(s.point), face_of(s.face),
      std::array<FT, 3>{{FT(w[0]), FT(w[1]), FT(w[2])}}, typename GeomTraits::Vector_3(n[0], n[1], n[2])};
}

} // namespace internal

/// \ingroup PkgPoissonDiskSampling3Ref
/// Generates a maximal Poisson-disk sample set on a triangle mesh (paper Section 4) and writes its points.
///
/// Borders, several components and non-manifold edges need no care; faces of zero area are skipped.
///
/// @tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// @tparam PointOutputIterator an output iterator accepting the mesh's `Point_3`
/// @tparam NamedParameters a sequence of named parameters
///
/// @param tm the mesh
/// @param out where the points are written
/// @param np exactly one of `radius`, `minimum_distance` and `number_of_points`, and options: the
///        ones of `sample_surface()` and the ones below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel of the output points}
///     \cgalParamType{a CGAL kernel}
///     \cgalParamDefault{the kernel of the vertex point map's value type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the output iterator past the last point
/// \throws Invalid_input for an empty mesh, a face that is not a triangle, a non-finite coordinate, a
///         bad size, or a mesh of zero area
/// \throws Point_limit_exceeded when the request exceeds `maximum_number_of_points`
/// \throws Target_not_reached when `number_of_points` cannot be met
template <class TriangleMesh, class PointOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
PointOutputIterator sample_triangle_mesh(const TriangleMesh& tm, PointOutputIterator out,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_of;
  Sampling_statistics local; // (if not given)
  // cleared before the mesh is read, which may throw
  Sampling_statistics& stats = internal::clear_statistics(np, local);
  const Triangle_fragment_traits_3 traits = internal::triangles_of_mesh(tm, np, face_of);
  internal::sample_request(traits, np, stats, [&](const Triangle_fragment_traits_3::Sample& s) {
    *out++ = internal::output_point<typename GT::Point_3>(s.point);
  });
  return out;
}

/// \ingroup PkgPoissonDiskSampling3Ref
/// Same as `sample_triangle_mesh()`, and writes for each sample its face, barycentric coordinates and
/// the face normal.
/// @tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// @tparam SampleOutputIterator an output iterator accepting
///         `Triangle_sample<GeomTraits, boost::graph_traits<TriangleMesh>::%face_descriptor>`
/// @tparam NamedParameters as for `sample_triangle_mesh()`
///
/// @param tm the mesh
/// @param out where the samples are written
/// @param np as for `sample_triangle_mesh()`
///
/// \returns the output iterator past the last sample
/// \throws Invalid_input, Point_limit_exceeded, Target_not_reached as `sample_triangle_mesh()`
template <class TriangleMesh, class SampleOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
SampleOutputIterator sample_triangle_mesh_with_locations(const TriangleMesh& tm, SampleOutputIterator out,
                                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<face_descriptor> face_of;
  Sampling_statistics local; // (if not given)
  // cleared before the mesh is read, which may throw
  Sampling_statistics& stats = internal::clear_statistics(np, local);
  const Triangle_fragment_traits_3 traits = internal::triangles_of_mesh(tm, np, face_of);
  internal::sample_request(traits, np, stats, [&](const Triangle_fragment_traits_3::Sample& s) {
    *out++ = internal::located_sample<GT, face_descriptor>(traits, s, [&](std::uint32_t i) { return face_of[i]; });
  });
  return out;
}

/// \ingroup PkgPoissonDiskSampling3Ref
/// Generates a maximal Poisson-disk sample set on a triangle soup, as CGAL's polygon-soup functions
/// take it: a range of points and a range of polygons, each a range of three point indices.
///
/// @tparam PointRange a random-access range of `Point_3`
/// @tparam PolygonRange a range of ranges of integer indices into `points` (floating-point ones do not
///         compile)
/// @tparam PointOutputIterator an output iterator accepting `Point_3`
/// @tparam NamedParameters as for `sample_triangle_mesh()`, without `vertex_point_map`
///
/// @param points the points of the soup
/// @param polygons the triangles, as indices into `points`
/// @param out where the points are written
/// @param np as for `sample_triangle_mesh()`, without `vertex_point_map`
///
/// \returns the output iterator past the last point
/// \throws Invalid_input for no polygons, a polygon that is not a triangle, an index out of range,
///         a non-finite coordinate, a bad size, or a soup of zero area
/// \throws Point_limit_exceeded, Target_not_reached as `sample_triangle_mesh()`
template <class PointRange, class PolygonRange, class PointOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
PointOutputIterator sample_polygon_soup(const PointRange& points, const PolygonRange& polygons,
                                        PointOutputIterator out,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Default_kernel;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                             Default_kernel>::type GT;
  Sampling_statistics local; // (if not given)
  // cleared before the soup is read, which may throw
  Sampling_statistics& stats = internal::clear_statistics(np, local);
  internal::check_no_vertex_point_map<NamedParameters>();
  const Triangle_fragment_traits_3 traits = internal::triangles_of_soup(points, polygons);
  internal::sample_request(traits, np, stats, [&](const Triangle_fragment_traits_3::Sample& s) {
    *out++ = internal::output_point<typename GT::Point_3>(s.point);
  });
  return out;
}

/// \ingroup PkgPoissonDiskSampling3Ref
/// Same as `sample_polygon_soup()`, and writes for each sample the polygon's index, barycentric
/// coordinates in the polygon's vertex order and its normal.
/// @tparam PointRange a random-access range of `Point_3`
/// @tparam PolygonRange a range of ranges of integer indices into `points` (floating-point ones do not
///         compile)
/// @tparam SampleOutputIterator an output iterator accepting `Triangle_sample<GeomTraits, std::size_t>`
/// @tparam NamedParameters as for `sample_polygon_soup()`
///
/// @param points the points of the soup
/// @param polygons the triangles, as indices into `points`
/// @param out where the samples are written
/// @param np as for `sample_polygon_soup()`
///
/// \returns the output iterator past the last sample
/// \throws Invalid_input, Point_limit_exceeded, Target_not_reached as `sample_polygon_soup()`
template <class PointRange, class PolygonRange, class SampleOutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
SampleOutputIterator sample_polygon_soup_with_locations(const PointRange& points, const PolygonRange& polygons,
                                                        SampleOutputIterator out,
                                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Default_kernel;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                             Default_kernel>::type GT;
  Sampling_statistics local; // (if not given)
  // cleared before the soup is read, which may throw
  Sampling_statistics& stats = internal::clear_statistics(np, local);
  internal::check_no_vertex_point_map<NamedParameters>();
  const Triangle_fragment_traits_3 traits = internal::triangles_of_soup(points, polygons);
  internal::sample_request(traits, np, stats, [&](const Triangle_fragment_traits_3::Sample& s) {
    *out++ = internal::located_sample<GT, std::size_t>(traits, s, [](std::uint32_t i) { return std::size_t(i); });
  });
  return out;
}

} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_SAMPLE_TRIANGLE_MESH_H
