// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sample_mesh [MESH] [--radius R | --minimum-distance D | --count N] [--seed S]
//             [--maximum-number-of-points M] [-o OUT.ply]
//
// Samples a triangle mesh (any file CGAL reads: OFF, OBJ, PLY, STL; by default lion.off from CGAL's
// data set) with a maximal Poisson-disk set, checks the result with the package's exact validation,
// writes a binary PLY (x y z, nx ny nz, face index) and prints one `key: value` a line. The file is
// read as a polygon soup and made into a Surface_mesh where its polygons make a valid one; a mesh's
// faces that are not triangles are triangulated first (CGAL::Polygon_mesh_processing::
// triangulate_faces(): the library samples triangles only), and the face indices written are then
// the triangulated mesh's. Triangles that make no valid polygon mesh (faces oriented
// inconsistently, an edge shared by three faces, ...) are sampled as a polygon soup, with
// sample_polygon_soup_with_locations().

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Poisson_disk_sampling_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include "command_line.h"

#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace PDS = CGAL::Poisson_disk_sampling_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::vector<std::vector<std::size_t>> Polygons;

namespace {

const char* const usage_line = "usage: sample_mesh [MESH] [--radius R | --minimum-distance D | --count N] [--seed S]\n"
                               "                   [--maximum-number-of-points M] [-o OUT.ply]\n";

const char* const defaults =
    "MESH: any file CGAL reads, its format chosen by its extension (.off, .obj, .ply, .stl); by default\n"
    "lion.off from CGAL's data set. With no size, about 10,000 points; --seed 0; --maximum-number-of-points\n"
    "100000000. The samples are written to OUT.ply (by default samples.ply, replaced if it exists).\n";

int usage(const char* message)
{
  std::cerr << "error: " << message << "\n" << usage_line;
  return 2;
}

// CGAL 5.5's STL reader takes a binary file's corner whose coordinate is NaN for an earlier corner
// (it merges equal points in a std::map, where a NaN is neither less nor greater than any coordinate,
// so that it falls on a point already there): another surface, unsaid. Returns what is wrong with a binary STL file (80 bytes, a count n, then n triangles of
// 50 bytes), or nothing, also for a file that is not one (whose text has no byte of a float that is
// not finite).
std::string binary_stl_problem(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  for(char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if(extension != ".stl" || error || size < 84) return std::string();
  std::ifstream in(path, std::ios::binary);
  unsigned char count[4];
  in.seekg(80);
  if(!in.read(reinterpret_cast<char*>(count), 4)) return std::string();
  const std::uintmax_t n = std::uintmax_t(count[0]) | std::uintmax_t(count[1]) << 8 |
                           std::uintmax_t(count[2]) << 16 | std::uintmax_t(count[3]) << 24;
  if(size != 84 + 50 * n) return std::string();
  unsigned char triangle[50];
  for(std::uintmax_t t = 0; t < n && in.read(reinterpret_cast<char*>(triangle), 50); ++t)
    for(int k = 3; k < 12; ++k) { // the corners' coordinates, after the normal: little-endian floats
      const unsigned char* b = triangle + 4 * k;
      if((b[3] & 0x7f) == 0x7f && (b[2] & 0x80) != 0) // all the exponent's bits: infinite or NaN
        return "triangle " + std::to_string(t) + " has a coordinate that is not finite";
    }
  return std::string();
}

// CGAL 5.5's PLY reader dereferences a null pointer where a vertex coordinate is not a float or a
// double (an int, a list), where a half-edge's source or target is not an unsigned int, and where a
// property comes before any element, and reads a coordinate that is missing as 0 (another surface,
// unsaid): the header of a PLY file is checked first, as that reader reads it (its elements "vertex"
// or "vertices", and "halfedge"). Returns what is wrong with it, or nothing (also for a file that is
// no PLY, which CGAL's readers judge).
std::string ply_header_problem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  // the header's lines, read up to 1 MB in all (a file of zeros has no line end)
  std::size_t budget = std::size_t(1) << 20;
  auto next_line = [&] {
    line.clear();
    for(char c; budget > 0 && in.get(c); --budget) {
      if(c == '\n') break;
      if(c != '\r') line.push_back(c);
    }
    return !line.empty() || (budget > 0 && in);
  };
  std::string first_word;
  if(!next_line() || !(std::istringstream(line) >> first_word) || first_word != "ply") return std::string();
  std::string element;
  bool any_element = false, has_vertices = false;
  std::set<std::string> coordinates;
  while(next_line()) {
    std::istringstream words(line);
    std::string keyword, type, name;
    words >> keyword;
    if(keyword == "end_header") {
      if(has_vertices)
        for(const char* c : {"x", "y", "z"})
          if(!coordinates.count(c)) return std::string("its vertices have no ") + c + " coordinate";
      return std::string();
    }
    if(keyword == "element") {
      words >> element;
      any_element = true;
      has_vertices = has_vertices || element == "vertex" || element == "vertices";
    } else if(keyword == "property") {
      if(!any_element) return "a property comes before any element";
      words >> type;
      if(type == "list") words >> name >> name; // the types of the count and of the items
      words >> name;
      const std::string kind = type == "list" ? "a list" : "of type " + type;
      if((element == "vertex" || element == "vertices") && (name == "x" || name == "y" || name == "z")) {
        if(type != "float" && type != "double" && type != "float32" && type != "float64")
          return "its vertices' " + name + " coordinate is " + kind + "; this program reads coordinates of type "
                 "float or double";
        coordinates.insert(name);
      }
      if(element == "halfedge" && (name == "source" || name == "target") && type != "uint" && type != "uint32")
        return "its half-edges' " + name + " is " + kind + "; CGAL reads it as an unsigned int (uint) only";
    }
  }
  return "its header has no end_header line within its first megabyte";
}

template <class Sample>
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
  examples::close_output(out, path);
}

