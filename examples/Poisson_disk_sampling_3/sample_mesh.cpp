// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sample_mesh [MESH] [--radius R | --minimum-distance D | --count N] [--seed S]
//             [--maximum-number-of-points M] [-o OUT.ply]
//
// Samples a triangle mesh (any file CGAL reads: OFF, OBJ, PLY, STL; by default lion.off from CGAL's
// data set) with a maximal Poisson-disk set, checks the result with the package's exact validation,
// writes a binary PLY (x y z, nx ny nz, face index) and prints one `key: value` a line.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "command_line.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace PDS = CGAL::Poisson_disk_sampling_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef PDS::Triangle_sample<K, Mesh::Face_index> Sample;

namespace {

const char* const usage_line = "usage: sample_mesh [MESH] [--radius R | --minimum-distance D | --count N] [--seed S]\n"
                               "                   [--maximum-number-of-points M] [-o OUT.ply]\n";

int usage(const char* message)
{
  std::cerr << "error: " << message << "\n" << usage_line;
  return 2;
}

std::string default_mesh()
{
  for(const char* dir : {
#ifdef CGAL_PDS_DATA_DIR
          CGAL_PDS_DATA_DIR,
#endif
#ifdef CGAL_PDS_INSTALLED_DATA_DIR
          CGAL_PDS_INSTALLED_DATA_DIR,
#endif
          "."}) {
    const std::string path = std::string(dir) + "/lion.off";
    if(std::ifstream(path)) return path;
  }
  return "lion.off";
}

void write_ply(const std::string& path, const std::vector<Sample>& samples)
{
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << samples.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n"
         "property double nx\nproperty double ny\nproperty double nz\nproperty uint face_index\nend_header\n";
  for(const Sample& s : samples) {
    const double v[6] = {s.point.x(), s.point.y(), s.point.z(), s.normal.x(), s.normal.y(), s.normal.z()};
    const std::uint32_t f = std::uint32_t(s.face);
    out.write(reinterpret_cast<const char*>(v), sizeof v); // x86 and ARM are little-endian
    out.write(reinterpret_cast<const char*>(&f), sizeof f);
  }
  if(!out) throw std::runtime_error("cannot write " + path);
}

} // namespace

int main(int argc, char** argv)
{
  std::string mesh_file, out_file = "samples.ply";
  examples::Size_options size;
  examples::Seen_options seen;
  try {
    for(int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if(examples::is_help(a)) {
        std::cout << usage_line;
        return 0;
      }
      if(size.read(argc, argv, i, seen)) continue;
      if(a == "-o" && i + 1 < argc) {
        seen.once(a);
        out_file = argv[++i];
      } else if(!a.empty() && a[0] == '-') throw examples::Usage_error("unknown option or missing value: " + a);
      else if(mesh_file.empty()) mesh_file = a;
      else throw examples::Usage_error("more than one mesh");
    }
    size.check();
  } catch(const examples::Usage_error& e) {
    return usage(e.what());
  }
  if(mesh_file.empty()) mesh_file = default_mesh();

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(mesh_file, mesh)) {
    std::cerr << "error: cannot read a polygon mesh from " << mesh_file << "\n";
    return 1;
  }

  try {
    std::vector<Sample> samples;
    PDS::Sampling_statistics stats;
    // with no size: about 10,000 points
    const double default_distance = std::sqrt(0.6965 * CGAL::Polygon_mesh_processing::area(mesh) / 10000);
    const auto start = std::chrono::steady_clock::now();
    size.sample_with(default_distance, 10000, stats, [&](const auto& np) {
      PDS::sample_triangle_mesh_with_locations(mesh, std::back_inserter(samples), np);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::vector<K::Point_3> points;
    for(const Sample& s : samples) points.push_back(s.point);
    const bool pds = bool(PDS::is_poisson_disk_set(points, stats.minimum_distance));
    const bool maximal = bool(PDS::is_maximal(mesh, points, stats.minimum_distance));
    write_ply(out_file, samples);

    std::cout << "mesh: " << mesh_file << "\n"
              << "faces: " << num_faces(mesh) << "\n"
              << "points: " << samples.size() << "\n"
              << "minimum_distance: " << stats.minimum_distance << "\n"
              << "seconds: " << seconds << "\n"
              << "points_per_second: " << double(samples.size()) / seconds << "\n"
              << "is_poisson_disk_set: " << (pds ? "true" : "false") << "\n"
              << "is_maximal: " << (maximal ? "true" : "false") << "\n"
              << "output: " << out_file << "\n";
    return pds && maximal ? 0 : 1;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
