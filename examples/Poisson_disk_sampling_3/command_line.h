// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the example programs' command lines share: numbers read strictly (a malformed one is an error,
// never a silent 0), each option at most once (a second value is an error, never a silent choice),
// and the one size option every sampler takes (--radius, --minimum-distance or --count) with --seed
// and --maximum-number-of-points: sizes that are no positive number are refused here, as a command
// line the program cannot use; the library checks the rest (a distance against the surface's precision,
// a count against the bound) and names the bad value.

#ifndef CGAL_POISSON_DISK_SAMPLING_3_EXAMPLES_COMMAND_LINE_H
#define CGAL_POISSON_DISK_SAMPLING_3_EXAMPLES_COMMAND_LINE_H

#include <CGAL/Poisson_disk_sampling_3.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace examples {

/// a command line the program cannot use; main() prints it with the usage
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// the number in argv[i + 1], after argv[i]; advances i. Errors name `option`, by default argv[i] (an
/// option that takes several numbers passes its own name for the numbers after the first)
inline double read_number(int argc, char** argv, int& i, std::string option = std::string())
{
  if(option.empty()) option = argv[i];
  if(i + 1 >= argc) throw Usage_error("missing number after " + option);
  char* end = nullptr;
  const char* text = argv[++i];
  const double value = std::strtod(text, &end);
  if(end == text || *end != '\0') throw Usage_error("malformed number after " + option + ": " + text);
  return value;
}

/// the integer in argv[i + 1], after argv[i], from 0 to 2^64 - 1 in decimal digits (read as a double,
/// a seed above 2^53 would be rounded to another one); advances i
inline std::uint64_t read_seed(int argc, char** argv, int& i)
{
  const std::string option = argv[i];
  if(i + 1 >= argc) throw Usage_error("missing number after " + option);
  const std::string text = argv[++i];
  // (digits only: from_chars takes no sign for an unsigned type, and says when the value is too large)
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if(text.empty() || error != std::errc() || end != text.data() + text.size())
    throw Usage_error(option + " takes an integer from 0 to 18446744073709551615, not \"" + text + "\"");
  return value;
}

/// the options seen so far: each may be given once
struct Seen_options
{
  std::set<std::string> seen;

  /// records `option`; throws if it was given before
  void once(const std::string& option)
  {
    if(!seen.insert(option).second) throw Usage_error(option + " is given more than once");
  }
};

/// whether argv[i] asks for the usage; main() then prints it and `exit_statuses` and returns 0
inline bool is_help(const std::string& a) { return a == "--help" || a == "-h"; }

/// what the programs' exit statuses mean
constexpr const char* exit_statuses =
    "exit status: 0 when the samples were written, a Poisson-disk set certified maximal; 1 after an\n"
    "error, or when their validation failed or was undecided; 2 for a command line it cannot use\n";

/// the file name after argv[i] (`-o`); advances i. A name that starts with '-' is refused as an option
/// given by mistake (`-o --radius 0.1` wrote to a file "--radius"): write ./-name for such a file.
inline std::string read_file_name(int argc, char** argv, int& i)
{
  const std::string option = argv[i];
  if(i + 1 >= argc) throw Usage_error("missing file name after " + option);
  const std::string name = argv[++i];
  if(name.empty()) throw Usage_error(option + " takes a file name, not an empty one");
  if(name[0] == '-')
    throw Usage_error(option + " takes a file name, not \"" + name + "\" (for a file of that name: ./" + name + ")");
  return name;
}

/// Throws unless `name` can be a file to write: not a folder, in a folder that exists. Checked before
/// sampling, so that a run is not lost for a mistyped path (writing can still fail, on a full disk).
inline void check_output_path(const std::string& name)
{
  std::error_code error;
  const std::filesystem::path path(name);
  if(std::filesystem::is_directory(path, error)) throw Usage_error("-o names a folder: " + name);
  const std::filesystem::path folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  if(!std::filesystem::is_directory(folder, error))
    throw Usage_error("-o names a file in a folder that does not exist: " + name);
}

/// Prints `text` (the usage and the defaults) and `exit_statuses` on the standard output (for --help):
/// 0, or 1 with a line on the standard error if they could not be written.
inline int help(const std::string& text)
{
  std::cout << text << exit_statuses << std::flush;
  if(!std::cout) {
    std::cerr << "error: cannot write the usage to the standard output\n";
    return 1;
  }
  return 0;
}

/// Closes `out`, the file `name` being written, and throws unless all of it was written: the last
/// buffer is written when the file is closed (on a full disk, a small output was lost unsaid).
inline void close_output(std::ofstream& out, const std::string& name)
{
  out.close();
  if(!out) throw std::runtime_error("cannot write " + name);
}

/// Prints `text` on the standard output and returns the exit status: 0 if the samples are valid
/// (a Poisson-disk set, certified maximal), else 1, with a line on the standard error, as when the
/// report cannot be written.
inline int report(const std::string& text, bool valid)
{
  std::cout << text << std::flush;
  if(!std::cout) {
    std::cerr << "error: cannot write the report to the standard output\n";
    return 1;
  }
  if(!valid) {
    std::cerr << "error: the samples' validation failed or was undecided (is_poisson_disk_set, is_maximal)\n";
    return 1;
  }
  return 0;
}

