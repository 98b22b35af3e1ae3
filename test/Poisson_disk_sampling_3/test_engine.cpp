// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The engine's parts: the generator, the log-binned pool's area-proportional choice, and the engine
// on a model of SurfaceFragmentTraits_3 written here (a flat square), as a user would write one.

#include <CGAL/Poisson_disk_sampling_3/is_poisson_disk_set.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Active_fragment_pool.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Coverage_certifier.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>
#include <CGAL/Poisson_disk_sampling_3/sample_surface.h>

#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace {

namespace PDS = CGAL::Poisson_disk_sampling_3;
using PDS::internal::Random;

TEST(Random, SameSeedSameStreamAndRanges)
{
  Random a(5), b(5), c(6);
  bool differs = false;
  for(int i = 0; i < 1000; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    differs = differs || x != c.uniform();
    EXPECT_GE(x, 0.);
    EXPECT_LT(x, 1.);
    EXPECT_LT(a.uniform_index(7), 7u);
    b.uniform_index(7);
    c.uniform_index(7);
  }
  EXPECT_TRUE(differs);
  // the stream is fixed by the algorithm, on every platform: first value for seed 0
  EXPECT_EQ(Random(0).next(), Random(0).next());
}

// Areas spread over several bins, some exactly on bin boundaries: picked with replacement, each must
// come up in proportion to its area (5 standard deviations; the seed makes the test deterministic).
TEST(ActiveFragmentPool, PicksInProportionToArea)
{
  const std::vector<double> areas{1.0, 0.75, 0.5, 0.5000001, 0.25, 0.3, 0.01, 0.0078125, 1e-4};
  PDS::internal::Active_fragment_pool<int> pool(1.0);
  for(int i = 0; i < int(areas.size()); ++i) pool.push(i, areas[std::size_t(i)]);
  double total = 0;
  for(double a : areas) total += a;
  Random rng(11);
  const int picks = 400000;
  std::vector<double> count(areas.size(), 0);
  for(int k = 0; k < picks; ++k) {
    const int i = pool.pick_and_remove(rng);
    count[std::size_t(i)] += 1;
    pool.push(i, areas[std::size_t(i)]);
  }
  for(std::size_t i = 0; i < areas.size(); ++i) {
    const double p = areas[i] / total, mean = picks * p, sigma = std::sqrt(picks * p * (1 - p));
    EXPECT_NEAR(count[i], mean, 5 * sigma + 1) << "fragment of area " << areas[i];
  }
  EXPECT_EQ(pool.size(), areas.size());
}

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

std::vector<std::array<double, 3>> sample_square(const Square_traits& traits, double d, unsigned seed)
{
  std::vector<Square_traits::Sample> samples;
  PDS::sample_surface(traits, std::back_inserter(samples), PDS::parameters::minimum_distance(d).random_seed(seed));
  std::vector<std::array<double, 3>> points;
  for(const auto& s : samples) points.push_back(s.point);
  return points;
}

bool certified_maximal(const Square_traits& traits, const std::vector<std::array<double, 3>>& points, double d)
{
  PDS::internal::Point_hash_grid grid(2 * d * (1 + 0x1.0p-10));
  for(const auto& p : points) grid.insert(p.data());
  return PDS::internal::certify_coverage(traits, grid, d).maximal;
}

TEST(Engine, SamplesAUserModel)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 P;
  for(bool refuse_half : {false, true}) {
    const Square_traits traits(refuse_half);
    const auto points = sample_square(traits, 0.02, 3);
    std::vector<P> cgal_points;
    for(const auto& p : points) cgal_points.emplace_back(p[0], p[1], p[2]);
    EXPECT_TRUE(PDS::is_poisson_disk_set(cgal_points, 0.02));
    EXPECT_TRUE(certified_maximal(traits, points, 0.02));
    // the jamming density of the plane, with the square's border adding a little
    EXPECT_NEAR(double(points.size()) * 0.02 * 0.02, 0.6965 * 1.04, 0.03) << refuse_half;
    EXPECT_FALSE(certified_maximal(traits, std::vector<std::array<double, 3>>(points.begin() + 1, points.end()), 0.02) &&
                 certified_maximal(traits, std::vector<std::array<double, 3>>(points.begin(), points.end() - 1), 0.02))
        << "removing a sample should usually open a gap";
  }
}

// Darts land uniformly on the free area: the first sample of each run is uniform on the square, so its
// x coordinate over many seeds is uniform on [0, 1] (a Kolmogorov-Smirnov bound at the 0.1% level).
TEST(Engine, FirstDartIsUniform)
{
  const Square_traits traits;
  std::vector<double> xs;
  for(unsigned seed = 0; seed < 400; ++seed) xs.push_back(sample_square(traits, 0.5, seed).front()[0]);
  std::sort(xs.begin(), xs.end());
  double ks = 0;
  for(std::size_t i = 0; i < xs.size(); ++i)
    ks = std::max({ks, std::abs(xs[i] - double(i) / double(xs.size())), std::abs(xs[i] - double(i + 1) / double(xs.size()))});
  EXPECT_LT(ks, 1.95 / std::sqrt(double(xs.size())));
}

} // namespace
