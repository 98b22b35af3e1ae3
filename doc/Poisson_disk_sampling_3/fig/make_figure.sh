#!/usr/bin/env bash
# Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Makes lion_samples.png for the user manual: 20,000 samples on CGAL's lion.off (seed 0), rendered as
# shaded points. Run from anywhere after building the examples (bash .ci/demo builds them).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$here/../../.."
build="${BUILD_DIR:-$root/build}"
"$build/examples/Poisson_disk_sampling_3/sample_mesh" --count 20000 --seed 0 -o "$build/lion_samples.ply"
/usr/bin/python3 "$here/render_samples.py" "$build/lion_samples.ply" "$here/lion_samples.png" 20 10
