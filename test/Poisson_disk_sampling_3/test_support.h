// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the test programs share: kernel, mesh loading from CGAL's data set, and the two checks every
// sampled set must pass.

#ifndef CGAL_POISSON_DISK_SAMPLING_3_TEST_SUPPORT_H
#define CGAL_POISSON_DISK_SAMPLING_3_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace PDS = CGAL::Poisson_disk_sampling_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

#ifndef CGAL_PDS_DATA_DIR
#error "CGAL_PDS_DATA_DIR must name the folder of CGAL's meshes (data/meshes of libcgal-demo's data.tar.gz)"
#endif

inline std::string data_file(const std::string& name) { return std::string(CGAL_PDS_DATA_DIR) + "/" + name; }

template <class PolygonMesh = Mesh>
PolygonMesh load_mesh(const std::string& name)
{
  PolygonMesh m;
  if(!CGAL::IO::read_polygon_mesh(data_file(name), m) || faces(m).empty())
    ADD_FAILURE() << "cannot read " << data_file(name);
  return m;
}

/// a minimum distance giving about n points on a surface of this area
inline double distance_for(double area, double n) { return std::sqrt(0.6965 * area / n); }

/// point by point, `scaled` is `unit` with every coordinate multiplied by 2^e, exactly
inline void expect_scaled_copy(const std::vector<Point>& unit, const std::vector<Point>& scaled, int e)
{
  ASSERT_EQ(scaled.size(), unit.size()) << "scaled by 2^" << e;
  for(std::size_t i = 0; i < unit.size(); ++i)
    ASSERT_EQ(scaled[i], Point(std::ldexp(unit[i].x(), e), std::ldexp(unit[i].y(), e), std::ldexp(unit[i].z(), e)))
        << "sample " << i << ", scaled by 2^" << e;
}

/// the two properties every output must have, decided by the package's exact validation
template <class Surface>
void expect_maximal_poisson_disk_set(const Surface& surface, const std::vector<Point>& points, double d)
{
  const PDS::Poisson_disk_check pds = PDS::is_poisson_disk_set(points, d);
  EXPECT_TRUE(pds) << "points " << pds.first << " and " << pds.second << " are closer than " << d;
  const auto max = PDS::is_maximal(surface, points, d);
  EXPECT_TRUE(max) << "not maximal: uncovered area " << max.uncovered_area;
}

#endif // CGAL_POISSON_DISK_SAMPLING_3_TEST_SUPPORT_H
