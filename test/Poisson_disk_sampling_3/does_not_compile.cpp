// SPDX-License-Identifier: GPL-3.0-or-later
//
// Calls that must not compile. Each case is this file compiled with one PDS_CASE_* macro defined
// (an object library of its own, outside `all`); its CTest test builds it and passes where the build
// fails with the package's message for that mistake (CMakeLists.txt), not on any other error. Without
// a macro the file compiles, so that a case fails for its own call and nothing else.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Poisson_disk_sampling_3.h>

#include <array>
#include <iterator>
#include <vector>

namespace PDS = CGAL::Poisson_disk_sampling_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

void calls()
{
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  const std::vector<std::array<std::size_t, 3>> triangles = {{0, 1, 2}};
  CGAL::Surface_mesh<Point> mesh;
  std::vector<Point> out;
  auto to = std::back_inserter(out);
  (void)points; (void)triangles; (void)mesh; (void)to;
#if defined(PDS_CASE_FLOAT_POLYGON_INDEX)
  // an index 1.7 would be read as 1, and NaN is undefined as a size_t
  const std::vector<std::array<double, 3>> float_triangles = {{0, 1.7, 2}};
  PDS::sample_polygon_soup(points, float_triangles, to, PDS::parameters::minimum_distance(0.1));
#elif defined(PDS_CASE_FLOAT_SEED)
  PDS::sample_triangle_mesh(mesh, to, PDS::parameters::minimum_distance(0.1).random_seed(1.5));
#elif defined(PDS_CASE_FLOAT_POINTS)
  // the samples are points of the mesh's kernel, here on float
  typedef CGAL::Simple_cartesian<float>::Point_3 Float_point;
  CGAL::Surface_mesh<Float_point> float_mesh;
  std::vector<Float_point> float_out;
  PDS::sample_triangle_mesh(float_mesh, std::back_inserter(float_out), PDS::parameters::minimum_distance(0.1));
#elif defined(PDS_CASE_INTEGER_POINTS)
  typedef CGAL::Simple_cartesian<int>::Point_3 Integer_point;
  CGAL::Surface_mesh<Integer_point> integer_mesh;
  std::vector<Integer_point> integer_out;
  PDS::sample_triangle_mesh(integer_mesh, std::back_inserter(integer_out), PDS::parameters::minimum_distance(0.1));
#elif defined(PDS_CASE_CONCURRENCY_TAG)
  PDS::sample_triangle_mesh(mesh, to, PDS::parameters::minimum_distance(0.1).concurrency(1));
#elif defined(PDS_CASE_PARALLEL_TAG_WITHOUT_TBB)
  PDS::sample_triangle_mesh(mesh, to, PDS::parameters::minimum_distance(0.1).concurrency(CGAL::Parallel_tag()));
#elif defined(PDS_CASE_SOUP_VERTEX_POINT_MAP)
  PDS::sample_polygon_soup(points, triangles, to,
                           PDS::parameters::minimum_distance(0.1).vertex_point_map(get(CGAL::vertex_point, mesh)));
#elif defined(PDS_CASE_SAMPLING_PARAMETER_IN_IS_MAXIMAL)
  PDS::is_maximal(mesh, out, 0.1, PDS::parameters::random_seed(3));
#endif
}
