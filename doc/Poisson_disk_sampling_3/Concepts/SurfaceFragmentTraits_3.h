// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

/// \ingroup PkgPoissonDiskSampling3Concepts
/// \cgalConcept
///
/// What the dart-throwing engine needs from a surface: the five operations of the paper's Section 3
/// (fragments, their areas, a uniform point on a fragment, a coverage test, a split into children),
/// plus a reference point and a rounding-error bound. The engine computes in double precision with
/// points as `std::array<double, 3>`; exactness is obtained from conservative coverage tests and exact
/// distance decisions, see the design page.
///
/// The coverage tests receive the minimum distance D as `radius`: a sample covers the points within
/// D of it (D is twice the named parameter `radius` of the samplers, r = D / 2).
///
/// Requirements the engine relies on:
/// - the initial fragments tile the surface, and the children of a fragment tile it;
/// - `random_sample()` is uniform with respect to area on the fragment (or, for models that sample
///   with rejection, uniform once accepted, and accepted with positive probability: a model that
///   refuses every dart for more than 2^30 draws in a row, the pool's own rejections included, gets
///   `Invalid_input`);
/// - `is_covered()` is conservative: it returns `true` only if every point of the fragment is within
///   `radius` of `center`, rounding included; and conservative by no more than its rounding error,
///   or by a margin that shrinks with the fragment. A fixed margin m leaves the points whose nearest
///   sample is between D - m and D away unproven for good: no dart is accepted there (they are within
///   D of a sample) and no fragment there is ever proven covered, so the fragments there multiply
///   four times a level down to the depth floor, and the engine stops with `Point_limit_exceeded`
///   (the larger the sample, the more such places there are);
/// - splitting shrinks fragments, so that a fragment smaller than a ball's margin is covered by it;
/// - areas are numbers, not negative (a fragment of area 0 is skipped: it must hold no part of the
///   surface of positive area, or that part is never sampled), no fragment's area is above the
///   largest initial fragment's but by rounding (2^-20 of it), and `area()` gives the same double for
///   the same fragment on every call: the engine files fragments by area relative to the largest
///   initial one, and draws them in proportion to the bounds of the range they were filed in;
/// - `level()`, where defined, counts the splits as said below: the engine drops a fragment still not
///   covered at depth 40 (it counts it in `Sampling_statistics::dropped_fragments`, and throws
///   nothing), so a `split()` that does not shrink (one that writes the fragment itself), or a
///   `level()` far above the number of splits, leaves gaps, which only `is_maximal_on_surface()` finds;
/// - the operations are `const` and may be called at the same time from several threads: with
///   `concurrency(CGAL::Parallel_tag())`, `area()`, `random_sample()`, `point()`, `level()`,
///   `is_covered()`, `is_covered_by_union()`, `split()`, `refine()` and `prefetch()` run on TBB's
///   threads (a model with scratch space or caches must keep them per thread); an exception they throw
///   reaches the caller, the same one as in a sequential run (the first in the order of its darts),
///   after the other threads' calls of the batch have returned. An optional operation
///   is found only with the signature given below, `const` included: one written otherwise is taken
///   as absent, and not called;
/// - `position_error()` is a finite number, not negative.
///
/// What the engine checks: a model that gives a position error that is negative or not finite, an area
/// that is not a number, or negative (the certificate checks these too, on its roots), or above the
/// largest initial fragment's beyond rounding, or a fragment's area outside the power-of-two range it
/// had when the fragment was stored, or that refuses every dart for more than 2^30 draws in a row, or
/// whose sample lies more than 10^15 times the distance from the origin (where doubles are too coarse
/// for it: its position error understates the rounding of its points), gets `Invalid_input`. A model
/// whose fragments in wait outnumber 64 times its samples so far, its expected points (area / (pi r^2))
/// and its initial fragments, plus about a million, gets `Point_limit_exceeded`: coverage tests that
/// never succeed, or succeed only with a fixed margin, or samples far off the surface leave places that
/// are never covered, and the fragments there multiply. (The triangle model keeps fewer than twice the
/// expected points and the initial fragments on CGAL's meshes; without its cuts of long thin faces, 33
/// times on a cylinder of 128 needles.)
///
/// What it does not check: that the fragments tile the surface, that the samples are uniform and on
/// their fragments (a sample placed in a neighbouring fragment, or just past the surface's border,
/// passes), that a coverage test that says `true` is right, that `refine()` keeps every uncovered
/// point. A model wrong in these ways gives a set that may not be a Poisson-disk set or not maximal,
/// without an error. `is_poisson_disk_set()` checks the distances of any set of points;
/// `is_maximal_on_surface()` certifies maximality with the model's own `initial_fragments()`,
/// `split()`, `is_covered()` and `reference_point()`, none of the sampler's union tests or `refine()`:
/// it catches a wrong union test or `refine()`, not a wrong split or single-ball test.
///
/// \cgalHasModel `CGAL::Poisson_disk_sampling_3::Triangle_fragment_traits_3`
/// \cgalHasModel `CGAL::Poisson_disk_sampling_3::Sphere_fragment_traits_3`
class SurfaceFragmentTraits_3
{
public:
  /// \name Types
  /// @{

