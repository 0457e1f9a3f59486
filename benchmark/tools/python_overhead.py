#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""What the Python module adds to a run: vvm.tet_mesh and vvm.optimize against the same runs of
the vvm-mesh program (the same front end, options and seed), medians of several runs.

For each case it prints the median wall time of the Python call (arrays in, meshio.Mesh out,
the per-cell quality arrays included), the median time vvm-mesh reports for the same call of
the front end (its JSON's run_time_s: reading the surface, meshing, optimizing, measuring; not
reading or writing mesh files),
the median wall time of the whole vvm-mesh process (with reading and writing), and the ratio
Python / vvm-mesh's work. The meshes are checked to be the same (counts, smallest angle).

    PYTHONPATH=build/python python3 benchmark/tools/python_overhead.py --vvm-mesh build/tools/vvm-mesh
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import tempfile
import time

import meshio

import vvm


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--vvm-mesh", required=True)
    parser.add_argument("--tetgen", default="tetgen")
    parser.add_argument("--model", default=os.path.join(root, "data", "fandisk.off"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="vvm-python-overhead-")
    model = os.path.join(work, os.path.basename(args.model))
    shutil.copy(args.model, model)
    subprocess.run([args.tetgen, "-pq1.3/15", "-YgQ", model], check=True, capture_output=True)
    tetgen = model.rsplit(".", 1)[0] + ".1.mesh"

    def program(command):
        report = os.path.join(work, "report.json")
        start = time.perf_counter()
        subprocess.run([args.vvm_mesh, *command, "--threads", str(args.threads), "--json", report, "--quiet"],
                       check=True, stdout=subprocess.DEVNULL)
        wall = time.perf_counter() - start
        with open(report) as f:
            r = json.loads(f.readline())
        return r, r["run_time_s"], wall

    def python(call):
        start = time.perf_counter()
        mesh = call()
        return vvm.quality(mesh), time.perf_counter() - start

    # meshio reads MEDIT files of version 1 in single precision: vvm-mesh gets the same
    # coordinates from a .vtu written from meshio's mesh
    tetgen_mesh = meshio.read(tetgen)
    tetgen_vtu = os.path.join(work, "tetgen.vtu")
    vvm.write(tetgen_mesh, tetgen_vtu)
    cases = [
        ("tet_mesh fandisk (make_mesh_3 + GSM, 10k vertices)",
         lambda: vvm.tet_mesh(model, features_angle=60, threads=args.threads),
         ["tet", model, "-o", os.path.join(work, "out.mesh"), "--features-angle", "60"]),
        ("optimize TetGen's fandisk (meshio.read)",
         lambda: vvm.optimize(tetgen_mesh, threads=args.threads),
         ["optimize", tetgen_vtu, "-o", os.path.join(work, "opt.mesh")]),
    ]
    print(f"{'case':52s} {'python s':>9s} {'vvm-mesh call s':>16s} {'vvm-mesh wall s':>16s} {'ratio':>7s}  same mesh")
    for name, call, command in cases:
        py, work_time, wall = [], [], []
        for _ in range(args.runs):
            q, t = python(call)
            py.append(t)
            r, w, p = program(command)
            work_time.append(w)
            wall.append(p)
        same = (q["vertices"], q["tetrahedra"]) == (r["n_vertices"], r["n_tets"]) and \
            abs(q["min_dihedral"] - r["theta_min"]) < 1e-9
        mp, mw, mx = statistics.median(py), statistics.median(work_time), statistics.median(wall)
        print(f"{name:52s} {mp:9.2f} {mw:16.2f} {mx:16.2f} {mp / mw:7.3f}  {'yes' if same else 'NO'} "
              f"({q['vertices']} vertices, min angle {q['min_dihedral']:.2f})")
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
