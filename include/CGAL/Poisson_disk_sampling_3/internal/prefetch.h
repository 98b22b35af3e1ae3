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

/// Asks the processor to bring the cache line of `p` in, without waiting for it, with the builtin's
/// `locality` (3: every level of cache; 2: the second level and beyond, x86's prefetcht1); a hint
/// only (no effect on the results, nothing on compilers without the builtin).
template <int locality>
inline void prefetch_with_locality(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p, 0, locality);
  // GCC's interprocedural analysis counts a prefetch as no effect: it takes a function that only
  // prefetches (`Neighbor_buckets::prefetch_points`, `Active_fragment_pool::prefetch`) for one
  // without effects, and at -O2 deletes the calls to it. An empty volatile assembly statement is an
  // effect it keeps, with the calls.
  __asm__ volatile("" : : "r"(p));
#else
  (void)p;
#endif
}

/// into every level of cache
inline void prefetch(const void* p) { prefetch_with_locality<3>(p); }

/// into the second-level cache, not the first: for data asked for long before it is read, which in
/// the first level would evict what is read before it
inline void prefetch_to_second_level(const void* p) { prefetch_with_locality<2>(p); }

/// Asks for every cache line of the object at `p`. An object of up to 64 bytes can cross the end of
/// a line (24-byte bucket headers, in an array, do at two places in eight): the lines
/// of its first and last bytes are all of its lines. One of up to 128 bytes (a triangle's face
/// record) can span three: the line 64 bytes after its first byte is the third.
template <class T>
inline void prefetch_object(const T* p)
{
  static_assert(sizeof(T) <= 128, "objects of more than 128 bytes can span more than three lines");
  const char* first = reinterpret_cast<const char*>(p);
  prefetch(first);
  if constexpr(sizeof(T) > 64) prefetch(first + 64);
  prefetch(first + (sizeof(T) - 1));
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_PREFETCH_H
