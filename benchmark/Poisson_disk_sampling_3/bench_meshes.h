// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The meshes the benchmarks sample: files of CGAL's data set, and the large mesh made from one.

#ifndef POISSON_DISK_SAMPLING_3_BENCH_MESHES_H
#define POISSON_DISK_SAMPLING_3_BENCH_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

/// The minimum distance that gives about `n` points on a surface of area `area`: a maximal set covers
/// about 0.6965 area / d^2 points (the jamming density of maximal Poisson-disk sets in the plane).
inline double distance_for(double area, double n) { return std::sqrt(0.6965 * area / n); }

/// A tube along z, its axis at (x, 0): of radius `radius` and height `height`, `segments` cells around
/// and `rings` along, two triangles a cell.
inline void add_tube(Mesh& m, double x, double radius, double height, int segments, int rings)
{
  std::vector<Mesh::Vertex_index> v;
  for(int r = 0; r <= rings; ++r)
    for(int i = 0; i < segments; ++i) {
      const double a = 6.283185307179586 * i / segments;
      v.push_back(m.add_vertex(Mesh::Point(x + radius * std::cos(a), radius * std::sin(a), height * r / rings)));
    }
  for(int r = 0; r < rings; ++r)
    for(int i = 0; i < segments; ++i) {
      const auto a = v[r * segments + i], b = v[r * segments + (i + 1) % segments];
      const auto c = v[(r + 1) * segments + i], d = v[(r + 1) * segments + (i + 1) % segments];
      m.add_face(a, b, d);
      m.add_face(a, d, c);
    }
}

/// A cylinder of radius 1 and height 30, 64 cells around and `rings` along, two triangles a cell.
inline void make_cylinder(Mesh& m, int rings) { add_tube(m, 0, 1, 30, 64, rings); }

/// 2,000 strips 1 long and `width` wide, 0.002 apart in the plane z = 0, two triangles each
inline void make_strips(Mesh& m, double width)
{
  for(int k = 0; k < 2000; ++k) {
    const double y = 0.002 * k;
    const auto a = m.add_vertex(Mesh::Point(0, y, 0)), b = m.add_vertex(Mesh::Point(1, y, 0));
    const auto c = m.add_vertex(Mesh::Point(1, y + width, 0)), d = m.add_vertex(Mesh::Point(0, y + width, 0));
    m.add_face(a, b, c);
    m.add_face(a, c, d);
  }
}

/// 20 unit squares 0.01 apart, one above the other, two triangles each: at distances of a few times
/// their spacing, a ball holds parts of several of them, and a maximal set's count goes about as d^-3
inline void make_sheets(Mesh& m)
{
  for(int k = 0; k < 20; ++k) {
    const double z = 0.01 * k;
    const auto a = m.add_vertex(Mesh::Point(0, 0, z)), b = m.add_vertex(Mesh::Point(1, 0, z));
    const auto c = m.add_vertex(Mesh::Point(1, 1, z)), d = m.add_vertex(Mesh::Point(0, 1, z));
    m.add_face(a, b, c);
    m.add_face(a, c, d);
  }
}

/// 100 tubes of radius 0.01 and length 1, 0.05 apart side by side, each of 100 rings of 24 cells, two
/// triangles a cell: at distances about their diameter a sample goes from holding part of a ring to
/// holding all of it, and a maximal set's count falls faster than d^-3
inline void make_tubes(Mesh& m)
{
  for(int t = 0; t < 100; ++t) add_tube(m, 0.05 * t, 0.01, 1, 24, 100);
}

/// A file of CGAL's data set (`lion.off`, ...); "armadillo_loop3": armadillo.off Loop-subdivided
/// three times, 52,000 faces x 4^3 = 3.3 million faces; "cylinder_128": a cylinder 30 high, of
/// radius 1, made of 128 triangles as high as it is and 0.1 wide; "cylinder_rings": the same surface
/// cut into 306 rings, its triangles about as high as they are wide; "strips_1e-7" and "strips_1e-5":
/// 2,000 strips that wide (`make_strips`); "sheets" and "tubes": `make_sheets()` and `make_tubes()`.
/// Read or made once per process.
inline const Mesh& mesh(const std::string& name)
{
  static std::map<std::string, std::unique_ptr<Mesh>> cache;
  auto& m = cache[name];
  if(!m) {
    m.reset(new Mesh);
    if(name == "cylinder_128") {
      make_cylinder(*m, 1);
    } else if(name == "cylinder_rings") {
      make_cylinder(*m, 306);
    } else if(name == "strips_1e-7" || name == "strips_1e-5") {
      make_strips(*m, name == "strips_1e-7" ? 1e-7 : 1e-5);
    } else if(name == "sheets") {
      make_sheets(*m);
    } else if(name == "tubes") {
      make_tubes(*m);
    } else if(name == "armadillo_loop3") {
      *m = mesh("armadillo.off");
      CGAL::Subdivision_method_3::Loop_subdivision(*m, CGAL::parameters::number_of_iterations(3));
    } else if(!CGAL::IO::read_polygon_mesh(std::string(CGAL_PDS_DATA_DIR) + "/" + name, *m)) {
      throw std::runtime_error("cannot read " + name);
    }
  }
  return *m;
}

} // namespace bench

#endif // POISSON_DISK_SAMPLING_3_BENCH_MESHES_H
