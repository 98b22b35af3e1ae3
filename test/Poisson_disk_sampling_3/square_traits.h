// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A model of SurfaceFragmentTraits_3 written for the tests, as a user would write one, and what
// test_engine.cpp and engine_variant.cpp share: the engine run in two translation units compiled
// with different macros, on one model and one output type.

#ifndef CGAL_POISSON_DISK_SAMPLING_3_TEST_SQUARE_TRAITS_H
#define CGAL_POISSON_DISK_SAMPLING_3_TEST_SQUARE_TRAITS_H

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

// A named namespace: both translation units must see the same types, so that the engine's member
// templates instantiated for them have the same names in both.
namespace pds_test {

// A flat unit square in the plane z = 0, split into four squares; optionally refusing half of its
// darts, as a model that samples with rejection does.
class Square_traits
{
public:
  typedef std::array<double, 3> Point;
  struct Fragment { double x, y, size; };
  struct Sample { Point point; };

  explicit Square_traits(bool refuse_half = false) : refuse_half_(refuse_half) {}

  template <class Out> Out initial_fragments(Out out) const { *out++ = Fragment{0, 0, 1}; return out; }
  double area(const Fragment& f) const { return f.size * f.size; }
  template <class Rng> std::optional<Sample> random_sample(const Fragment& f, Rng& rng) const
  {
    if(refuse_half_ && rng.uniform() < 0.5) return std::nullopt;
    return Sample{{{f.x + f.size * rng.uniform(), f.y + f.size * rng.uniform(), 0.}}};
  }
  const Point& point(const Sample& s) const { return s.point; }
  Point reference_point(const Fragment& f) const { return {{f.x + f.size / 2, f.y + f.size / 2, 0.}}; }
  bool is_covered(const Fragment& f, const Point& c, double radius) const
  {
    const double r = radius - 4 * position_error();
    for(double x : {f.x, f.x + f.size})
      for(double y : {f.y, f.y + f.size})
        if((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + c[2] * c[2] > r * r * (1 - 1e-15)) return false;
    return true;
  }
  template <class Out> Out split(const Fragment& f, Out out) const
  {
    const double h = f.size / 2;
    for(double dx : {0., h})
      for(double dy : {0., h}) *out++ = Fragment{f.x + dx, f.y + dy, h};
    return out;
  }
  double position_error() const { return 1e-15; }

private:
  bool refuse_half_;
};

/// Writes the points of the samples the engine accepts.
struct Point_collector
{
  std::vector<Square_traits::Point>* points;
  void operator()(const Square_traits::Sample& s) const { points->push_back(s.point); }
};

/// A run of the engine on the square, compiled as its translation unit is.
struct Variant_run
{
  std::vector<Square_traits::Point> points;
  double stage_seconds = 0; // the stages' times, summed: 0 unless the unit times them
};

/// Runs the engine on the square at the distance 0.05 in engine_variant.cpp, compiled without
/// CGAL_LINKED_WITH_TBB and with CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES.
Variant_run run_in_variant_unit(std::uint64_t seed);

} // namespace pds_test

#endif // CGAL_POISSON_DISK_SAMPLING_3_TEST_SQUARE_TRAITS_H
