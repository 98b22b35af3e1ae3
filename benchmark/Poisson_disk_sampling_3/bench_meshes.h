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

namespace bench {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

/// The minimum distance that gives about `n` points on a surface of area `area`: a maximal set covers
/// about 0.6965 area / d^2 points (the jamming density of maximal Poisson-disk sets in the plane).
inline double distance_for(double area, double n) { return std::sqrt(0.6965 * area / n); }

/// A file of CGAL's data set (`lion.off`, ...), or "armadillo_loop3": armadillo.off Loop-subdivided
/// three times, 52,000 faces x 4^3 = 3.3 million faces. Read or made once per process.
inline const Mesh& mesh(const std::string& name)
{
  static std::map<std::string, std::unique_ptr<Mesh>> cache;
  auto& m = cache[name];
  if(!m) {
    m.reset(new Mesh);
    if(name == "armadillo_loop3") {
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