  /// a piece of the surface; copied often, so keep it small. Default constructible and copyable (the
  /// engine keeps fragments in arrays)
  typedef unspecified_type Fragment;

  /// what is produced for an accepted dart: its point and where it lies on the surface. Copyable and
  /// assignable (the engine holds the sample of each dart of a batch in a `std::optional`)
  typedef unspecified_type Sample;

  /// @}

  /// \name Operations
  /// @{

  /// writes the initial fragments (paper requirement 1)
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out) const;

  /// Optional. The initial fragments for the minimum distance `minimum_distance`, which must tile the
  /// same surface; the engine and the maximality certificate use it instead of the one above when a
  /// model defines it. A model whose root fragments would split badly at some scale cuts them first
  /// (`Triangle_fragment_traits_3` writes a long thin triangle as one block of rows per needle, at most
  /// two per face, whose rows, one to four times max(D, w) long with w its width, are made as darts
  /// halve the blocks; and clusters where the faces are much smaller than D; the engine counts the
  /// roots before storing any, and refuses them when they outnumber the faces by more than four times
  /// `maximum_number_of_points` plus six per face).
  template <class OutputIterator>
  OutputIterator initial_fragments(OutputIterator out, double minimum_distance) const;

  /// the area of a fragment, or an upper bound of it for models that sample with rejection; the engine
  /// chooses fragments in proportion to it (requirement 2). It must return the same double for the
  /// same fragment on every call, wherever the compiler inlines it: the engine files a fragment by
  /// its area when it is pushed, and refuses it (`Invalid_input`) when it is drawn with an area
  /// outside the power-of-two range it was filed in. (A difference of two products may round
  /// differently where the compiler fuses a product and a sum into one instruction, FMA.)
  double area(const Fragment& f) const;

  /// a point uniformly distributed on `f`, or an empty optional if a rejection step refuses the dart,
  /// in which case the engine puts `f` back unchanged (requirement 3). Models that need a projection to
  /// the surface do it here. `rng.uniform()` returns a double uniform in [0, 1).
  template <class RandomGenerator>
  std::optional<Sample> random_sample(const Fragment& f, RandomGenerator& rng) const;

  /// the point of a sample
  const std::array<double, 3>& point(const Sample& s) const;

  /// true only if every point of `f` is within `radius` of `center` (requirement 4); conservative, by
  /// no more than rounding or a margin that shrinks with `f` (see above). `radius` is the minimum
  /// distance D.
  bool is_covered(const Fragment& f, const std::array<double, 3>& center, double radius) const;

  /// Optional. True only if every point of `f` is within `radius` of some point of `centers` (a range
  /// of `std::array<double, 3>`), conservative as `is_covered()`. A fragment that straddles the
  /// boundary between two balls is covered by their union but by neither alone; without this test
  /// the engine splits it, and throws a dart at each piece, until single balls cover the pieces. The
  /// engine calls it, with the samples within 2 `radius` of the dart, on children that no single ball
  /// covers, and on a fragment at the depth floor that no single ball covers; a model that does not
  /// define it gets single-ball tests only. `Triangle_fragment_traits_3` and
  /// `Sphere_fragment_traits_3` define it. Its margin must be larger than `is_covered()`'s: the
  /// certificate (`is_maximal_on_surface()`) proves coverage with single balls, on pieces small enough
  /// that one ball holds each with its margin, which is possible only where the union test left at
  /// least that much room. Margins relative to the fragment, not to the origin, keep both small
  /// everywhere.
  template <class PointRange>
  bool is_covered_by_union(const Fragment& f, const PointRange& centers, double radius) const;

  /// Optional. The depth of `f`: the number of splits between `f` and the root fragment it comes
  /// from (0 for the fragments of `initial_fragments(out)`), or as many as it takes to shrink a whole
  /// root of `initial_fragments(out)` to the size of `f` (a piece of `initial_fragments(out, d)` may
  /// start deeper than 0). A child's depth is its parent's or one more, and grows along any chain of
  /// splits; the sphere model, which halves one range of a rectangle at a time, gives the larger of
  /// the numbers of halvings of its two ranges. The engine stops splitting at depth 40, the
  /// certificate at 48; without this operation both count the splits. A model whose fragments carry
  /// this number spares the engine from storing it beside each active fragment (for the triangle
  /// model, 32 bytes instead of 40; for the sphere model, 16 instead of 24).
  int level(const Fragment& f) const;

  /// Optional. Starts loading into the cache what `random_sample(f, rng)` will read, without waiting
  /// for it (for instance with `__builtin_prefetch`). The engine calls it for a whole batch of darts
  /// before it places any of them, so that their cache misses overlap. A hint: it must not change any
  /// result.
  void prefetch(const Fragment& f) const;

  /// Optional. The engine's step for a fragment that got a dart, done at once: returns `true` if one
  /// point of `near` covers `f` (as `is_covered()` decides it), and writes nothing. Otherwise writes
  /// fragments of positive area that lie in `f`, overlap nowhere, and hold every point of `f` that
  /// the balls of radius `radius` around `near` and `around` leave uncovered, with a depth (`level()`)
  /// no less than `f`'s. Without it the engine writes the children of `split()` of positive area that
  /// no point of `near` covers and that `is_covered_by_union(child, around, radius)` does not prove
  /// covered; a model defines it when it can share work between these operations
  /// (`Sphere_fragment_traits_3` gives their answers, and so the same samples, in less time), or when
  /// it can leave fewer fragments (`Triangle_fragment_traits_3` cuts off along a chord what one ball
  /// holds, instead of splitting, when that ball takes a quarter of `f` or more). `near` and `around`
  /// are `std::vector<std::array<double, 3>>`.
  template <class PointRange, class OutputIterator>
  bool refine(const Fragment& f, const PointRange& near, const PointRange& around, double radius,
              OutputIterator children) const;

  /// writes the children of `f`, which tile it (requirement 5)
  template <class OutputIterator>
  OutputIterator split(const Fragment& f, OutputIterator children) const;

  /// a point of the surface in `f`, used by the maximality certificate (`is_maximal_on_surface()`) to
  /// find the samples near `f`, and reported by it as the place of a gap
  std::array<double, 3> reference_point(const Fragment& f) const;

  /// a bound on the distance between a computed point of the surface and the exact one, a finite
  /// number, not negative; the engine and the certificate refuse minimum distances below 2^20 times
  /// this bound
  double position_error() const;

  /// @}
};
