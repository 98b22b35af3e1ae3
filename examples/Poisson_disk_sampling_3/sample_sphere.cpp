// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sample_sphere [--center X Y Z] [--sphere-radius R] [--radius r | --minimum-distance D | --count N]
//               [--seed S] [--maximum-number-of-points M] [-o OUT.ply]
//
// Samples a sphere (by default the unit sphere, about 10,000 points) with a maximal Poisson-disk set,
// checks it, writes a binary PLY (x y z, nx ny nz) and prints one `key: value` a line.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_disk_sampling_3.h>

#include "command_line.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace PDS = CGAL::Poisson_disk_sampling_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

const char* const usage_line = "usage: sample_sphere [--center X Y Z] [--sphere-radius R] "
                               "[--radius r | --minimum-distance D | --count N]\n"
                               "                     [--seed S] [--maximum-number-of-points M] [-o OUT.ply]\n";

const char* const defaults =
    "The sphere: by default centred at 0 0 0, of radius 1. With no size, about 10,000 points; --seed 0;\n"
    "--maximum-number-of-points 100000000. The samples are written to OUT.ply (by default\n"
    "sphere_samples.ply, replaced if it exists).\n";

int usage(const char* message)
{
  std::cerr << "error: " << message << "\n" << usage_line;
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  double cx = 0, cy = 0, cz = 0, sphere_radius = 1;
  examples::Size_options size;
  std::string out_file = "sphere_samples.ply";
  examples::Seen_options seen;
  try {
    for(int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if(examples::is_help(a)) return examples::help(std::string(usage_line) + defaults);
      if(size.read(argc, argv, i, seen)) continue;
      if(a == "--center") {
        seen.once(a);
        cx = examples::read_number(argc, argv, i, a); // each call reads the next argument
        cy = examples::read_number(argc, argv, i, a);
        cz = examples::read_number(argc, argv, i, a);
      } else if(a == "--sphere-radius") {
        seen.once(a);
        sphere_radius = examples::read_number(argc, argv, i);
      } else if(a == "-o") {
        seen.once(a);
        out_file = examples::read_file_name(argc, argv, i);
      } else throw examples::Usage_error("unknown argument or missing value: " + a);
    }
    size.check();
    examples::check_output_path(out_file);
  } catch(const examples::Usage_error& e) {
    return usage(e.what());
  }
  if(!(sphere_radius > 0) || !std::isfinite(sphere_radius)) return usage("--sphere-radius takes a positive number");

  try {
    // Sphere_3 takes the squared radius: the check above keeps a negative radius from passing as its square
    const K::Sphere_3 sphere(K::Point_3(cx, cy, cz), sphere_radius * sphere_radius);
    std::vector<K::Point_3> points;
    PDS::Sampling_statistics stats;
    // with no size: about 10,000 points
    const double default_distance =
        std::sqrt(0.6965 * 4 * 3.14159265358979323846 * sphere_radius * sphere_radius / 10000);
    const auto start = std::chrono::steady_clock::now();
    size.sample_with(default_distance, 10000, stats, [&](const auto& np) {
      PDS::sample_sphere(sphere, std::back_inserter(points), np);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool pds = bool(PDS::is_poisson_disk_set(points, stats.minimum_distance));
    const auto maximal = PDS::is_maximal(sphere, points, stats.minimum_distance);

    std::ofstream out(out_file, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << points.size()
        << "\nproperty double x\nproperty double y\nproperty double z\n"
           "property double nx\nproperty double ny\nproperty double nz\nend_header\n";
    for(const K::Point_3& p : points) {
      const double v[6] = {p.x(), p.y(), p.z(), (p.x() - cx) / sphere_radius, (p.y() - cy) / sphere_radius,
                           (p.z() - cz) / sphere_radius};
      out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
    examples::close_output(out, out_file);

    std::ostringstream text;
    text << "points: " << points.size() << "\n"
         << "minimum_distance: " << examples::exact_text(stats.minimum_distance) << "\n"
         << "random_seed: " << stats.random_seed << "\n"
         << "runs: " << stats.number_of_runs << "\n"
         << "seconds: " << seconds << "\n"
         << "points_per_second: " << double(points.size()) / seconds << "\n"
         << "is_poisson_disk_set: " << (pds ? "true" : "false") << "\n"
         << "is_maximal: " << examples::maximality_text(maximal) << "\n"
         << "output: " << out_file << "\n";
    return examples::report(text.str(), pds && bool(maximal));
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
