#!/usr/bin/python3
# Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Renders the binary PLY written by sample_mesh (x y z nx ny nz face_index) as shaded discs.

usage: render_samples.py SAMPLES.ply OUT.png [azimuth_degrees] [elevation_degrees]
Needs Debian's python3-matplotlib and python3-numpy.
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_ply(path):
    with open(path, "rb") as f:
        count = 0
        while True:
            line = f.readline().decode("ascii").strip()
            if line.startswith("element vertex"):
                count = int(line.split()[-1])
            if line == "end_header":
                break
        record = np.dtype([("p", "<f8", 3), ("n", "<f8", 3), ("face", "<u4")])
        data = np.frombuffer(f.read(count * record.itemsize), dtype=record)
    return data["p"], data["n"]


def main():
    points, normals = read_ply(sys.argv[1])
    azimuth = np.radians(float(sys.argv[3]) if len(sys.argv) > 3 else 30.0)
    elevation = np.radians(float(sys.argv[4]) if len(sys.argv) > 4 else 15.0)
    # an orthographic camera: right, up and towards-the-viewer axes
    view = np.array([np.cos(elevation) * np.sin(azimuth), np.sin(elevation), np.cos(elevation) * np.cos(azimuth)])
    right = np.cross([0.0, 1.0, 0.0], view)
    right /= np.linalg.norm(right)
    up = np.cross(view, right)
    x, y, depth = points @ right, points @ up, points @ view
    facing = normals @ view
    keep = facing > 0  # back-facing samples are hidden
    light = np.clip(normals[keep] @ (view + up * 0.5) / np.linalg.norm(view + up * 0.5), 0.15, 1.0)
    order = np.argsort(depth[keep])
    fig, ax = plt.subplots(figsize=(8, 8), dpi=100)
    ax.scatter(x[keep][order], y[keep][order], s=2.0, c=light[order], cmap="copper", vmin=0, vmax=1, linewidths=0)
    ax.set_aspect("equal")
    ax.axis("off")
    fig.savefig(sys.argv[2], bbox_inches="tight", pad_inches=0.05, facecolor="white")


if __name__ == "__main__":
    main()
