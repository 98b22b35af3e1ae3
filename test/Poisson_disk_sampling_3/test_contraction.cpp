// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package compiled as users may compile it: with a product and a sum fused into one instruction
// (FMA) wherever the compiler likes. This program alone is built with -ffp-contract=fast, and with
// -mfma where the compiler has the flag and the machine that builds it runs FMA (CMakeLists.txt).
// Fused or not, a value the engine computes twice must come out the same both times: the sphere's
// area of a cell, computed from its bounds, differed by a unit in the last place between two places
// where it was inlined, and every sampling of the sphere stopped at a precondition of the fragment
// pool. The points differ from an unfused build's (design.md, "Reproducibility"); what must hold is
// that every run is a maximal Poisson-disk set.

#include "test_support.h"

#include <vector>

namespace {

TEST(Contraction, FusedInstructionsAreOn)
{
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA) || defined(__FP_FAST_FMA)
  SUCCEED();
#else
  GTEST_SKIP() << "this compiler or machine has no FMA: the other tests here run unfused";
#endif
}

TEST(Contraction, SphereSamplesAreMaximal)
{
  const K::Sphere_3 unit(Point(0, 0, 0), 1);
  for(double d : {0.02, 0.05, 0.1, 0.2}) {
    for(unsigned seed = 0; seed < 5; ++seed) {
      std::vector<Point> out;
      PDS::sample_sphere(unit, std::back_inserter(out), PDS::parameters::minimum_distance(d).random_seed(seed));
      EXPECT_GT(out.size(), 0.5 * 4 * 3.14159 / (d * d)) << d << " " << seed;
      EXPECT_TRUE(PDS::is_poisson_disk_set(out, d)) << d << " " << seed;
      EXPECT_TRUE(PDS::is_maximal(unit, out, d)) << d << " " << seed;
    }
  }
}

TEST(Contraction, MeshSamplesAreMaximal)
{
  for(const char* name : {"fandisk.off", "lion.off"}) {
    const Mesh m = load_mesh(name);
    const double d = distance_for(CGAL::Polygon_mesh_processing::area(m), 5000);
    for(unsigned seed = 0; seed < 2; ++seed) {
      std::vector<Point> out;
      PDS::sample_triangle_mesh(m, std::back_inserter(out), PDS::parameters::minimum_distance(d).random_seed(seed));
      EXPECT_GT(out.size(), 4000u) << name;
      EXPECT_TRUE(PDS::is_poisson_disk_set(out, d)) << name;
      EXPECT_TRUE(PDS::is_maximal(m, out, d)) << name;
    }
  }
}

} // namespace
