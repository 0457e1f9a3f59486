#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the worst tets of a mesh sit against the input surface's feature curves.

usage: where_slivers_sit.py SURFACE.off MESH.mesh [--features-angle DEG] [--bounds 25,27,30]

SURFACE: the closed triangle surface the mesh was made from (OFF). MESH: a MEDIT tet mesh
(`compare_optimizers --out-dir`, `vvm-mesh tet -o X.mesh`). The feature curves are the surface
edges whose two facets turn by more than DEG (default 60, as `--features-angle`); their
corners are the vertices where other than two of them meet. For each bound, the tets whose
smallest dihedral angle is under it: how many have a vertex on a feature curve, how many are
within two mean edge lengths of a corner, and how many have 0 to 4 vertices on the boundary
(the mesh's Triangles).
"""
import argparse
import os
import sys
from collections import defaultdict

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from render_mesh import smallest_dihedral_angles  # noqa: E402


def read_off(path):
    words = open(path).read().split()
    if words[0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    i = 4
    points = np.array(words[i:i + 3 * nv], float).reshape(nv, 3)
    i += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[i])
        faces.append([int(x) for x in words[i + 1:i + 1 + k]])
        i += 1 + k
    return points, np.array(faces)


def read_medit(path):
    words = open(path).read().split()

    def block(name, width, kept):
        i = words.index(name)
        n = int(words[i + 1])
        return np.array(words[i + 2:i + 2 + width * n], float).reshape(n, width)[:, :kept]

    points = block("Vertices", 4, 3)
    triangles = block("Triangles", 4, 3).astype(int) - 1
    tets = block("Tetrahedra", 5, 4).astype(int) - 1
    return points, triangles, tets


def feature_curves(points, faces, angle):
    normals = np.cross(points[faces[:, 1]] - points[faces[:, 0]], points[faces[:, 2]] - points[faces[:, 0]])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    edge_faces = defaultdict(list)
    for f, (a, b, c) in enumerate(faces):
        for u, v in ((a, b), (b, c), (c, a)):
            edge_faces[(min(u, v), max(u, v))].append(f)
    edges = [e for e, fs in edge_faces.items()
             if len(fs) == 2 and np.degrees(np.arccos(np.clip(normals[fs[0]] @ normals[fs[1]], -1, 1))) > angle]
    degree = defaultdict(int)
    for u, v in edges:
        degree[u] += 1
        degree[v] += 1
    corners = np.array([points[u] for u, d in degree.items() if d != 2]).reshape(-1, 3)
    return np.array([points[u] for u, _ in edges]), np.array([points[v] for _, v in edges]), corners


def distance_to_segments(q, a, b):
    d = np.full(len(q), np.inf)
    ab = b - a
    length2 = (ab * ab).sum(1)
    for k in range(0, len(a), 1000):
        t = np.clip(((q[:, None, :] - a[None, k:k + 1000]) * ab[None, k:k + 1000]).sum(2) / length2[None, k:k + 1000], 0, 1)
        nearest = a[None, k:k + 1000] + t[..., None] * ab[None, k:k + 1000]
        d = np.minimum(d, np.linalg.norm(q[:, None, :] - nearest, axis=2).min(1))
    return d


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("surface")
    parser.add_argument("mesh")
    parser.add_argument("--features-angle", type=float, default=60)
    parser.add_argument("--bounds", default="25,27,30")
    args = parser.parse_args()

    surface_points, surface_faces = read_off(args.surface)
    points, triangles, tets = read_medit(args.mesh)
    a, b, corners = feature_curves(surface_points, surface_faces, args.features_angle)
    angles = smallest_dihedral_angles(points, tets)
    p = points[tets]
    edge = np.cbrt(np.abs(np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])))
                   * np.sqrt(2)).mean()  # the edge of a regular tet of the mean volume
    on_boundary = np.zeros(len(points), bool)
    on_boundary[triangles.ravel()] = True
    bounds = [float(x) for x in args.bounds.split(",")]
    involved = np.unique(tets[angles < max(bounds)])
    on_curve = np.zeros(len(points), bool)
    near_corner = np.zeros(len(points), bool)
    if len(a):
        scale = np.ptp(surface_points, axis=0).max()
        on_curve[involved] = distance_to_segments(points[involved], a, b) < 1e-7 * scale
    if len(corners):
        for v in involved:
            near_corner[v] = np.linalg.norm(corners - points[v], axis=1).min() < 2 * edge
    print(f"{len(a)} feature edges over {args.features_angle:g} degrees, {len(corners)} corners; "
          f"{len(tets)} tets, mean edge {edge:.4g}")
    print("under  tets  on_curve  near_corner  boundary_vertices_0/1/2/3/4")
    for bound in bounds:
        worst = tets[angles < bound]
        counts = on_boundary[worst].sum(1)
        print(f"{bound:5g} {len(worst):5d} {int(on_curve[worst].any(1).sum()):9d} {int(near_corner[worst].any(1).sum()):12d}  "
              + "/".join(str(int((counts == k).sum())) for k in range(5)))


if __name__ == "__main__":
    main()
