// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks of fragment models that the triangle and sphere tests share.

#ifndef CGAL_POISSON_DISK_SAMPLING_3_TEST_FRAGMENT_CHECKS_H
#define CGAL_POISSON_DISK_SAMPLING_3_TEST_FRAGMENT_CHECKS_H

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <vector>

// The Kolmogorov-Smirnov distance between the sample `xs` and the distribution function `cdf`; the
// sample comes from that distribution with 99.9% probability where it is below 1.95 / sqrt(n).
template <class Cdf>
double one_sample_ks_distance(std::vector<double> xs, Cdf cdf)
{
  std::sort(xs.begin(), xs.end());
  const double n = double(xs.size());
  double ks = 0;
  for(std::size_t i = 0; i < xs.size(); ++i) {
    const double f = cdf(xs[i]);
    ks = (std::max)({ks, std::abs(f - double(i) / n), std::abs(f - double(i + 1) / n)});
  }
  return ks;
}

// a fragment `levels` splits below `f`, taking a random child at each split
template <class Traits, class Random>
typename Traits::Fragment random_descendant(const Traits& traits, typename Traits::Fragment f, int levels, Random& rng)
{
  for(; levels > 0; --levels) {
    std::vector<typename Traits::Fragment> children;
    traits.split(f, std::back_inserter(children));
    f = children[rng.uniform_index(children.size())];
  }
  return f;
}

// how often each branch of the engine's step was taken, so that a test can check it has teeth
struct Refine_counts
{
  int parent_covered = 0, child_by_single = 0, child_by_union = 0, child_kept = 0;
};

// The engine's step for f through is_covered(), split() and is_covered_by_union() one by one, as the
// engine takes it without refine(): returns whether one ball of `near` covers f, and otherwise writes
// the children of positive area that neither one ball of `near` nor the union test covers
template <class Traits>
bool step_by_operations(const Traits& traits, const typename Traits::Fragment& f,
                        const std::vector<std::array<double, 3>>& near,
                        const std::vector<std::array<double, 3>>& around, double radius,
                        std::vector<typename Traits::Fragment>& kept, Refine_counts& counts)
{
  typedef typename Traits::Fragment Fragment;
  bool covered = false;
  for(const auto& c : near) covered = covered || traits.is_covered(f, c, radius);
  kept.clear();
  if(covered) return true;
  std::vector<Fragment> children;
  traits.split(f, std::back_inserter(children));
  for(const Fragment& c : children) {
    bool single = false;
    for(const auto& b : near) single = single || traits.is_covered(c, b, radius);
    const bool by_union = !single && traits.is_covered_by_union(c, around, radius);
    counts.child_by_single += single;
    counts.child_by_union += by_union;
    if(!single && !by_union && traits.area(c) > 0) kept.push_back(c);
  }
  return false;
}

// The engine's step for f done both ways: with is_covered(), split() and is_covered_by_union() one
// by one, and with the model's refine(). The answers must be the same; `same(a, b)` compares two
// fragments field by field.
template <class Traits, class Same>
void expect_refine_agrees(const Traits& traits, const typename Traits::Fragment& f,
                          const std::vector<std::array<double, 3>>& near,
                          const std::vector<std::array<double, 3>>& around, double radius, Same same,
                          Refine_counts& counts, int trial)
{
  typedef typename Traits::Fragment Fragment;
  std::vector<Fragment> expected;
  const bool expected_covered = step_by_operations(traits, f, near, around, radius, expected, counts);
  counts.parent_covered += expected_covered;
  counts.child_kept += int(expected.size());

  std::vector<Fragment> got;
  const bool covered = traits.refine(f, near, around, radius, std::back_inserter(got));
  ASSERT_EQ(covered, expected_covered) << "trial " << trial;
  ASSERT_EQ(got.size(), expected.size()) << "trial " << trial;
  for(std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], expected[i])) << "trial " << trial;
}

// every branch of the step was taken often
inline void expect_every_branch_taken(const Refine_counts& counts)
{
  EXPECT_GT(counts.parent_covered, 200);
  EXPECT_GT(counts.child_by_single, 1000);
  EXPECT_GT(counts.child_by_union, 300);
  EXPECT_GT(counts.child_kept, 1000);
}

#endif // CGAL_POISSON_DISK_SAMPLING_3_TEST_FRAGMENT_CHECKS_H
