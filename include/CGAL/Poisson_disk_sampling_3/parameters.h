// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_PARAMETERS_H
#define CGAL_POISSON_DISK_SAMPLING_3_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Poisson_disk_sampling_3 {

/// \cond SKIP_IN_MANUAL
namespace internal_np {
enum radius_t { radius };
enum minimum_distance_t { minimum_distance };
enum number_of_points_t { number_of_points };
enum maximum_number_of_points_t { maximum_number_of_points };
enum statistics_t { statistics };
enum concurrency_t { concurrency };
} // namespace internal_np
/// \endcond

/// \ingroup PkgPoissonDiskSampling3Ref
/// Named parameters of the package. CGAL 5.5's list of named parameters is closed, so ours live in
/// this namespace: a chain that uses one of them starts here, e.g.
/// `PDS::parameters::minimum_distance(0.1).random_seed(7)`. The chain offers the package's own
/// parameters and the CGAL ones the package reads (`random_seed`, `vertex_point_map`, `geom_traits`),
/// in any order. CGAL's own `CGAL::parameters::...` chains are accepted where no package parameter
/// is needed (`is_maximal()`); the samplers need a size, which only a chain started here can carry.
namespace parameters {

/// \ingroup PkgPoissonDiskSampling3Ref
/// A chain of named parameters; a `CGAL::Named_function_parameters` with the package's parameters
/// added as member functions.
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
class Named_parameters : public CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_parameters;

public:
  /// \cond SKIP_IN_MANUAL
  Named_parameters(const T& v) : Cgal_parameters(v) {}
  Named_parameters(const T& v, const Base& b) : Cgal_parameters(v, b) {}

#define CGAL_PDS_CHAIN(NAME, TAG)                                                  \
  template <class K>                                                               \
  Named_parameters<K, TAG, Cgal_parameters> NAME(const K& k) const                 \
  {                                                                                \
    return Named_parameters<K, TAG, Cgal_parameters>(k, *this);                    \
  }
  CGAL_PDS_CHAIN(radius, internal_np::radius_t)
  CGAL_PDS_CHAIN(minimum_distance, internal_np::minimum_distance_t)
  CGAL_PDS_CHAIN(number_of_points, internal_np::number_of_points_t)
  CGAL_PDS_CHAIN(maximum_number_of_points, internal_np::maximum_number_of_points_t)
  CGAL_PDS_CHAIN(statistics, internal_np::statistics_t)
  CGAL_PDS_CHAIN(concurrency, internal_np::concurrency_t)
  CGAL_PDS_CHAIN(random_seed, CGAL::internal_np::random_seed_t)
  CGAL_PDS_CHAIN(vertex_point_map, CGAL::internal_np::vertex_point_t)
  CGAL_PDS_CHAIN(geom_traits, CGAL::internal_np::geom_traits_t)
#undef CGAL_PDS_CHAIN
  /// \endcond
};

/// \cond SKIP_IN_MANUAL
#define CGAL_PDS_START(NAME, TAG)                                                  \
  template <class K>                                                               \
  Named_parameters<K, TAG> NAME(const K& k)                                        \
  {                                                                                \
    return Named_parameters<K, TAG>(k);                                            \
  }
CGAL_PDS_START(radius, internal_np::radius_t)
CGAL_PDS_START(minimum_distance, internal_np::minimum_distance_t)
CGAL_PDS_START(number_of_points, internal_np::number_of_points_t)
CGAL_PDS_START(maximum_number_of_points, internal_np::maximum_number_of_points_t)
CGAL_PDS_START(statistics, internal_np::statistics_t)
CGAL_PDS_START(concurrency, internal_np::concurrency_t)
CGAL_PDS_START(random_seed, CGAL::internal_np::random_seed_t)
CGAL_PDS_START(vertex_point_map, CGAL::internal_np::vertex_point_t)
CGAL_PDS_START(geom_traits, CGAL::internal_np::geom_traits_t)
#undef CGAL_PDS_START
/// \endcond

using CGAL::parameters::default_values;

} // namespace parameters
} // namespace Poisson_disk_sampling_3
} // namespace CGAL

#endif // CGAL_POISSON_DISK_SAMPLING_3_PARAMETERS_H
