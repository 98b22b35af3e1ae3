// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H

#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The active fragments in logarithmic area bins (paper Section 4, Figure 1): bin i holds the
/// fragments with area in (Amax/2^(i+1), Amax/2^i]. A draw picks a fragment with probability exactly
/// proportional to its area, in constant expected time when few bins are used.
///
/// The bin is chosen in proportion to count_i * Amax/2^i, an upper bound of its area that is exact in
/// floating point and never drifts, then a fragment of the bin uniformly, accepted with probability
/// area/(Amax/2^i) >= 1/2; a refused draw is simply not a dart. See doc/Poisson_disk_sampling_3/design.md.
///
/// Draws come in batches: between `begin_batch()` and `end_batch()` the pool stands still, so that the
/// draws are independent and identically distributed (the engine relies on it), and their memory
/// accesses can overlap. `take()` marks a drawn fragment for removal at `end_batch()`; `push()` may be
/// called at any time.
template <class Item>
class Active_fragment_pool
{
public:
  /// where a drawn fragment is, valid until `end_batch()`
  struct Handle
  {
    std::uint32_t bin;
    std::uint32_t index;
  };

  explicit Active_fragment_pool(double max_area) : max_area_(max_area)
  {
    CGAL_precondition(max_area > 0 && std::isfinite(max_area));
  }

  bool empty() const { return size_ == 0; }
  /// fragments in the pool, counting the ones taken in the current batch
  std::size_t size() const { return size_; }

  void push(const Item& item, double area)
  {
    CGAL_precondition(area > 0);
    const std::size_t b = bin_of(area);
    while(b >= bins_.size()) {
      bounds_.push_back(bin_bound(bins_.size()));
      bins_.emplace_back();
    }
    if(bins_[b].size() >= std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("Active_fragment_pool: too many fragments in one bin");
    bins_[b].push_back(Entry{item, area});
    if(size_ == 0 || b < first_) first_ = b;
    if(size_ == 0 || b > last_) last_ = b;
    ++size_;
  }

  /// fixes the bins' weights for the draws of a batch; precondition: !empty()
  void begin_batch()
  {
    CGAL_precondition(!empty() && taken_.empty());
    while(bins_[first_].empty()) ++first_;
    while(bins_[last_].empty()) --last_;
    // weights relative to bin `first_`: count * 2^-(b - first_), exact for each bin
    cumulative_.clear();
    double total = 0;
    for(std::size_t b = first_; b <= last_; ++b) {
      total += weight(b);
      cumulative_.push_back(total);
    }
  }

  /// a fragment drawn in proportion to its bin's envelope, uniformly in the bin; pass it to `accepts`
  /// with a uniform number of [0, 1) to complete the draw
  Handle draw(Random& rng) const
  {
    const double u = rng.uniform() * cumulative_.back();
    std::size_t i = std::size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin());
    if(i == cumulative_.size()) --i; // rounding at the end
    std::size_t b = first_ + i;
    while(bins_[b].empty()) --b;     // an empty bin adds nothing to the sum, but rounding may land on it
    return Handle{std::uint32_t(b), std::uint32_t(rng.uniform_index(bins_[b].size()))};
  }

  /// the rejection step of a draw: true with probability area / bin bound
  bool accepts(const Handle& h, double u) const
  {
    const double a = bins_[h.bin][h.index].area;
    CGAL_precondition(a > 0); // not taken yet: draws come before takes in a batch
    return u * bounds_[h.bin] < a;
  }

  void prefetch(const Handle& h) const { internal::prefetch(&bins_[h.bin][h.index]); }

  const Item& item(const Handle& h) const { return bins_[h.bin][h.index].item; }

  /// marks the fragment for removal at `end_batch()`; false if it was already marked in this batch
  bool take(const Handle& h)
  {
    double& a = bins_[h.bin][h.index].area;
    if(!(a > 0)) return false;
    a = -a;
    taken_.push_back(h);
    return true;
  }

  /// removes the fragments taken since `begin_batch()`
  void end_batch()
  {
    // by bin, then from the highest index down: moving a bin's last entry into a freed place never
    // moves one that is still to be removed
    std::sort(taken_.begin(), taken_.end(), [](const Handle& a, const Handle& b) {
      return a.bin != b.bin ? a.bin < b.bin : a.index > b.index;
    });
    for(const Handle& h : taken_) {
      std::vector<Entry>& bin = bins_[h.bin];
      bin[h.index] = bin.back();
      bin.pop_back();
    }
    size_ -= taken_.size();
    taken_.clear();
  }

private:
  struct Entry
  {
    Item item;
    double area;
  };

  // count_b * 2^-(b - first_); a table spares the ldexp call for the bins in use
  double weight(std::size_t b) const
  {
    static const std::array<double, 64> power_of_half = [] {
      std::array<double, 64> t{};
      for(std::size_t i = 0; i < t.size(); ++i) t[i] = std::ldexp(1., -int(i));
      return t;
    }();
    const std::size_t k = b - first_;
    const double count = double(bins_[b].size());
    return k < power_of_half.size() ? count * power_of_half[k] : std::ldexp(count, -int(k));
  }

  double bin_bound(std::size_t b) const { return std::ldexp(max_area_, -int(b)); }

  std::size_t bin_of(double area) const
  {
    if(area >= max_area_) return 0;
    int b = std::ilogb(max_area_ / area);
    if(b < 0) b = 0;
    while(b > 0 && area > bin_bound(std::size_t(b))) --b;
    while(area <= bin_bound(std::size_t(b) + 1)) ++b;
    return std::size_t(b);
  }

  double max_area_;
  std::vector<std::vector<Entry>> bins_;
  std::vector<double> bounds_; // bin_bound(b), so that a pick calls no ldexp
  std::size_t first_ = 0, last_ = 0; // the non-empty bins are among [first_, last_]
  std::size_t size_ = 0;
  std::vector<double> cumulative_;   // running sums of the weights of bins first_.. in this batch
  std::vector<Handle> taken_;
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H
