// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POISSON_DISK_SAMPLING_3_H
#define CGAL_POISSON_DISK_SAMPLING_3_H

/// \file Poisson_disk_sampling_3.h
/// Convenience header: includes every public header of the package.

#include <CGAL/Poisson_disk_sampling_3/exceptions.h>
#include <CGAL/Poisson_disk_sampling_3/parameters.h>
#include <CGAL/Poisson_disk_sampling_3/sample_surface.h>
#include <CGAL/Poisson_disk_sampling_3/Triangle_fragment_traits_3.h>
#include <CGAL/Poisson_disk_sampling_3/Sphere_fragment_traits_3.h>
#include <CGAL/Poisson_disk_sampling_3/sample_triangle_mesh.h>
#include <CGAL/Poisson_disk_sampling_3/sample_sphere.h>
#include <CGAL/Poisson_disk_sampling_3/is_poisson_disk_set.h>
#include <CGAL/Poisson_disk_sampling_3/is_maximal.h>

#endif // CGAL_POISSON_DISK_SAMPLING_3_H
