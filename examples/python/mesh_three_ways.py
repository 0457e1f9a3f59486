#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Meshes a bundled model three ways with the vvm module: make_mesh_3 with CGAL's own
optimizers (perturb+exude), make_mesh_3 with GSM, and an FCC lattice aligned with the
boundary's cross field. Writes the three meshes (.vtu, with the quality arrays, for
ParaView) and plots the histograms of the tetrahedra's smallest dihedral angles.

    PYTHONPATH=build/python python3 examples/python/mesh_three_ways.py data/fandisk.off --out fandisk
"""

import argparse
import os

import numpy as np

import vvm


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("surface", nargs="?", default=os.path.join(here, "..", "..", "data", "fandisk.off"),
                        help="a closed surface (default: the bundled fandisk)")
    parser.add_argument("--vertices", type=int, default=5000, help="vertices of each mesh (default 5000)")
    parser.add_argument("--out", default="mesh_three_ways", help="the folder to write to")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    def progress(event):
        if event.fraction == 1:
            print(f"  {event.stage}: {event.detail} ({event.elapsed:.1f} s)")

    meshes = {}
    for method in ("perturb+exude", "gsm", "fcc"):
        print(f"{method}:")
        mesh = vvm.tet_mesh(args.surface, method=method, vertices=args.vertices, progress=progress)
        q = vvm.quality(mesh)
        print(f"  {q['vertices']} vertices, {q['tetrahedra']} tets, smallest dihedral angle "
              f"{q['min_dihedral']:.2f}, {q['tets_under'][30]} tets under 30 degrees")
        path = os.path.join(args.out, method.replace("+", "_") + ".vtu")
        vvm.write(mesh, path)
        meshes[method] = mesh

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(7, 4))
    bins = np.arange(0, 75, 2.5)
    for method, mesh in meshes.items():
        angles = np.concatenate([a for b, a in zip(mesh.cells, mesh.cell_data["min_dihedral_angle"])
                                 if b.type == "tetra"])
        axes.hist(angles, bins=bins, histtype="step", linewidth=1.5,
                  label=f"{method} (min {angles.min():.1f}\N{DEGREE SIGN})")
    axes.set_yscale("log")
    axes.set_xlabel("smallest dihedral angle of a tetrahedron (degrees)")
    axes.set_ylabel("tetrahedra")
    axes.set_title(os.path.basename(args.surface))
    axes.legend()
    figure.tight_layout()
    plot = os.path.join(args.out, "dihedral_histograms.png")
    figure.savefig(plot, dpi=120)
    print("wrote", ", ".join(sorted(os.listdir(args.out))), "in", os.path.abspath(args.out))


if __name__ == "__main__":
    main()
