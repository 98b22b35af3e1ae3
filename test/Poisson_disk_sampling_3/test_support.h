// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the test programs share: kernel, mesh loading from CGAL's data set, and the checks every
// sampled set must pass: the package's own exact validations, and checks written here without the
// package's code (a plain grid, CGAL's exact comparison of squared distances, uniform probe points).

#ifndef CGAL_POISSON_DISK_SAMPLING_3_TEST_SUPPORT_H
#define CGAL_POISSON_DISK_SAMPLING_3_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/point_generators_3.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
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

/// whether |p - q| < d exactly, on the stored doubles: EPICK's exact comparison of the squared
/// distance with the doubles on either side of d * d, and rationals when it falls between them
inline bool is_closer_than(const Point& p, const Point& q, double d)
{
  const double square = d * d;
  if(CGAL::compare_squared_distance(p, q, std::nextafter(square, 0.)) == CGAL::SMALLER) return true;
  if(CGAL::compare_squared_distance(p, q, std::nextafter(square, std::numeric_limits<double>::infinity())) !=
     CGAL::SMALLER)
    return false;
  typedef CGAL::Exact_rational Q;
  const Q dx = Q(p.x()) - Q(q.x()), dy = Q(p.y()) - Q(q.y()), dz = Q(p.z()) - Q(q.z());
  return dx * dx + dy * dy + dz * dz < Q(d) * Q(d);
}

/// The samples in cubes of side `cell`, for the checks below: a map, not the package's grids.
class Test_grid
{
public:
  Test_grid(const std::vector<Point>& points, double cell) : cell_(cell)
  {
    for(std::size_t i = 0; i < points.size(); ++i) cells_[key(points[i])].push_back(i);
  }

  /// calls f(i) for every sample i in the 27 cubes around q's (all the samples within `cell` of q)
  template <class F>
  void for_each_near(const Point& q, F f) const
  {
    const std::array<long long, 3> k = key(q);
    for(long long x = -1; x <= 1; ++x)
      for(long long y = -1; y <= 1; ++y)
        for(long long z = -1; z <= 1; ++z) {
          const auto it = cells_.find({k[0] + x, k[1] + y, k[2] + z});
          if(it != cells_.end())
            for(std::size_t i : it->second) f(i);
        }
  }

private:
  std::array<long long, 3> key(const Point& p) const
  {
    std::array<long long, 3> k;
    for(int i = 0; i < 3; ++i) {
      const double c = std::floor(p[i] / cell_);
      if(!(std::abs(c) < 0x1.0p60)) ADD_FAILURE() << "coordinate " << p[i] << " too far for the test grid";
      k[i] = std::abs(c) < 0x1.0p60 ? (long long)c : 0;
    }
    return k;
  }

  double cell_;
  std::map<std::array<long long, 3>, std::vector<std::size_t>> cells_;
};

/// no two points closer than d, checked without the package's code; returns the number of pairs
/// found closer
inline std::size_t expect_no_pair_closer_than(const std::vector<Point>& points, double d)
{
  const Test_grid grid(points, d);
  std::size_t closer = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    grid.for_each_near(points[i], [&](std::size_t j) {
      if(j > i && is_closer_than(points[i], points[j], d)) {
        if(closer++ == 0) ADD_FAILURE() << "points " << i << " and " << j << " are closer than " << d;
      }
    });
  return closer;
}

/// uniform random points on the surface, from CGAL's generators
inline std::vector<Point> probe_points(const Mesh& m, std::size_t n, unsigned seed)
{
  CGAL::Random rng(seed);
  CGAL::Random_points_in_triangle_mesh_3<Mesh> generate(m, rng);
  std::vector<Point> probes;
  std::copy_n(generate, n, std::back_inserter(probes));
  return probes;
}
inline std::vector<Point> probe_points(const K::Sphere_3& s, std::size_t n, unsigned seed)
{
  CGAL::Random rng(seed);
  CGAL::Random_points_on_sphere_3<Point> generate(std::sqrt(s.squared_radius()), rng);
  std::vector<Point> probes;
  for(std::size_t i = 0; i < n; ++i, ++generate) probes.push_back(*generate + (s.center() - CGAL::ORIGIN));
  return probes;
}

/// A necessary condition of maximality, checked without the package's code: `probes` uniform random
/// points of the surface are each within d of a sample, up to the rounding of their positions. It
/// catches a part of the surface left without samples, not the tiniest gaps (the certificate of
/// `is_maximal()` does). Returns the number of probes farther than that.
template <class Surface>
std::size_t expect_probes_covered(const Surface& surface, const std::vector<Point>& points, double d,
                                  std::size_t probes, unsigned seed = 7)
{
  // a probe is off the surface by a few units in the last place of its coordinates
  const std::vector<Point> probe = probe_points(surface, probes, seed);
  auto slack = [&](const Point& q) {
    return 1e-9 * d + 1e-14 * (std::abs(q.x()) + std::abs(q.y()) + std::abs(q.z()));
  };
  double largest_slack = 0;
  for(const Point& q : probe) largest_slack = (std::max)(largest_slack, slack(q));
  // cells at least as wide as the farthest distance tested, with room for the rounding of the sum
  const Test_grid grid(points, (d + largest_slack) * (1 + 1e-12));
  std::size_t far = 0;
  for(const Point& q : probe) {
    const double reach = d + slack(q);
    bool covered = false;
    grid.for_each_near(q, [&](std::size_t i) { covered = covered || is_closer_than(q, points[i], reach); });
    if(!covered && far++ == 0) ADD_FAILURE() << "probe " << q << " is farther than " << d << " from every sample";
  }
  return far;
}

/// the two properties every output must have: decided by the package's exact validations, and
/// checked without its code (every pair, and 20 probes a sample, at most 200,000)
template <class Surface>
void expect_maximal_poisson_disk_set(const Surface& surface, const std::vector<Point>& points, double d)
{
  const PDS::Poisson_disk_check pds = PDS::is_poisson_disk_set(points, d);
  EXPECT_TRUE(pds) << "points " << pds.first << " and " << pds.second << " are closer than " << d;
  const auto max = PDS::is_maximal(surface, points, d);
  EXPECT_TRUE(max) << "not maximal: uncovered area " << max.uncovered_area;
  expect_no_pair_closer_than(points, d);
  expect_probes_covered(surface, points, d, (std::min)(std::size_t(200000), 20 * points.size()));
}

#endif // CGAL_POISSON_DISK_SAMPLING_3_TEST_SUPPORT_H
