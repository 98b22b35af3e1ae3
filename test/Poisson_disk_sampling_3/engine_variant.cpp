// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A second translation unit of test_engine, compiled without CGAL_LINKED_WITH_TBB and with
// CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES (see test/Poisson_disk_sampling_3/CMakeLists.txt): the
// engine's layout differs from the one test_engine.cpp sees, and each unit must run its own.

#ifdef CGAL_LINKED_WITH_TBB
#error "engine_variant.cpp is compiled without CGAL_LINKED_WITH_TBB"
#endif
#ifndef CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES
#error "engine_variant.cpp is compiled with CGAL_POISSON_DISK_SAMPLING_3_STAGE_TIMES"
#endif

#include <CGAL/Poisson_disk_sampling_3/internal/Dart_throwing_engine.h>

#include "square_traits.h"

namespace pds_test {

Variant_run run_in_variant_unit(std::uint64_t seed)
{
  const Square_traits square;
  CGAL::Poisson_disk_sampling_3::internal::Dart_throwing_engine<Square_traits> engine(square, 0.05, seed, 10000);
  Variant_run result;
  const auto statistics = engine.run(Point_collector{&result.points});
  for(double seconds : statistics.stage_seconds) result.stage_seconds += seconds;
  return result;
}

} // namespace pds_test