// Samples with `sample(np, out)`, validates with `is_maximal(points, d)`, writes the PLY and prints the
// report; returns the program's exit status.
template <class Sample, class Sampler, class Certifier>
int sample_and_report(const std::string& mesh_file, const char* kind, std::size_t faces, double area,
                      const examples::Size_options& size, const std::string& out_file, Sampler sample,
                      Certifier is_maximal)
{
  std::vector<Sample> samples;
  PDS::Sampling_statistics stats;
  // with no size: about 10,000 points
  const double default_distance = std::sqrt(0.6965 * area / 10000);
  const auto start = std::chrono::steady_clock::now();
  size.sample_with(default_distance, 10000, stats, [&](const auto& np) { sample(np, std::back_inserter(samples)); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<K::Point_3> points;
  for(const Sample& s : samples) points.push_back(s.point);
  const bool pds = bool(PDS::is_poisson_disk_set(points, stats.minimum_distance));
  const auto maximal = is_maximal(points, stats.minimum_distance);
  write_ply(out_file, samples);

  std::ostringstream text;
  text << "mesh: " << mesh_file << "\n"
       << "read_as: " << kind << "\n"
       << "faces: " << faces << "\n"
       << "points: " << samples.size() << "\n"
       << "minimum_distance: " << examples::exact_text(stats.minimum_distance) << "\n"
       << "random_seed: " << stats.random_seed << "\n"
       << "runs: " << stats.number_of_runs << "\n"
       << "seconds: " << seconds << "\n"
       << "points_per_second: " << double(samples.size()) / seconds << "\n"
       << "darts: " << stats.darts << "\n"
       << "dropped_fragments: " << stats.dropped_fragments << "\n"
       << "is_poisson_disk_set: " << (pds ? "true" : "false") << "\n"
       << "is_maximal: " << examples::maximality_text(maximal) << "\n"
       << "output: " << out_file << "\n";
  return examples::report(text.str(), pds && bool(maximal));
}

// whether a polygon names one point twice (orient_polygon_soup() requires that none does)
bool repeats_a_vertex(const Polygons& polygons)
{
  for(const auto& p : polygons)
    if(std::set<std::size_t>(p.begin(), p.end()).size() != p.size()) return true;
  return false;
}

// the area of a soup of triangles whose indices are checked
double soup_area(const std::vector<K::Point_3>& points, const Polygons& polygons)
{
  double area = 0;
  for(const auto& p : polygons)
    area += std::sqrt(CGAL::to_double(K::Triangle_3(points[p[0]], points[p[1]], points[p[2]]).squared_area()));
  return area;
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
      if(examples::is_help(a)) return examples::help(std::string(usage_line) + defaults);
      if(size.read(argc, argv, i, seen)) continue;
      if(a == "-o") {
        seen.once(a);
        out_file = examples::read_file_name(argc, argv, i);
      } else if(!a.empty() && a[0] == '-') throw examples::Usage_error("unknown option or missing value: " + a);
      else if(mesh_file.empty()) mesh_file = a;
      else throw examples::Usage_error("more than one mesh");
    }
    size.check();
    examples::check_output_path(out_file);
  } catch(const examples::Usage_error& e) {
    return usage(e.what());
  }
  if(mesh_file.empty()) mesh_file = examples::data_file("lion.off");

  try {
    std::error_code error;
    if(std::filesystem::is_directory(mesh_file, error) || !std::ifstream(mesh_file, std::ios::binary)) {
      std::cerr << "error: cannot open " << mesh_file << "\n";
      return 1;
    }
    const std::string file_problem =
        ply_header_problem(mesh_file) + binary_stl_problem(mesh_file); // (a file is one or the other)
    if(!file_problem.empty()) {
      std::cerr << "error: cannot read " << mesh_file << ": " << file_problem << "\n";
      return 1;
    }
    // The file's polygons, read once, checked, then made into a mesh where they make a valid one.
    std::vector<K::Point_3> soup_points;
    Polygons soup_polygons;
    bool read = false;
    try {
      read = CGAL::IO::read_polygon_soup(mesh_file, soup_points, soup_polygons);
    } catch(const std::length_error&) {
      // a count of the file that no vector can hold (a negative one, read as unsigned)
    }
    if(!read) {
      std::cerr << "error: cannot read a polygon mesh or polygon soup from " << mesh_file
                << " (its format is chosen by its extension: .off, .obj, .ply or .stl)\n";
      return 1;
    }
    std::size_t not_triangles = 0;
    for(std::size_t i = 0; i < soup_polygons.size(); ++i) {
      if(soup_polygons[i].size() < 3) {
        std::cerr << "error: polygon " << i << " of " << mesh_file << " has " << soup_polygons[i].size()
                  << (soup_polygons[i].size() == 1 ? " vertex" : " vertices") << "; a polygon needs at least 3\n";
        return 1;
      }
      not_triangles += (soup_polygons[i].size() != 3);
      for(std::size_t v : soup_polygons[i])
        if(v >= soup_points.size()) {
          std::cerr << "error: polygon " << i << " of " << mesh_file << " refers to point " << v
                    << " (counted from 0), of " << soup_points.size() << " points\n";
          return 1;
        }
    }
    const auto faces_text = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " face" : " faces"); };
    const std::string not_triangles_text = faces_text(not_triangles) + " of " + mesh_file +
                                           (not_triangles == 1 ? " is not a triangle" : " are not triangles");

    // Polygons that are not triangles are triangulated on a mesh: where they make no valid one (faces
    // oriented inconsistently, a vertex or an edge where sheets meet), they are oriented first, and
    // points are duplicated where sheets meet (the same surface). Triangles that make no valid mesh are
    // sampled as they are, as a soup.
    bool oriented = false;
    if(not_triangles > 0 && !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup_polygons) &&
       !repeats_a_vertex(soup_polygons)) {
      CGAL::Polygon_mesh_processing::orient_polygon_soup(soup_points, soup_polygons);
      oriented = true;
    }
    if(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup_polygons)) {
      Mesh mesh;
      CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup_points, soup_polygons, mesh);
      soup_points = {};
      soup_polygons = {};
      if(not_triangles > 0 && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh)) {
        std::cerr << "error: " << not_triangles_text << ", and CGAL::Polygon_mesh_processing::triangulate_faces() "
                  << "failed (a degenerate or self-intersecting face?); the library samples triangles only\n";
        return 1;
      }
      const std::string read_as = oriented ? "polygon soup, oriented into a polygon mesh" : "polygon mesh";
      const std::string kind = not_triangles == 0 ? read_as
                                                  : read_as + ", " + faces_text(not_triangles) +
                                                        " triangulated (face indices are the triangulated mesh's)";
      return sample_and_report<PDS::Triangle_sample<K, Mesh::Face_index>>(
          mesh_file, kind.c_str(), num_faces(mesh), CGAL::Polygon_mesh_processing::area(mesh), size, out_file,
          [&](const auto& np, auto out) { PDS::sample_triangle_mesh_with_locations(mesh, out, np); },
          [&](const std::vector<K::Point_3>& points, double d) { return PDS::is_maximal(mesh, points, d); });
    }
    if(not_triangles > 0) {
      // (the soup was a mesh neither as read nor once oriented; it was not oriented where a polygon
      // repeats a vertex)
      std::cerr << "error: " << not_triangles_text << ", and the file's "
                << "polygons make no valid polygon mesh (" << (!oriented ? "a polygon "
                   "repeats a vertex" : "not even once oriented") << "), so this program cannot triangulate "
                   "them; the library samples triangles only\n";
      return 1;
    }
    return sample_and_report<PDS::Triangle_sample<K, std::size_t>>(
        mesh_file, "polygon soup (not a valid polygon mesh)", soup_polygons.size(),
        soup_area(soup_points, soup_polygons), size, out_file,
        [&](const auto& np, auto out) {
          PDS::sample_polygon_soup_with_locations(soup_points, soup_polygons, out, np);
        },
        [&](const std::vector<K::Point_3>& points, double d) {
          return PDS::is_maximal_on_polygon_soup(soup_points, soup_polygons, points, d);
        });
  } catch(const std::bad_alloc&) {
    std::cerr << "error: out of memory reading or sampling " << mesh_file << "\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
