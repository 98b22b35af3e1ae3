// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COVERAGE_CERTIFIER_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COVERAGE_CERTIFIER_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Point_hash_grid.h>
#include <CGAL/Poisson_disk_sampling_3/internal/exact_distance.h>
#include <CGAL/Poisson_disk_sampling_3/internal/optional_operations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

struct Certificate
{
  bool maximal = true;
  double uncovered_area = 0;   // area of the fragments not proven covered (an upper bound)
  bool has_witness = false;    // a point within the position error of a surface point farther than D
                               // from every sample
  std::array<double, 3> witness{{0, 0, 0}};
  std::size_t samples_tested = 0; // samples within reach of a piece that a decision tested
};

/// Proves that every point of the surface lies within distance D of some sample, or measures where
/// it fails. Each root fragment is split with the model's own `split` until one sample's ball covers
/// each piece (the model's conservative `is_covered`).
///
/// The work and the memory are bounded. The work counts one for each piece decided and a sixteenth for
/// each sample within reach of it that the decision tests (so that a cluster of many samples, which
/// each decision near it scans, counts for what it costs). A piece whose reference point is farther
/// than D from every sample, by more than the point's rounding (decided exactly), is a proven gap: it
/// is refined only down to `leaf_area` for the area estimate; once a gap is proven and a quarter of
/// `budget` more work spent, so is every piece not proven covered. Pieces still undecided below
/// D^2 / 2^24 are deferred: in a maximal set they are the few that sit where two ball boundaries cross
/// close to a piece's edge, and they are refined breadth-first down to `max_depth`, until a gap is proven or
/// a budget is spent. Around a real gap, many pieces straddle its boundary; refining all of them
/// depth-first would take time exponential in the depth. At most `budget / 4` pieces wait at a time, in
/// one queue; beyond that a piece counts as not proven covered, as do the pieces left when the budget
/// is spent, and those that the first phase would split after `budget` of work and 256 per sample and
/// per root: the answer is then `false` with no witness, undecided.
template <class Traits>
Certificate certify_coverage(const Traits& traits, const Point_hash_grid& samples, double d,
                             int max_depth = 48, std::size_t budget = 10000000)
{
  typedef typename Traits::Fragment Fragment;
  struct Item
  {
    Fragment fragment;
    int depth;
  };

  // the roots are made as they are certified, one at a time: a long face's pieces are not stored
  const double surface_area = total_area(traits);
  check_surface_area(surface_area, "certify");
  const double leaf_area = (std::max)(d * d / 64, surface_area * 0x1.0p-20);
  const double defer_area = d * d * 0x1.0p-24;

  Certificate result;
  Point_hash_grid::Nearby_queries near_samples(samples);
  std::vector<Fragment> children;
  // A reference point is computed: it lies within the model's position error of the surface point
  // it stands for, not on it. A gap is proven where no sample is within d plus twice that error (the
  // error bounds each coordinate; the next double above the sum makes up for its rounding), so that
  // the surface point itself is farther than d from every sample; nearer, no gap is proven there,
  // and a piece that no single ball covers is split. (Without the margin, the centre of a piece,
  // rounded off a triangle's edge near its corner, the one point of the triangle at distance d from
  // the samples, was the witness of a set that was maximal.)
  const double d_gap = std::nextafter(d + 2 * traits.position_error(), std::numeric_limits<double>::infinity());
  const double d2_near = d_gap * d_gap * (1 + 1e-9);

  // a reference point whose nearest sample is this far, in double precision, is at d to about a
  // millionth (see `record` below)
  const double d2_at_d = d * d * (1 - 0x1.0p-19);

  enum Verdict { COVERED, GAP_LEAF, SPLIT };
  // decides one piece; records a proven gap
  // the work (see above): pieces decided, and samples tested, 16 to a decision; the work when a gap was
  // first proven
  std::size_t decisions = 0, tests = 0, work_at_gap = 0;
  const auto work = [&] { return decisions + tests / 16; };
  bool ref_at_d = false; // the last piece decided has its reference point at d from the samples
  auto decide = [&](const Item& item) {
    ++decisions;
    const std::array<double, 3> ref = traits.reference_point(item.fragment);
    bool ref_near = false; // a sample within d_gap of the reference point: no gap proven there
    bool covered = false;
    ref_at_d = true;
    // the samples in reach, until one's ball holds the piece
    near_samples.for_each_near(ref.data(), d_gap, [&](Point_hash_grid::Index, const double* q) {
      const double dx = q[0] - ref[0], dy = q[1] - ref[1], dz = q[2] - ref[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      if(d2 > d2_near) return false;
      ++tests;
      if(traits.is_covered(item.fragment, std::array<double, 3>{{q[0], q[1], q[2]}}, d)) return covered = true;
      if(d2 < d2_at_d) ref_at_d = false;
      if(!ref_near && compare_distance_exact(ref.data(), q, d_gap) != CGAL::LARGER) ref_near = true;
      return false;
    });
    if(covered) return COVERED;
    if(ref_near) return SPLIT;
    result.maximal = false;
    if(!result.has_witness) {
      result.has_witness = true;
      work_at_gap = work();
      result.witness = ref;
    }
    return traits.area(item.fragment) <= leaf_area ? GAP_LEAF : SPLIT;
  };
  // passes the children of a piece to put
  auto split = [&](const Item& item, auto&& put) {
    children.clear();
    traits.split(item.fragment, std::back_inserter(children));
    for(const Fragment& c : children) put(Item{c, level_or(traits, c, item.depth + 1)});
  };

  std::vector<Item> stack;
  std::deque<Item> waiting; // the deferred pieces, in the order they are refined
  auto not_proven = [&](const Item& item) {
    result.maximal = false;
    result.uncovered_area += traits.area(item.fragment);
  };
  // a piece to refine later: in `waiting` while it holds fewer than budget / 4, else not proven covered
  const std::size_t max_waiting = budget / 4;
  auto defer = [&](const Item& item) {
    if(waiting.size() < max_waiting) waiting.push_back(item);
    else not_proven(item);
  };
  // Regions that the pieces fill. For the pieces of area up to d^2 / 64, the count decided at each
  // depth, and how many of them were left undecided (split, or deferred and decided again later)
  // with their reference point at d from the samples, to about a millionth: pieces long and thin,
  // which no ball holds whatever the samples (blocks of rows of a long face), are left undecided
  // wherever they are, but have their middle at d only by chance. Where the places that no ball
  // holds with the margin of is_covered() shrink to points or curves as the pieces shrink, as around
  // any place a ball holds with some margin, at most about half to 0.7 of a depth's pieces stay
  // undecided. Where they stay undecided 19 in 20 at four depths in a row, with 1,024 pieces or more
  // at each, they fill a region where the distance to the samples is within rounding of d (a set
  // maximal with no margin: one sample on a sphere at d = 2R, whose distance peaks smoothly at the
  // antipode; a sample at the centre of a sphere of radius d, off the surface): refining it only
  // multiplies its pieces, and from then on an undecided piece of that size counts as not proven
  // covered whole (see design.md, "Exactness").
  const double fill_area = d * d / 64;
  std::size_t decided_at[64] = {}, undecided_at[64] = {};
  bool filling = false;
  auto record = [&](const Item& item, double area, bool undecided) {
    if(filling || !(area <= fill_area)) return;
    const int k = (std::min)((std::max)(item.depth, 0), 63);
    ++decided_at[k];
    undecided_at[k] += undecided && ref_at_d;
    if(k < 3) return;
    for(int j = k - 3; j <= k; ++j)
      if(decided_at[j] < 1024 || undecided_at[j] * 20 < decided_at[j] * 19) return;
    filling = true;
  };
  // The first phase's work: pieces that no ball holds are split down to the deferral size, and a model
  // whose is_covered() never succeeds (a wrong test) would have the whole surface split so, about 2^24
  // area / d^2 decisions (270 million on a unit square at d = 0.25, four times as many each time d
  // halves). Past `budget` of work and 256 per sample and per root, such pieces count as not proven
  // covered, without being split. (Maximal sets took 3 to 44 decisions per sample and root, counted on
  // CGAL's meshes at 1,000 to 100,000 points, and on a needle 2^14 d long, the most.)
  std::size_t roots = 0;
  const auto over_budget = [&] { return work() > budget + 256 * (samples.size() + roots); };
  auto certify_root = [&](const Fragment& root) {
    ++roots;
    if(!(checked_area(traits, root) > 0)) return;
    stack.push_back(Item{root, level_or(traits, root, 0)});
    while(!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      const Verdict v = decide(item);
      const double area = traits.area(item.fragment);
      if(v == COVERED) {
        record(item, area, false);
        continue;
      }
      if(v == GAP_LEAF) result.uncovered_area += area;
      // Once a gap is proven the answer is known, and what is left is the area estimate. After a
      // quarter of the budget of work spent on it, a piece of leaf size that no single ball holds
      // counts whole instead of being refined across the balls' boundaries down to the deferral size,
      // which costs time and memory in proportion to the boundaries' length over that size.
      else if(result.has_witness && area <= leaf_area && work() - work_at_gap > budget / 4)
        result.uncovered_area += area;
      else if(filling && area <= fill_area) not_proven(item);
      else if(area <= defer_area || item.depth >= max_depth) defer(item);
      else if(over_budget()) not_proven(item);
      else {
        record(item, area, true);
        split(item, [&](const Item& c) { stack.push_back(c); });
      }
    }
  };
  root_fragments(traits, d, Calling_output(&certify_root));

  // The deferred pieces, breadth-first (one depth after the other: a piece's children go behind the
  // pieces waiting), until a gap is proven, the budget is spent or the pieces are found to fill a
  // region (above): what is left then counts as not proven covered.
  const std::size_t work_at_start = work();
  while(!waiting.empty() && !result.has_witness && work() - work_at_start < budget && !filling) {
    bool deeper = false; // a piece above the depth floor waits for the next round
    for(std::size_t round = waiting.size(); round > 0 && !filling; --round) {
      const Item item = waiting.front();
      waiting.pop_front();
      const Verdict v = decide(item);
      if(v == COVERED) {
        record(item, traits.area(item.fragment), false);
      } else if(v == GAP_LEAF || item.depth >= max_depth || result.has_witness) {
        defer(item);
      } else {
        record(item, traits.area(item.fragment), true);
        split(item, [&](const Item& c) {
          deeper = deeper || (c.depth < max_depth && waiting.size() < max_waiting);
          defer(c);
        });
      }
    }
    if(!deeper && !filling) break;
  }
  for(const Item& item : waiting) not_proven(item);
  result.samples_tested = tests;
  return result;
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_COVERAGE_CERTIFIER_H