/// The file `name` of the examples' data: CGAL's meshes in the build tree, then the data folder
/// installed beside the program (found from the program's own path, so that an installation made
/// with `cmake --install build --prefix <prefix>` under another prefix than the configured one, or
/// moved, still finds it), then the configured prefix's, then the working folder.
inline std::string data_file(const std::string& name)
{
  std::vector<std::filesystem::path> folders;
#ifdef CGAL_PDS_DATA_DIR
  folders.push_back(CGAL_PDS_DATA_DIR);
#endif
#ifdef CGAL_PDS_DATA_DIR_FROM_PROGRAM
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if(!error) folders.push_back(program.parent_path() / CGAL_PDS_DATA_DIR_FROM_PROGRAM);
#endif
#ifdef CGAL_PDS_INSTALLED_DATA_DIR
  folders.push_back(CGAL_PDS_INSTALLED_DATA_DIR);
#endif
  folders.push_back(".");
  for(const std::filesystem::path& folder : folders) {
    std::error_code error;
    const std::filesystem::path path = folder / name;
    if(std::filesystem::is_regular_file(path, error)) return path.string();
  }
  return name;
}

struct Size_options
{
  std::optional<double> radius, minimum_distance, count, max_points;
  std::optional<std::uint64_t> seed;

  /// reads argv[i] (and its value) if it is one of the size options, --seed or
  /// --maximum-number-of-points; advances i
  bool read(int argc, char** argv, int& i, Seen_options& seen)
  {
    const std::string a = argv[i];
    if(a == "--seed") {
      seen.once(a);
      seed = read_seed(argc, argv, i);
      return true;
    }
    std::optional<double>* target = a == "--radius" ? &radius
                                    : a == "--minimum-distance" ? &minimum_distance
                                    : a == "--count" ? &count
                                    : a == "--maximum-number-of-points" ? &max_points
                                    : nullptr;
    if(!target) return false;
    seen.once(a);
    *target = read_number(argc, argv, i);
    return true;
  }

  /// one size at most, a positive and finite one, integers below 10^18 where integers are meant (the
  /// library then checks the values against the surface: a distance too small for its coordinates'
  /// precision, a count above the bound)
  void check() const
  {
    if(bool(radius) + bool(minimum_distance) + bool(count) > 1)
      throw Usage_error("give one of --radius, --minimum-distance, --count");
    if(radius && !(*radius > 0 && std::isfinite(*radius))) throw Usage_error("--radius takes a positive number");
    if(minimum_distance && !(*minimum_distance > 0 && std::isfinite(*minimum_distance)))
      throw Usage_error("--minimum-distance takes a positive number");
    if(count && !(*count >= 1 && *count == std::floor(*count) && *count < 1e18))
      throw Usage_error("--count takes a positive integer below 10^18");
    if(max_points && !(*max_points >= 1 && *max_points == std::floor(*max_points) && *max_points < 1e18))
      throw Usage_error("--maximum-number-of-points takes a positive integer below 10^18");
  }

  /// Calls `sample(np)` with the named parameters of the size given, the seed, the bound and `stats`
  /// to fill. With no size, `default_distance`; where that is not a positive, finite distance (a
  /// surface whose area is zero or overflows), `default_count` points, so that the library names
  /// what is wrong with the surface, not with a distance the user did not give.
  template <class Sample>
  void sample_with(double default_distance, std::size_t default_count,
                   CGAL::Poisson_disk_sampling_3::Sampling_statistics& stats, Sample&& sample) const
  {
    namespace P = CGAL::Poisson_disk_sampling_3::parameters;
    const std::uint64_t s = seed ? *seed : 0;
    const std::size_t m = max_points ? std::size_t(*max_points) : std::size_t(100000000);
    // the options every size takes
    auto with_options = [&](const auto& size_np) {
      return size_np.random_seed(s).maximum_number_of_points(m).statistics(std::ref(stats));
    };
    const bool use_count = count || (!radius && !minimum_distance &&
                                      !(default_distance > 0 && std::isfinite(default_distance)));
    if(use_count) sample(with_options(P::number_of_points(count ? std::size_t(*count) : default_count)));
    else if(radius) sample(with_options(P::radius(*radius)));
    else sample(with_options(P::minimum_distance(minimum_distance ? *minimum_distance : default_distance)));
  }
};

/// `x` with the fewest significant digits that give it back when read (at most 17), so that the
/// minimum distance a `--count` run found, given back with `--minimum-distance` and its `random_seed`
/// with `--seed`, gives the same samples, and a distance given as 0.1 is printed 0.1
inline std::string exact_text(double x)
{
  for(int digits = 1;; ++digits) {
    std::ostringstream text;
    text.precision(digits);
    text << x;
    if(digits >= 17 || std::strtod(text.str().c_str(), nullptr) == x) return text.str();
  }
}

/// the answer of `is_maximal()` for the report: true, false with the place of a gap, or undecided (a
/// set maximal with no margin, or the certificate's bounds on its work reached: user manual, Validation)
template <class Maximality_check>
std::string maximality_text(const Maximality_check& check)
{
  if(check) return "true";
  if(!check.uncovered_point) return "undecided";
  const auto& p = *check.uncovered_point;
  std::ostringstream text;
  text << "false (one more sample fits at " << p.x() << " " << p.y() << " " << p.z() << ")";
  return text.str();
}

} // namespace examples

#endif // CGAL_POISSON_DISK_SAMPLING_3_EXAMPLES_COMMAND_LINE_H
