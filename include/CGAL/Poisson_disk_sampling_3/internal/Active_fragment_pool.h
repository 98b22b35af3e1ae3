// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H

#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>

#include <CGAL/assertions.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// The active fragments in logarithmic area bins (paper Section 4, Figure 1): bin i holds the
/// fragments with area in (Amax/2^(i+1), Amax/2^i]. `pick_and_remove` returns a fragment chosen with
/// probability exactly proportional to its area, in constant expected time when few bins are used.
///
/// The bin is chosen in proportion to count_i * Amax/2^i, an upper bound of its area that is exact in
/// floating point and never drifts, then a fragment of the bin uniformly, accepted with probability
/// area/(Amax/2^i) >= 1/2; on rejection the choice starts over. See doc/Poisson_disk_sampling_3/design.md.
template <class Item>
class Active_fragment_pool
{
public:
  explicit Active_fragment_pool(double max_area) : max_area_(max_area)
  {
    CGAL_precondition(max_area > 0 && std::isfinite(max_area));
  }

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  void push(const Item& item, double area)
  {
    CGAL_precondition(area > 0);
    const std::size_t b = bin_of(area);
    while(b >= bins_.size()) {
      bounds_.push_back(bin_bound(bins_.size()));
      bins_.emplace_back();
    }
    bins_[b].push_back(Entry{item, area});
    if(size_ == 0 || b < first_) first_ = b;
    if(size_ == 0 || b > last_) last_ = b;
    ++size_;
  }

  /// precondition: !empty()
  Item pick_and_remove(Random& rng)
  {
    CGAL_precondition(!empty());
    while(bins_[first_].empty()) ++first_;
    while(bins_[last_].empty()) --last_;
    for(;;) {
      // weights relative to bin `first_`: count * 2^-(b - first_), exact for each bin
      double total = 0;
      for(std::size_t b = first_; b <= last_; ++b) total += weight(b);
      double u = rng.uniform() * total;
      std::size_t b = first_;
      for(; b < last_; ++b) {
        const double w = weight(b);
        if(u < w) break;
        u -= w;
      }
      while(bins_[b].empty()) --b; // rounding at the end of the walk
      std::vector<Entry>& bin = bins_[b];
      const std::size_t k = std::size_t(rng.uniform_index(bin.size()));
      if(rng.uniform() * bounds_[b] >= bin[k].area) continue;
      const Item item = bin[k].item;
      bin[k] = bin.back();
      bin.pop_back();
      --size_;
      return item;
    }
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
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H
