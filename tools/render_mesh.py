#!/usr/bin/python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Renders volume meshes to a PNG: the mesh cut by a plane, so that the inside shows.

usage: render_mesh.py MESH [MESH ...] -o OUT.png [--cut x|y|z] [--at F] [--view AZIMUTH,ELEVATION]
                      [--title T ...] [--histogram] [--width INCHES] [--dpi N]

Each MESH (any file meshio reads: .mesh, .msh, .vtu) is one panel, side by side. The cells whose
centroid lies beyond the plane normal to the `--cut` axis at fraction `--at` of the bounding box
(default x at 0.5) are dropped, and the faces of the cells kept that no other kept cell shares
are drawn: the mesh's boundary on one side and the cut through its volume. A tetrahedral mesh is
coloured by each cell's smallest dihedral angle (red under 10 degrees, green at 50 and over,
with a colour bar); a mesh with hexahedra, prisms or pyramids by cell type (hexahedra grey-blue,
prisms orange, pyramids yellow, tetrahedra red). With `--histogram`, each panel of tetrahedra
has below it the histogram of all its tetrahedra's smallest dihedral angles (5-degree bins, counts
on a log scale). Uses numpy, meshio and matplotlib (Debian's
python3-matplotlib); no display needed.
"""

import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

# the faces of each cell type, as meshio numbers its vertices (VTK order)
CELL_FACES = {
    "tetra": [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)],
    "hexahedron": [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
    "wedge": [(0, 2, 1), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
    "pyramid": [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
}
TYPE_COLOURS = {"hexahedron": (0.62, 0.72, 0.85), "wedge": (0.96, 0.62, 0.25),
                "pyramid": (0.98, 0.88, 0.35), "tetra": (0.88, 0.30, 0.28)}
ANGLE_RANGE = (10.0, 50.0)  # degrees: the colour map's ends


def fail(message):
    print("render_mesh: error: " + message, file=sys.stderr)
    sys.exit(2)


def smallest_dihedral_angles(points, tets):
    """the smallest dihedral angle of each tetrahedron, in degrees"""
    p = points[tets]
    faces = [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)]
    normals = []  # of the face opposite each vertex, pointing away from it
    for i, (a, b, c) in enumerate(faces):
        n = np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a])
        n *= -np.sign(np.einsum("ij,ij->i", n, p[:, i] - p[:, a]))[:, None]
        normals.append(n / np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None])
    angles = [180.0 - np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", normals[i], normals[j]), -1, 1)))
              for i in range(4) for j in range(i + 1, 4)]
    return np.min(angles, axis=0)


def cut_faces(mesh, axis, at):
    """the faces of the kept cells that no other kept cell shares: (polygons, colour per face,
    whether the colours are angles)"""
    blocks = [b for b in mesh.cells if b.type in CELL_FACES and len(b.data)]
    if not blocks:
        fail("no tetrahedron, hexahedron, prism or pyramid in the mesh")
    points = np.asarray(mesh.points, dtype=float)[:, :3]
    if not np.isfinite(points).all():
        fail("the mesh has a non-finite coordinate")
    low, high = points.min(axis=0), points.max(axis=0)
    plane = low[axis] + at * (high[axis] - low[axis])
    all_tets = all(b.type == "tetra" for b in blocks)
    faces = {}  # sorted vertices -> (polygon, value, count)
    for b in blocks:
        cells = np.asarray(b.data)
        kept = points[cells].mean(axis=1)[:, axis] <= plane
        values = smallest_dihedral_angles(points, cells) if b.type == "tetra" else None
        for k in np.nonzero(kept)[0]:
            for f in CELL_FACES[b.type]:
                polygon = tuple(int(cells[k][i]) for i in f)
                key = tuple(sorted(polygon))
                if key in faces:
                    faces[key][2] += 1
                else:
                    faces[key] = [polygon, values[k] if all_tets else b.type, 1]
    shown = [(polygon, value) for polygon, value, count in faces.values() if count == 1]
    if not shown:
        fail("the cut keeps no cell: choose another --at")
    return points, shown, all_tets


def shade(colours, polygons, points, light):
    """Lambert shading of each face, so that the shape reads without edges"""
    normals = []
    for polygon in polygons:
        q = points[list(polygon)]
        n = np.cross(q[1] - q[0], q[2] - q[0])
        normals.append(n / max(np.linalg.norm(n), 1e-300))
    brightness = 0.55 + 0.45 * np.abs(np.asarray(normals) @ light)
    return np.clip(colours[:, :3] * brightness[:, None], 0, 1)


def draw(ax, path, axis, at, view, title):
    try:
        mesh = meshio.read(path)
    except Exception as e:  # meshio raises many kinds for a bad file
        fail(f"cannot read {path}: {e}")
    points, shown, by_angle = cut_faces(mesh, axis, at)
    tets = [np.asarray(b.data) for b in mesh.cells if b.type == "tetra" and len(b.data)]
    angles_of_all = np.concatenate([smallest_dihedral_angles(points, t) for t in tets]) if tets else None
    polygons = [polygon for polygon, _ in shown]
    if by_angle:
        angles = np.array([value for _, value in shown])
        colours = plt.get_cmap("RdYlGn")((np.clip(angles, *ANGLE_RANGE) - ANGLE_RANGE[0]) /
                                         (ANGLE_RANGE[1] - ANGLE_RANGE[0]))
    else:
        colours = np.array([TYPE_COLOURS[value] + (1.0,) for _, value in shown])
    azimuth, elevation = np.radians(view[0]), np.radians(view[1])
    light = np.array([np.cos(elevation) * np.cos(azimuth), np.cos(elevation) * np.sin(azimuth), np.sin(elevation)])
    collection = Poly3DCollection([points[list(p)] for p in polygons], facecolors=shade(colours, polygons, points, light),
                                  edgecolors=(0.1, 0.1, 0.1, 0.35), linewidths=0.05)
    ax.add_collection3d(collection)
    low, high = points.min(axis=0), points.max(axis=0)
    centre, half = (low + high) / 2, (high - low).max() / 2
    for set_limits, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_limits(c - half, c + half)
    ax.set_box_aspect((1, 1, 1), zoom=1.3)
    ax.view_init(elev=view[1], azim=view[0])
    ax.set_axis_off()
    if title:
        ax.set_title(title, fontsize=10)
    return by_angle, angles_of_all


def draw_histogram(ax, angles):
    """the smallest dihedral angles of all tetrahedra, 5-degree bins coloured as the cells"""
    edges = np.arange(0, 95, 5.0)
    counts, _ = np.histogram(angles, bins=edges)
    centres = (edges[:-1] + edges[1:]) / 2
    colours = plt.get_cmap("RdYlGn")((np.clip(centres, *ANGLE_RANGE) - ANGLE_RANGE[0]) / (ANGLE_RANGE[1] - ANGLE_RANGE[0]))
    ax.bar(centres, np.maximum(counts, 0.5), width=4.5, color=colours, edgecolor=(0.2, 0.2, 0.2), linewidth=0.3)
    ax.set_yscale("log")
    ax.set_ylim(0.8, None)
    ax.set_xlim(0, 90)
    ax.set_xlabel("smallest dihedral angle (degrees)", fontsize=8)
    ax.set_ylabel("tetrahedra", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.set_title(f"smallest {angles.min():.1f}°, {int((angles < 30).sum())} under 30°", fontsize=8)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--cut", choices="xyz", default="x")
    parser.add_argument("--at", type=float, default=0.5)
    parser.add_argument("--view", default="30,25")
    parser.add_argument("--title", action="append", default=[], help="a panel's title, once per mesh")
    parser.add_argument("--histogram", action="store_true", help="the smallest angles' histogram under each tet panel")
    parser.add_argument("--width", type=float, default=4.0, help="inches per panel")
    parser.add_argument("--dpi", type=int, default=110)
    args = parser.parse_args()
    if not (0 < args.at <= 1):
        fail("--at must be in (0, 1]")
    try:
        view = [float(v) for v in args.view.split(",")]
    except ValueError:
        view = []
    if len(view) != 2 or not np.isfinite(view).all():
        fail("--view must be AZIMUTH,ELEVATION in degrees")
    if not args.output.endswith(".png"):
        fail("the output must be a .png file")
    titles = args.title or [""] * len(args.meshes)
    if len(titles) != len(args.meshes):
        fail(f"{len(titles)} titles for {len(args.meshes)} meshes")
    n = len(args.meshes)
    rows = 2 if args.histogram else 1
    figure = plt.figure(figsize=(args.width * n, args.width * (1.45 if args.histogram else 1)))
    grid = figure.add_gridspec(rows, n, height_ratios=[1, 0.45][:rows], hspace=0.25)
    by_angle = by_type = False
    for i, (path, title) in enumerate(zip(args.meshes, titles)):
        ax = figure.add_subplot(grid[0, i], projection="3d")
        coloured_by_angle, angles = draw(ax, path, "xyz".index(args.cut), args.at, view, title)
        if coloured_by_angle:
            by_angle = True
        else:
            by_type = True
        if args.histogram and angles is not None:
            draw_histogram(figure.add_subplot(grid[1, i]), angles)
    if by_type:
        names = {"hexahedron": "hexahedra", "wedge": "prisms", "pyramid": "pyramids", "tetra": "tetrahedra"}
        figure.legend(handles=[Patch(color=TYPE_COLOURS[t], label=names[t]) for t in names], loc="lower center",
                      ncol=4, frameon=False, fontsize=9)
    if by_angle:
        bar = figure.colorbar(plt.cm.ScalarMappable(norm=plt.Normalize(*ANGLE_RANGE), cmap="RdYlGn"),
                              ax=[a for a in figure.axes if a.name == "3d"], shrink=0.6, pad=0.02)
        bar.set_label("smallest dihedral angle (degrees)")
    figure.savefig(args.output, dpi=args.dpi, bbox_inches="tight")
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
