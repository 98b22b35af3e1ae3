// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_PREFETCH_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_PREFETCH_H

// keeps a function out of its callers, so that their common path stays small enough to be inlined
#if defined(__GNUC__) || defined(__clang__)
#  define CGAL_PDS_NOINLINE __attribute__((noinline))
#else
#  define CGAL_PDS_NOINLINE
#endif

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

/// Asks the processor to bring the cache line of `p` in, without waiting for it; a hint only (no
/// effect on the results, nothing on compilers without the builtin).
inline void prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
  // GCC's interprocedural analysis counts a prefetch as no effect: it takes a function that only
  // prefetches (`Neighbor_buckets::prefetch_points`, `Active_fragment_pool::prefetch`) for one
  // without effects, and at -O2 deletes the calls to it. An empty volatile assembly statement is an
  // effect it keeps, with the calls.
  __asm__ volatile("" : : "r"(p));
#else
  (void)p;
#endif
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_PREFETCH_H
