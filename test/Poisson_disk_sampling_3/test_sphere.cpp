// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sphere: maximal Poisson-disk sets on several spheres, the area formula, uniformity, and the
// coverage test that stays right near the poles where the paper's corner test fails.

#include "test_support.h"

#include <cmath>
#include <iterator>

namespace {

typedef PDS::Sphere_fragment_traits_3 Traits;
typedef Traits::Fragment Fragment;
const double pi = 3.14159265358979323846;

struct Case
{
  Point center;
  double radius, d;
  unsigned seed;
};

class SphereSampling : public ::testing::TestWithParam<Case> {};

TEST_P(SphereSampling, IsMaximalPoissonDiskSet)
{
  const Case c = GetParam();
  const K::Sphere_3 sphere(c.center, c.radius * c.radius);
  std::vector<Point> points;
  PDS::Sampling_statistics stats;
  PDS::sample_sphere(sphere, std::back_inserter(points),
                     PDS::parameters::minimum_distance(c.d).random_seed(c.seed).statistics(std::ref(stats)));
  EXPECT_EQ(stats.dropped_fragments, 0u);
  for(const Point& p : points)
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p, c.center)), c.radius, 1e-12 * (c.radius + 1000));
  expect_maximal_poisson_disk_set(sphere, points, c.d);
}

INSTANTIATE_TEST_SUITE_P(Spheres, SphereSampling,
                         ::testing::Values(Case{{0, 0, 0}, 1, 0.1, 1}, Case{{0, 0, 0}, 1, 0.02, 2},
                                           Case{{1, -2, 3}, 4, 0.1, 3}, Case{{1000, 0, -500}, 0.5, 0.01, 4},
                                           Case{{0, 0, 0}, 1, 1.5, 5}, Case{{0, 0, 0}, 1, 1.99, 6},
                                           Case{{0, 0, 0}, 1e-3, 2e-5, 7}));

TEST(SphereSampling, CountMatchesTheAreaAndIsReproducible)
{
  const K::Sphere_3 unit(CGAL::ORIGIN, 1);
  std::vector<Point> a, b;
  PDS::sample_sphere(unit, std::back_inserter(a), PDS::parameters::minimum_distance(0.01).random_seed(3));
  PDS::sample_sphere(unit, std::back_inserter(b), PDS::parameters::minimum_distance(0.01).random_seed(3));
  EXPECT_EQ(a, b);
  const double density = double(a.size()) * 0.01 * 0.01 / (4 * pi);
  EXPECT_NEAR(density, 0.6965, 0.02);
}

TEST(SphereSampling, NumberOfPoints)
{
  const K::Sphere_3 sphere(Point(0, 0, 1), 4);
  std::vector<Point> points;
  PDS::Sampling_statistics stats;
  PDS::sample_sphere(sphere, std::back_inserter(points),
                     PDS::parameters::number_of_points(5000).statistics(std::ref(stats)));
  EXPECT_LE(std::abs(double(points.size()) - 5000), 50);
  expect_maximal_poisson_disk_set(sphere, points, stats.minimum_distance);
}

// Area-uniform darts make the heights z of the samples uniform on [-R, R] (Archimedes); a biased
// sampler (e.g. uniform in phi) would crowd the poles. Ten slabs of equal area, compared with a
// chi-square bound far above its 9-degree-of-freedom expectation but far below what a bias gives.
TEST(SphereSampling, HeightsAreUniform)
{
  std::vector<Point> points;
  PDS::sample_sphere(K::Sphere_3(CGAL::ORIGIN, 1), std::back_inserter(points), PDS::parameters::minimum_distance(0.01));
  std::vector<double> slab(10, 0);
  for(const Point& p : points) slab[std::min(9, int((p.z() + 1) * 5))] += 1;
  const double expected = double(points.size()) / 10;
  double chi2 = 0;
  for(double n : slab) chi2 += (n - expected) * (n - expected) / expected;
  EXPECT_LT(chi2, 30) << "a maximal Poisson-disk set is far more regular than white noise, so even this is loose";
}

TEST(SphereFragments, AreaIsEquationOneAndChildrenTileTheParent)
{
  const Traits traits({{0, 0, 0}}, 2);
  std::vector<Fragment> roots;
  traits.initial_fragments(std::back_inserter(roots));
  double total = 0;
  for(const Fragment& f : roots) total += traits.area(f);
  EXPECT_NEAR(total, 4 * pi * 4, 1e-12);
  const Fragment f{0.3, 1.1, std::cos(1.0), std::cos(0.2)}; // theta in [0.3, 1.1], phi in [0.2, 1]
  EXPECT_NEAR(traits.area(f), 4 * (1.1 - 0.3) * (std::cos(0.2) - std::cos(1.0)), 1e-14);
  std::vector<Fragment> children;
  traits.split(f, std::back_inserter(children));
  ASSERT_EQ(children.size(), 4u);
  for(const Fragment& c : children) EXPECT_NEAR(traits.area(c), traits.area(f) / 4, 1e-14);
}

