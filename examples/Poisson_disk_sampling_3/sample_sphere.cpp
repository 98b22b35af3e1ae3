// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sample_sphere [--center X Y Z] [--sphere-radius R] [--radius r | --minimum-distance D | --count N]
//               [--seed S] [-o OUT.ply]
//
// Samples a sphere (by default the unit sphere, about 10,000 points) with a maximal Poisson-disk set,
// checks it, writes a binary PLY (x y z, nx ny nz) and prints one `key: value` a line.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_disk_sampling_3.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace PDS = CGAL::Poisson_disk_sampling_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

int usage(const char* message)
{
  std::cerr << "error: " << message << "\nusage: sample_sphere [--center X Y Z] [--sphere-radius R] "
               "[--radius r | --minimum-distance D | --count N] [--seed S] [-o OUT.ply]\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  double cx = 0, cy = 0, cz = 0, sphere_radius = 1, radius = 0, distance = 0;
  long long count = 0;
  unsigned seed = 0;
  std::string out_file = "sphere_samples.ply";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--center" && i + 3 < argc) {
      cx = std::atof(argv[++i]);
      cy = std::atof(argv[++i]);
      cz = std::atof(argv[++i]);
    } else if(a == "--sphere-radius" && has_value) sphere_radius = std::atof(argv[++i]);
    else if(a == "--radius" && has_value) radius = std::atof(argv[++i]);
    else if(a == "--minimum-distance" && has_value) distance = std::atof(argv[++i]);
    else if(a == "--count" && has_value) count = std::atoll(argv[++i]);
    else if(a == "--seed" && has_value) seed = unsigned(std::strtoul(argv[++i], nullptr, 10));
    else if(a == "-o" && has_value) out_file = argv[++i];
    else return usage(("unknown argument or missing value: " + a).c_str());
  }
  if((radius != 0) + (distance != 0) + (count != 0) > 1) return usage("give one of --radius, --minimum-distance, --count");
  if(radius == 0 && distance == 0 && count == 0)
    distance = std::sqrt(0.6965 * 4 * 3.14159265358979323846 * sphere_radius * sphere_radius / 10000);
  if(radius != 0) distance = 2 * radius;

  try {
    const K::Sphere_3 sphere(K::Point_3(cx, cy, cz), sphere_radius * sphere_radius);
    std::vector<K::Point_3> points;
    PDS::Sampling_statistics stats;
    const auto start = std::chrono::steady_clock::now();
    if(count != 0)
      PDS::sample_sphere(sphere, std::back_inserter(points),
                         PDS::parameters::number_of_points(count).random_seed(seed).statistics(std::ref(stats)));
    else
      PDS::sample_sphere(sphere, std::back_inserter(points),
                         PDS::parameters::minimum_distance(distance).random_seed(seed).statistics(std::ref(stats)));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool pds = bool(PDS::is_poisson_disk_set(points, stats.minimum_distance));
    const bool maximal = bool(PDS::is_maximal(sphere, points, stats.minimum_distance));

    std::ofstream out(out_file, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << points.size()
        << "\nproperty double x\nproperty double y\nproperty double z\n"
           "property double nx\nproperty double ny\nproperty double nz\nend_header\n";
    for(const K::Point_3& p : points) {
      const double v[6] = {p.x(), p.y(), p.z(), (p.x() - cx) / sphere_radius, (p.y() - cy) / sphere_radius,
                           (p.z() - cz) / sphere_radius};
      out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
    if(!out) throw std::runtime_error("cannot write " + out_file);

    std::cout << "points: " << points.size() << "\n"
              << "minimum_distance: " << stats.minimum_distance << "\n"
              << "seconds: " << seconds << "\n"
              << "points_per_second: " << double(points.size()) / seconds << "\n"
              << "is_poisson_disk_set: " << (pds ? "true" : "false") << "\n"
              << "is_maximal: " << (maximal ? "true" : "false") << "\n"
              << "output: " << out_file << "\n";
    return pds && maximal ? 0 : 1;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
