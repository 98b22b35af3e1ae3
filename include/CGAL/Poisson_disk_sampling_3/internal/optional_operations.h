// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_OPTIONAL_OPERATIONS_H
#define CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_OPTIONAL_OPERATIONS_H

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Poisson_disk_sampling_3 {
namespace internal {

// Which optional operations of SurfaceFragmentTraits_3 a model offers, and the engine's and the
// certificate's way to call the ones both use.

/// whether a model offers the optional `is_covered_by_union(fragment, centers, radius)`
template <class Traits, class = void>
struct Has_union_coverage : std::false_type {};
template <class Traits>
struct Has_union_coverage<Traits, std::void_t<decltype(std::declval<const Traits&>().is_covered_by_union(
                                      std::declval<const typename Traits::Fragment&>(),
                                      std::declval<const std::vector<std::array<double, 3>>&>(), 1.))>>
    : std::true_type {};

/// whether a model offers the optional `prefetch(fragment)`
template <class Traits, class = void>
struct Has_prefetch : std::false_type {};
template <class Traits>
struct Has_prefetch<Traits, std::void_t<decltype(std::declval<const Traits&>().prefetch(
                                std::declval<const typename Traits::Fragment&>()))>> : std::true_type {};

/// whether a model offers the optional `level(fragment)`
template <class Traits, class = void>
struct Has_level : std::false_type {};
template <class Traits>
struct Has_level<Traits, std::void_t<decltype(std::declval<const Traits&>().level(
                             std::declval<const typename Traits::Fragment&>()))>> : std::true_type {};

/// whether a model offers the optional `refine(fragment, near, around, radius, children)`
template <class Traits, class = void>
struct Has_refine : std::false_type {};
template <class Traits>
struct Has_refine<Traits, std::void_t<decltype(std::declval<const Traits&>().refine(
                              std::declval<const typename Traits::Fragment&>(),
                              std::declval<const std::vector<std::array<double, 3>>&>(),
                              std::declval<const std::vector<std::array<double, 3>>&>(), 1.,
                              std::declval<std::back_insert_iterator<std::vector<typename Traits::Fragment>>>()))>>
    : std::true_type {};

/// whether a model offers the optional `initial_fragments(out, minimum_distance)`
template <class Traits, class = void>
struct Has_roots_for_distance : std::false_type {};
template <class Traits>
struct Has_roots_for_distance<
    Traits, std::void_t<decltype(std::declval<const Traits&>().initial_fragments(
                std::declval<std::back_insert_iterator<std::vector<typename Traits::Fragment>>>(), 1.))>>
    : std::true_type {};

/// the root fragments for minimum distance d: the model's own for d if it has them
template <class Traits, class OutputIterator>
OutputIterator root_fragments(const Traits& traits, double d, OutputIterator out)
{
  if constexpr(Has_roots_for_distance<Traits>::value) return traits.initial_fragments(out, d);
  else {
    (void)d;
    return traits.initial_fragments(out);
  }
}

/// the depth of a fragment: the model's level if it has one (the pieces of a face may start deeper
/// than the face, and a split may leave the level as it was), else `otherwise`
template <class Traits>
int level_or(const Traits& traits, const typename Traits::Fragment& f, int otherwise)
{
  if constexpr(Has_level<Traits>::value) return int(traits.level(f));
  else {
    (void)traits;
    (void)f;
    return otherwise;
  }
}

/// an output iterator that only counts what is written to it
struct Counting_output
{
  typedef std::output_iterator_tag iterator_category;
  typedef void value_type;
  typedef void difference_type;
  typedef void pointer;
  typedef void reference;
  std::size_t* count;
  Counting_output& operator*() { return *this; }
  Counting_output& operator++() { return *this; }
  Counting_output& operator++(int) { return *this; }
  template <class T>
  Counting_output& operator=(const T&)
  {
    ++*count;
    return *this;
  }
};

/// an output iterator that calls `*f` on what is written to it. It holds a pointer, not the function
/// object, so that it is copy-assignable as output iterators must be (a model may write
/// `out = std::copy(first, last, out);`), also for a lambda, which is not.
template <class F>
struct Calling_output
{
  typedef std::output_iterator_tag iterator_category;
  typedef void value_type;
  typedef void difference_type;
  typedef void pointer;
  typedef void reference;
  explicit Calling_output(F* f) : f(f) {}
  F* f;
  Calling_output& operator*() { return *this; }
  Calling_output& operator++() { return *this; }
  Calling_output& operator++(int) { return *this; }
  template <class T>
  Calling_output& operator=(const T& x)
  {
    (*f)(x);
    return *this;
  }
};

/// a fragment's area, refused (`Invalid_input`) unless it is a number and not negative: a model's error,
/// which the engine and the certificate report alike
template <class Traits>
double checked_area(const Traits& traits, const typename Traits::Fragment& f)
{
  const double a = traits.area(f);
  if(!(a >= 0))
    throw Invalid_input("the surface model gave a fragment of area " + number_text(a) +
                        "; areas must be numbers, not negative");
  return a;
}

/// the area of a model's surface: the sum of the areas of `initial_fragments(out)`, summed as the
/// roots are made, not stored (32 bytes a face: 106 MB on a mesh of 3.3 million faces)
template <class Traits>
double total_area(const Traits& traits)
{
  double a = 0;
  auto add = [&](const typename Traits::Fragment& f) { a += checked_area(traits, f); };
  traits.initial_fragments(Calling_output(&add));
  return a;
}

} // namespace internal
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_INTERNAL_OPTIONAL_OPERATIONS_H
