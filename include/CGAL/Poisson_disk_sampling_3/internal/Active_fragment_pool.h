// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/internal/Random.h>
#include <CGAL/Poisson_disk_sampling_3/internal/power_of_half.h>
#include <CGAL/Poisson_disk_sampling_3/internal/prefetch.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
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
///
/// Memory: a bin stores its fragments in chunks of 256, so that it never holds more than one chunk
/// of free room and never copies more than its first 128 fragments to grow (a doubling vector holds
/// up to twice its contents, three times while it moves). Its first chunk starts at 16 fragments and
/// doubles up to 256; the later chunks that bins empty wait for other bins in a list of at most four,
/// so that the free room of the bins in use (about 20 at a time) weighs little even at a few thousand
/// points. The areas are not stored: the caller passes the fragment's area to `accepts()` (the engine
/// computes it from the model, which the dart reads anyway).
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

  explicit Active_fragment_pool(double max_area)
    : max_area_(max_area), max_exponent_(std::ilogb(max_area)),
      max_mantissa_(std::ldexp(max_area, -max_exponent_)), normal_bins_(max_exponent_ + 1023)
  {
    CGAL_precondition(max_area > 0 && std::isfinite(max_area));
    // so that end_batch(), which moves emptied chunks there, allocates nothing
    spares_.chunks.reserve(Spare_chunks::max_spares);
  }

  bool empty() const { return size_ == 0; }
  /// fragments in the pool, counting the ones taken in the current batch
  std::size_t size() const { return size_; }
  /// the fragments the pool's memory holds room for, its spare chunks included
  std::size_t capacity() const
  {
    std::size_t c = spares_.chunks.size() * Chunked_array::chunk_size();
    for(const Chunked_array& bin : bins_) c += bin.capacity();
    return c;
  }

  void push(const Item& item, double area)
  {
    CGAL_precondition(area > 0);
    const std::size_t b = bin_of(area);
    while(b >= bins_.size()) {
      bounds_.push_back(bin_bound(bins_.size()));
      bins_.emplace_back();
    }
    // a handle holds an index within its bin in 32 bits; the engine's bound on fragments in wait
    // (64 times the samples, the expected points and the roots, plus 2^20) keeps a bin below this up to
    // about 30 million expected points; beyond, only a model that breaks the concept comes near it
    if(bins_[b].size() >= std::numeric_limits<std::uint32_t>::max())
      throw Point_limit_exceeded("2^32 - 1 active fragments of about the same area, the most a bin holds; "
                                 "use a larger distance or fewer points");
    bins_[b].push_back(item, spares_);
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

  /// whether `area` falls in the bin of `h`, as the area a fragment was pushed with does: two
  /// comparisons where the bin's bounds are normal doubles (their halves are exact)
  bool is_filed_with(const Handle& h, double area) const
  {
    if(int(h.bin) + 1 < normal_bins_) {
      const double bound = bounds_[h.bin];
      return area > 0.5 * bound && (h.bin == 0 || area <= bound);
    }
    return area > 0 && bin_of(area) == h.bin;
  }

  /// the bounds (lower, upper] of the areas in the bin of `h`; infinity above bin 0, where the areas
  /// above the largest one given to the constructor are filed
  std::pair<double, double> bin_range(const Handle& h) const
  {
    const double upper = h.bin == 0 ? std::numeric_limits<double>::infinity() : bin_bound(h.bin);
    return {bin_bound(std::size_t(h.bin) + 1), upper};
  }

  /// the rejection step of a draw: true with probability area / bin bound, for `u` uniform in [0, 1);
  /// `area` must be the area the fragment was pushed with
  bool accepts(const Handle& h, double area, double u) const
  {
    CGAL_precondition(is_filed_with(h, area));
    if(int(h.bin) < normal_bins_) return u * bounds_[h.bin] < area;
    // a bound below the normal doubles is rounded: compare both sides scaled up by the same power of
    // two, exactly (the bin is at least max_exponent_ + 1023, so the area is scaled up)
    return u * max_mantissa_ < std::ldexp(area, int(h.bin) - max_exponent_);
  }

  void prefetch(const Handle& h) const { internal::prefetch_object(&bins_[h.bin][h.index]); }

  const Item& item(const Handle& h) const { return bins_[h.bin][h.index]; }

  /// marks the fragment for removal at `end_batch()`; false if it was already marked in this batch
  bool take(const Handle& h)
  {
    if(4 * (taken_.size() + 1) > taken_set_.size()) {
      taken_set_.assign(taken_set_.empty() ? 64 : 2 * taken_set_.size(), 0);
      for(const Handle& t : taken_) insert_key(key_of(t));
    }
    if(!insert_key(key_of(h))) return false;
    taken_.push_back(h);
    return true;
  }

  /// removes the fragments taken since `begin_batch()`
  void end_batch()
  {
    // Each taken entry is replaced by the bin's last entry that is not taken; taken entries at the
    // end are dropped first, and a handle beyond the end was one of them. No sort: the taken set
    // answers whether an entry is taken, and an entry refilled with a live one leaves the set.
    for(const Handle& h : taken_) {
      Chunked_array& bin = bins_[h.bin];
      while(!bin.empty() && is_taken(Handle{h.bin, std::uint32_t(bin.size() - 1)})) bin.pop_back(spares_);
      if(h.index >= bin.size()) continue;
      bin[h.index] = bin.back();
      bin.pop_back(spares_);
      untake(h);
    }
    std::fill(taken_set_.begin(), taken_set_.end(), std::uint64_t(0));
    size_ -= taken_.size();
    taken_.clear();
  }

private:
  // Full chunks that bins have emptied, for any bin to take: a bin at a chunk boundary, pushed and
  // popped in turn, moves one chunk between itself and this list instead of allocating it each time.
  // At most `max_spares` of them are kept.
  struct Spare_chunks
  {
    static constexpr std::size_t max_spares = 4;
    std::vector<std::unique_ptr<Item[]>> chunks;
  };

  // A growable array in chunks of 256: indexing reads the chunk's address (the chunk tables are
  // small and stay in cache), then the item. The first chunk starts at 16 items and is copied to
  // twice its size until it holds 256, so that a bin of few fragments (the pool has one per
  // octave of area, about 20 in use at a time) does not hold a whole chunk.
  class Chunked_array
  {
  public:
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    std::size_t capacity() const { return capacity_; }
    static constexpr std::size_t chunk_size() { return chunk; }
    Item& operator[](std::size_t i) { return chunks_[i >> shift][i & (chunk - 1)]; }
    const Item& operator[](std::size_t i) const { return chunks_[i >> shift][i & (chunk - 1)]; }
    Item& back() { return (*this)[size_ - 1]; }
    void push_back(const Item& x, Spare_chunks& spares)
    {
      if(size_ == capacity_) grow(spares);
      (*this)[size_++] = x;
    }
    void pop_back(Spare_chunks& spares)
    {
      --size_;
      if(size_ == 0 && capacity_ > first_chunk) {
        // an empty bin keeps no chunk of the sizes above the first: most bins empty once, as the
        // fragments of their octave of area are used up
        chunks_.clear();
        capacity_ = 0;
      } else if(chunks_.size() > 1 && size_ == capacity_ - chunk) {
        // the last chunk is empty: it goes to the spares, or is freed
        if(spares.chunks.size() < Spare_chunks::max_spares) spares.chunks.push_back(std::move(chunks_.back()));
        chunks_.pop_back();
        capacity_ -= chunk;
      }
    }

  private:
    void grow(Spare_chunks& spares)
    {
      if(capacity_ < chunk) {
        // the first chunk, copied to twice its size
        const std::size_t c = capacity_ == 0 ? first_chunk : 2 * capacity_;
        std::unique_ptr<Item[]> larger(new Item[c]);
        if(capacity_ > 0) std::copy(chunks_[0].get(), chunks_[0].get() + size_, larger.get());
        if(chunks_.empty()) chunks_.emplace_back();
        chunks_[0] = std::move(larger);
        capacity_ = c;
        return;
      }
      if(!spares.chunks.empty()) {
        chunks_.push_back(std::move(spares.chunks.back()));
        spares.chunks.pop_back();
      } else {
        chunks_.emplace_back(new Item[chunk]);
      }
      capacity_ += chunk;
    }

    static constexpr std::size_t shift = 8, chunk = std::size_t(1) << shift, first_chunk = 16;
    std::vector<std::unique_ptr<Item[]>> chunks_;
    std::size_t size_ = 0, capacity_ = 0;
  };

  // never 0, and bit 63 is never set (there are far fewer than 2^31 bins)
  static std::uint64_t key_of(const Handle& h) { return (std::uint64_t(h.bin) << 32 | h.index) + 1; }

  // the set of the keys of the taken handles, by open addressing in taken_set_ (0: empty slot)
  std::size_t slot_of(std::uint64_t key) const
  {
    const std::size_t mask = taken_set_.size() - 1;
    std::size_t k = std::size_t((key * 0x9E3779B97F4A7C15ull) >> 20) & mask;
    while(taken_set_[k] != 0 && taken_set_[k] != key) k = (k + 1) & mask;
    return k;
  }
  bool is_taken(const Handle& h) const
  {
    const std::uint64_t key = key_of(h);
    return taken_set_[slot_of(key)] == key;
  }
  // leaves a mark that matches no key (bit 63 is never set in one) and keeps later keys reachable
  void untake(const Handle& h)
  {
    const std::uint64_t key = key_of(h);
    taken_set_[slot_of(key)] = key | std::uint64_t(1) << 63;
  }
  // false if the key was there already
  bool insert_key(std::uint64_t key)
  {
    const std::size_t k = slot_of(key);
    if(taken_set_[k] == key) return false;
    taken_set_[k] = key;
    return true;
  }

  // count_b * 2^-(b - first_), exact (far below first_, ldexp keeps a subnormal that 2^-k alone would lose)
  double weight(std::size_t b) const
  {
    const std::size_t k = b - first_;
    const double count = double(bins_[b].size());
    return k < 511 ? count * power_of_half(k) : std::ldexp(count, -int(k));
  }

  double bin_bound(std::size_t b) const { return std::ldexp(max_area_, -int(b)); }

  // the b with max_area_ 2^-(b+1) < area <= max_area_ 2^-b. The difference of the exponents is b or
  // b + 1, for any positive area (the quotient of the areas, which it replaces, overflowed to infinity
  // below max_area_ / 2^1024, and the loops then ran 2^31 times). Where the bounds are normal doubles
  // they are exact and come from the table; below, the area is scaled up instead, exactly.
  std::size_t bin_of(double area) const
  {
    if(area >= max_area_) return 0;
    int b = max_exponent_ - binary_exponent(area); // (std::ilogb, without a call of the library)
    if(b < 0) b = 0;
    if(b + 1 < normal_bins_) {
      while(b > 0 && area > bound(std::size_t(b))) --b;
      while(area <= bound(std::size_t(b) + 1)) ++b;
    } else {
      while(b > 0 && std::ldexp(area, b) > max_area_) --b;
      while(std::ldexp(area, b + 1) <= max_area_) ++b;
    }
    return std::size_t(b);
  }
  // bin_bound(b), from the table when the bin exists
  double bound(std::size_t b) const { return b < bounds_.size() ? bounds_[b] : bin_bound(b); }

  double max_area_;
  int max_exponent_;    // std::ilogb(max_area_)
  double max_mantissa_; // max_area_ 2^-max_exponent_, in [1, 2) even where max_area_ is subnormal
  int normal_bins_; // bins 0 to normal_bins_ - 1 have bounds max_area_ 2^-b that are normal doubles
  std::vector<Chunked_array> bins_;
  Spare_chunks spares_;
  std::vector<double> bounds_; // bin_bound(b), so that a pick calls no ldexp
  std::size_t first_ = 0, last_ = 0; // the non-empty bins are among [first_, last_]
  std::size_t size_ = 0;
  std::vector<double> cumulative_;   // running sums of the weights of bins first_.. in this batch
  std::vector<Handle> taken_;
  std::vector<std::uint64_t> taken_set_; // a power of two in size, at most a quarter full
};

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_ACTIVE_FRAGMENT_POOL_H
