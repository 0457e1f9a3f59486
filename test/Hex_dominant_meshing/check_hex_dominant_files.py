#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs test_hex_dominant_io and reads the mixed meshes it writes back.

usage: check_hex_dominant_files.py <test_hex_dominant_io executable> <output directory>

mixed.vtu, mixed.msh and mixed.mesh are read with meshio: per cell type the counts and
subdomains must be those of expected.txt, every cell positively oriented, the total
volume the expected one. Then Gmsh (required, tools/install_dependencies.sh installs
it) checks mixed.msh for negative volumes, re-saves it, and the re-saved file must
read back the same.
"""

import json
import os
import shutil
import subprocess
import sys

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from vvm_checks import Check_failed, require  # noqa: E402

# The cells cut into tetrahedra in meshio's vertex order, the same cuts as in
# test_hex_dominant_io.cpp. meshio's order is VTK's except for the linear wedge, which
# is Gmsh's (the triangle 0 1 2 turns around a normal pointing to 3 4 5): its VTU
# reader swaps VTK's wedge vertices 1<->2 and 4<->5, its Gmsh and MEDIT readers keep
# the vertices as they are. So a cell of any of the three files has positive pieces
# iff the file holds it positively oriented in its own format.
SUB_TETRAHEDRA = {
    "tetra": [(0, 1, 2, 3)],
    "hexahedron": [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)],
    "wedge": [(0, 1, 2, 3), (1, 2, 3, 4), (2, 3, 4, 5)],
    "pyramid": [(0, 1, 2, 4), (0, 2, 3, 4)],
}
VTK_TYPES = {"tetra": 10, "hexahedron": 12, "wedge": 13, "pyramid": 14}


def cell_volumes(points, cell_type, connectivity):
    """the volume of each cell; every piece of every cell must be positive"""
    volumes = np.zeros(len(connectivity))
    for t in SUB_TETRAHEDRA[cell_type]:
        a, b, c, d = (points[connectivity[:, i]] for i in t)
        pieces = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6
        require((pieces > 0).all(), f"{cell_type}: a piece {t} of a cell has the volume {pieces.min()}")
        volumes += pieces
    return volumes


def check_mesh(name, mesh, expected, subdomain_key):
    """counts, subdomains, orientation and volume of `mesh`; its subdomains are the cell data `subdomain_key`"""
    require(len(mesh.points) == expected["points"], f"{name}: {len(mesh.points)} points, not {expected['points']}")
    # meshio reads MEDIT's MeshVersionFormatted 1 as float32; the test's points are exact there
    points = np.asarray(mesh.points, dtype=np.float64)
    subdomains = {t: [] for t in expected["cells"]}
    total_volume = 0.0
    for k, block in enumerate(mesh.cells):
        require(block.type in subdomains, f"{name}: unexpected cells of type {block.type}")
        subdomains[block.type] += [int(s) for s in mesh.cell_data[subdomain_key][k]]
        volumes = cell_volumes(points, block.type, block.data)
        total_volume += volumes.sum()
        if "volume" in mesh.cell_data:  # the cell fields of the VTU
            require(np.allclose(mesh.cell_data["volume"][k], volumes, rtol=1e-12, atol=0),
                    f"{name}: the field 'volume' is not the volume of the {block.type} cells")
            require((mesh.cell_data["cell_type"][k] == VTK_TYPES[block.type]).all(),
                    f"{name}: the field 'cell_type' of the {block.type} cells is not {VTK_TYPES[block.type]}")
    for t, expected_subdomains in expected["subdomains"].items():
        require(sorted(subdomains[t]) == sorted(expected_subdomains),
                f"{name}: the {t} cells are in the subdomains {sorted(subdomains[t])}, not {sorted(expected_subdomains)}")
    require(abs(total_volume - expected["volume"]) <= 1e-12 * abs(expected["volume"]),
            f"{name}: total volume {total_volume!r}, not {expected['volume']!r}")
    counts = {t: len(s) for t, s in subdomains.items()}
    require(counts == expected["cells"], f"{name}: {counts} cells, not {expected['cells']}")
    print(f"{name}: {counts}, volume {total_volume!r}, all cells positive: ok")


def run_gmsh(gmsh, args):
    result = subprocess.run([gmsh] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    require(result.returncode == 0, f"gmsh {' '.join(args)} exited with {result.returncode}:\n{result.stdout}")
    return result.stdout


def check_gmsh(gmsh, out_dir, expected):
    msh = os.path.join(out_dir, "mixed.msh")
    # Gmsh's own orientation test (MElement::getVolumeSign per element type)
    output = run_gmsh(gmsh, [msh, "-check"])
    require("Checking mesh coherence" in output and "negative volume" not in output,
            f"gmsh -check on mixed.msh:\n{output}")
    # ... which does see an inverted element: the prism 1 2 3 4 5 6 as 1 3 2 4 6 5
    with open(msh) as f:
        lines = f.read().split("\n")
    start = lines.index("$Elements")
    for i in range(start, len(lines)):
        fields = lines[i].split()
        if len(fields) == 4 and fields[0] == "3" and fields[2] == "6":  # a prism block
            element = lines[i + 1].split()
            lines[i + 1] = " ".join([element[0]] + [element[1 + j] for j in (0, 2, 1, 3, 5, 4)])
            break
    inverted = os.path.join(out_dir, "inverted.msh")
    with open(inverted, "w") as f:
        f.write("\n".join(lines))
    require("negative volume" in run_gmsh(gmsh, [inverted, "-check"]), "gmsh -check misses an inverted prism")

    resaved = os.path.join(out_dir, "resaved.msh")
    if os.path.exists(resaved):
        os.remove(resaved)
    run_gmsh(gmsh, [msh, "-save", "-format", "msh41", "-o", resaved])
    require(os.path.exists(resaved), "gmsh did not write resaved.msh")
    check_mesh("resaved.msh (Gmsh)", meshio.read(resaved), expected, "gmsh:geometrical")
    print("gmsh -check: no negative volume, and it finds an inverted prism: ok")


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    executable, out_dir = sys.argv[1:]
    os.makedirs(out_dir, exist_ok=True)
    for f in ("mixed.vtu", "mixed.msh", "mixed.mesh", "expected.txt", "resaved.msh", "inverted.msh"):
        if os.path.exists(os.path.join(out_dir, f)):
            os.remove(os.path.join(out_dir, f))
    result = subprocess.run([executable, out_dir])
    if result.returncode != 0:
        print(f"FAIL: {executable} exited with {result.returncode}", file=sys.stderr)
        return 1
    gmsh = shutil.which("gmsh")
    if gmsh is None:
        print("FAIL: the gmsh executable is not on PATH (tools/install_dependencies.sh installs it)",
              file=sys.stderr)
        return 1
    try:
        with open(os.path.join(out_dir, "expected.txt")) as f:
            expected = json.load(f)
        vtu = meshio.read(os.path.join(out_dir, "mixed.vtu"))
        for field in expected["cell_fields"] + ["cell_type", "subdomain"]:
            require(field in vtu.cell_data, f"mixed.vtu: no cell data '{field}'")
        check_mesh("mixed.vtu", vtu, expected, "subdomain")
        msh = meshio.read(os.path.join(out_dir, "mixed.msh"))
        check_mesh("mixed.msh", msh, expected, "gmsh:geometrical")
        check_mesh("mixed.msh, physical tags", msh, expected, "gmsh:physical")
        check_mesh("mixed.mesh", meshio.read(os.path.join(out_dir, "mixed.mesh")), expected, "medit:ref")
        check_gmsh(gmsh, out_dir, expected)
    except Check_failed as e:
        print(f"FAIL: {e}", file=sys.stderr)
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