// Near the pole, an edge at constant phi is a small circle around the pole. Seen from a ball centred
// across the pole, the middle of the outer edge is farther than its ends: the four corners are inside
// the ball and that edge is not (the paper's Section 5.1 caveat).
TEST(SphereFragments, CoverageIsRightNearThePoleWhereTheCornerTestFails)
{
  const Traits traits({{0, 0, 0}}, 1);
  const double phi0 = 0.05, phi1 = 0.3;
  const Fragment f{0, 2.0, std::cos(phi1), std::cos(phi0)}; // a wide band near the north pole
  // the ball: centred on the sphere at phi = 0.1 across the pole (theta = 1 + pi), with a radius
  // that just holds the four corners
  const double pc = 0.1, tc = 1 + 3.14159265358979323846;
  const Traits::Point c{{std::sin(pc) * std::cos(tc), std::sin(pc) * std::sin(tc), std::cos(pc)}};
  auto at = [](double theta, double phi) {
    return Traits::Point{{std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)}};
  };
  auto dist = [&](const Traits::Point& p) {
    return std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2]));
  };
  double corner_max = 0;
  for(double theta : {0., 2.}) for(double phi : {phi0, phi1}) corner_max = std::max(corner_max, dist(at(theta, phi)));
  const double radius = corner_max * (1 + 1e-9);
  // a dense walk over the boundary finds points outside the ball
  double far = 0;
  for(int i = 0; i <= 1000; ++i) {
    const double s = i / 1000.;
    far = std::max({far, dist(at(2 * s, phi0)), dist(at(2 * s, phi1)), dist(at(0, phi0 + s * (phi1 - phi0))),
                    dist(at(2, phi0 + s * (phi1 - phi0)))});
  }
  ASSERT_GT(far, radius * 1.01) << "the configuration should expose the corner test";
  EXPECT_TRUE(traits.are_corners_covered(f, c, radius)) << "the paper's test says covered";
  EXPECT_FALSE(traits.is_covered(f, c, radius)) << "ours must not";
  EXPECT_TRUE(traits.is_covered(f, c, far * (1 + 1e-9))) << "and is not merely conservative";
  EXPECT_FALSE(traits.is_covered(f, c, far * (1 - 1e-6)));
}

// The closed-form minimum agrees with a dense evaluation on many random rectangles and balls.
TEST(SphereFragments, CoverageMatchesDenseEvaluation)
{
  const Traits traits({{0.5, -1, 2}}, 1.5);
  PDS::internal::Random rng(7);
  int covered = 0;
  for(int trial = 0; trial < 2000; ++trial) {
    const double t0 = rng.uniform() * 2 * pi, t1 = t0 + rng.uniform() * (2 * pi - t0);
    const double za = 2 * rng.uniform() - 1, zb = 2 * rng.uniform() - 1;
    const Fragment f{t0, t1, std::min(za, zb), std::max(za, zb)};
    const double tc = rng.uniform() * 2 * pi, zc = 2 * rng.uniform() - 1, rc = std::sqrt(1 - zc * zc);
    const Traits::Point c{{0.5 + 1.5 * rc * std::cos(tc), -1 + 1.5 * rc * std::sin(tc), 2 + 1.5 * zc}};
    double worst = 0;
    for(int i = 0; i <= 200; ++i)
      for(int j = 0; j <= 200; ++j) {
        const double theta = t0 + (t1 - t0) * i / 200, z = f.z0 + (f.z1 - f.z0) * j / 200;
        const double r = std::sqrt(std::max(0., 1 - z * z));
        const double x = 0.5 + 1.5 * r * std::cos(theta) - c[0], y = -1 + 1.5 * r * std::sin(theta) - c[1],
                     w = 2 + 1.5 * z - c[2];
        worst = std::max(worst, std::sqrt(x * x + y * y + w * w));
      }
    // the grid only sees a lower bound of the true farthest distance, within its spacing
    EXPECT_FALSE(traits.is_covered(f, c, worst * (1 - 1e-9))) << trial;
    if(traits.is_covered(f, c, worst * 1.01)) ++covered;
  }
  EXPECT_GT(covered, 1900);
}

} // namespace
