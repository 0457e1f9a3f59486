#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs vvm-mesh on small bundled inputs and checks what it writes.

usage: check_vvm_mesh.py --vvm-mesh EXE --data DIR --work DIR [--tetgen EXE] [--gmsh EXE] CHECK
       check_vvm_mesh.py --registered CHECK...   (fails if a check is not in the list)

Each CHECK is one CTest entry (vvm_mesh.CHECK). Meshes are read back with meshio
(counts, labels, orientation of every tetrahedron) and re-saved by Gmsh; the
optimize checks start from meshes written by Debian's TetGen and Gmsh.
"""

import argparse
import json
import os
import shutil
import struct
import subprocess
import sys

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from vvm_checks import require, run_main  # noqa: E402

ARGS = None


def fail(message):
    require(False, message)


def work(name):
    return os.path.join(ARGS.work, name)


def data(name):
    return os.path.join(ARGS.data, name)


def run(args, expect=0):
    """runs vvm-mesh; returns (stdout, stderr); fails unless it exits with `expect`"""
    result = subprocess.run([ARGS.vvm_mesh] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    require(result.returncode == expect,
            f"vvm-mesh {' '.join(args)} exited with {result.returncode}, not {expect}:\n"
            f"{result.stdout}\n{result.stderr}")
    return result.stdout, result.stderr


def run_tool(args):
    result = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    require(result.returncode == 0, f"{' '.join(args)} exited with {result.returncode}:\n{result.stdout}")
    return result.stdout


def report(path):
    with open(path) as f:
        return json.loads(f.readline())


def signed_volumes(points, tets):
    p = points[tets]
    return np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6.0


def labels_of(mesh):
    """the subdomain label of each cell block, whatever the format calls it"""
    for key in ("gmsh:physical", "medit:ref", "subdomain"):
        if key in mesh.cell_data:
            return mesh.cell_data[key]
    fail(f"no subdomain labels in {list(mesh.cell_data)}")


def verify_tet_file(path, expected):
    """counts, labels and orientation of a tet mesh file against the JSON report `expected`"""
    mesh = meshio.read(path)
    require(all(b.type == "tetra" for b in mesh.cells if b.type not in ("triangle", "line", "vertex")),
            f"{path}: cells other than tetrahedra")
    tets = np.concatenate([b.data for b in mesh.cells if b.type == "tetra"])
    labels = np.concatenate([l for b, l in zip(mesh.cells, labels_of(mesh)) if b.type == "tetra"])
    require(len(tets) == expected["n_tets"], f"{path}: {len(tets)} tets, the report says {expected['n_tets']}")
    used = np.unique(tets)
    require(len(used) == expected["n_vertices"],
            f"{path}: {len(used)} vertices used, the report says {expected['n_vertices']}")
    require(sorted(set(labels.tolist())) == expected["labels"],
            f"{path}: labels {sorted(set(labels.tolist()))}, the report says {expected['labels']}")
    require((signed_volumes(mesh.points, tets) > 0).all(), f"{path}: a tetrahedron is not positively oriented")
    return mesh


def mesh_volume(path):
    mesh = meshio.read(path)
    tets = np.concatenate([b.data for b in mesh.cells if b.type == "tetra"])
    return abs(signed_volumes(mesh.points, tets).sum())


def gmsh_resave(path, expected_cells, expected_labels=None):
    """Gmsh reads `path` and writes it again as MSH 4.1: the same counts (and labels: its
    physical groups, or for a MEDIT file, whose references Gmsh makes entities, its entities)"""
    resaved = path + ".resaved.msh"
    run_tool([ARGS.gmsh, path, "-save", "-format", "msh41", "-o", resaved])
    mesh = meshio.read(resaved)
    volume = ("tetra", "hexahedron", "wedge", "pyramid")
    counts = {}
    for b in mesh.cells:
        if b.type in volume:
            counts[b.type] = counts.get(b.type, 0) + len(b.data)
    require(counts == expected_cells, f"Gmsh re-saved {path} with {counts}, expected {expected_cells}")
    if expected_labels is not None:
        key = "gmsh:physical" if "gmsh:physical" in mesh.cell_data else "gmsh:geometrical"
        labels = sorted(set(np.concatenate([l for b, l in zip(mesh.cells, mesh.cell_data[key])
                                            if b.type in volume]).tolist()))
        require(labels == expected_labels, f"Gmsh re-saved {path} with labels {labels}, expected {expected_labels}")


# ---------------------------------------------------------------------------------------- checks

def check_tet_gsm():
    out, err = run(["tet", data("sphere966.off"), "-o", work("sphere.msh"), "--vertices", "2000",
                    "--json", work("sphere.json")])
    r = report(work("sphere.json"))
    require(r["method"] == "gsm" and r["n_inverted"] == 0, f"report {r}")
    require(abs(r["n_vertices"] - 2000) <= 200, f"{r['n_vertices']} vertices for --vertices 2000")
    require(r["theta_min"] >= 25, f"smallest dihedral angle {r['theta_min']} after GSM")
    require("smallest dihedral angle" in out and "make_mesh_3: " in err and "gsm: round" in err,
            f"summary/progress:\n{out}\n{err}")
    verify_tet_file(work("sphere.msh"), r)


def check_tet_perturb_exude():
    run(["tet", data("sphere966.off"), "-o", work("pe.mesh"), "--vertices", "1000", "--method", "perturb+exude",
         "--json", work("pe.json"), "--quiet"])
    r = report(work("pe.json"))
    require(r["method"] == "perturb+exude" and r["n_inverted"] == 0, f"report {r}")
    verify_tet_file(work("pe.mesh"), r)


def check_tet_lattice():
    _, err = run(["tet", data("sphere966.off"), "-o", work("bcc.vtu"), "--method", "bcc", "--vertices", "1500",
                  "--json", work("bcc.json")])
    r = report(work("bcc.json"))
    require(r["n_inverted"] == 0 and r["theta_min"] > 5, f"report {r}")
    require("lattice bcc" in err, f"no particle progress:\n{err}")
    mesh = verify_tet_file(work("bcc.vtu"), r)
    require("min_dihedral_angle" in mesh.cell_data and "scaled_jacobian" in mesh.cell_data,
            f"the VTU has no quality arrays: {list(mesh.cell_data)}")
    angles = np.concatenate(mesh.cell_data["min_dihedral_angle"])
    require(abs(angles.min() - r["theta_min"]) < 1e-6, f"VTU min angle {angles.min()} vs {r['theta_min']}")


def check_thickness_sizing():
    """--sizing thickness on a block carrying fins 0.08 thick (no feature protected: the fins'
    close rims would set the count): the count kept, and the fins finer against the block than in
    the uniform mesh; the lattice and hex-dominant meshes valid"""
    sink = data(os.path.join("thin_walled", "heat_sink.off"))
    reports = {}
    for sizing in ("uniform", "thickness"):
        run(["tet", sink, "-o", work(sizing + ".mesh"), "--vertices", "3000", "--sizing", sizing,
             "--features-angle", "0", "--json", work(sizing + ".json"), "--quiet"])
        reports[sizing] = report(work(sizing + ".json"))
        verify_tet_file(work(sizing + ".mesh"), reports[sizing])
    r = reports["thickness"]
    require(abs(r["n_vertices"] - 3000) <= 300 and r["n_inverted"] == 0, f"report {r}")
    require(r["theta_min"] >= 20, f"smallest dihedral angle {r['theta_min']} after GSM")

    def fin_to_block(path):  # the median edge inside the fins over that inside the block
        mesh = meshio.read(path)
        tets = mesh.get_cells_type("tetra")
        edges = np.concatenate([tets[:, [i, j]] for i, j in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3))])
        mid = 0.5 * (mesh.points[edges[:, 0]] + mesh.points[edges[:, 1]])
        length = np.linalg.norm(mesh.points[edges[:, 0]] - mesh.points[edges[:, 1]], axis=1)
        in_fin = (mid[:, 2] > 0.6) & (np.mod(mid[:, 0] - 0.1, 0.4) < 0.08)
        in_block = (mid[:, 2] < 0.35) & (mid[:, 2] > 0.15) & (np.abs(mid[:, 0] - 1) < 0.8) & (np.abs(mid[:, 1] - 0.75) < 0.55)
        return np.median(length[in_fin]) / np.median(length[in_block])
    graded, uniform = fin_to_block(work("thickness.mesh")), fin_to_block(work("uniform.mesh"))
    print(f"fin edges over block edges: {graded:.3f} (thickness), {uniform:.3f} (uniform)")
    require(graded < 0.8 * uniform, f"fin/block edge ratio {graded} with the thickness sizing, {uniform} uniform")
    run(["tet", sink, "-o", work("bcc.mesh"), "--method", "bcc", "--vertices", "2000", "--sizing", "thickness",
         "--features-angle", "0", "--json", work("bcc.json"), "--quiet"])
    r = report(work("bcc.json"))
    require(r["n_inverted"] == 0 and r["theta_min"] > 5, f"bcc report {r}")
    run(["hexdom", sink, "-o", work("hexdom.vtu"), "--particles", "2000", "--sizing", "thickness",
         "--features-angle", "0", "--json", work("hexdom.json"), "--quiet"])
    r = report(work("hexdom.json"))
    require(r["n_hex"] > 0 and r["n_inverted"] == 0, f"hexdom report {r}")
    # the cross field's scale correction reaches the thickness-scaled field: without it, other particles
    run(["hexdom", sink, "-o", work("hexdom_uncorrected.vtu"), "--particles", "2000", "--sizing", "thickness",
         "--features-angle", "0", "--maximum-size-ratio", "1", "--quiet"])
    corrected, uncorrected = meshio.read(work("hexdom.vtu")).points, meshio.read(work("hexdom_uncorrected.vtu")).points
    require(corrected.shape != uncorrected.shape or not np.array_equal(corrected, uncorrected),
            "--maximum-size-ratio 1 gave the same hex-dominant mesh as the default ratio 2")


def write_labelled_inr(path, n=24):
    """a ball of label 1 around a smaller ball of label 2, n^3 voxels of size 0.1"""
    header = (f"#INRIMAGE-4#{{\nXDIM={n}\nYDIM={n}\nZDIM={n}\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 bits\n"
              f"SCALE=2**0\nCPU=decm\nVX=0.1\nVY=0.1\nVZ=0.1\n")
    header += "\n" * (252 - len(header)) + "##}\n"
    c = (n - 1) / 2.0
    z, y, x = np.mgrid[0:n, 0:n, 0:n]
    r = np.sqrt((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2)
    label = np.where(r < 0.25 * n, 2, np.where(r < 0.45 * n, 1, 0)).astype(np.uint8)
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(label.tobytes())


def check_tet_image():
    write_labelled_inr(work("balls.inr"))
    run(["tet", work("balls.inr"), "-o", work("balls.mesh"), "--vertices", "1500", "--json", work("balls.json"),
         "--quiet"])
    r = report(work("balls.json"))
    require(r["labels"] == [1, 2] and r["n_inverted"] == 0 and r["theta_min"] >= 20, f"report {r}")
    verify_tet_file(work("balls.mesh"), r)


def check_formats():
    """one two-label mesh written in the three formats: meshio reads the same, Gmsh re-saves .msh and .mesh"""
    run(["tet", data("sphere966.off"), "-o", work("sphere.mesh"), "--vertices", "1000", "--quiet"])
    mesh = meshio.read(work("sphere.mesh"))
    tets = mesh.cells_dict["tetra"]
    labels = np.where(mesh.points[tets].mean(axis=1)[:, 0] < 0, 3, 5).astype(np.int64)
    meshio.write(work("two.mesh"), meshio.Mesh(mesh.points, [("tetra", tets)], cell_data={"medit:ref": [labels]}))
    volume = {l: signed_volumes(mesh.points, tets[labels == l]).sum() for l in (3, 5)}
    for extension in (".mesh", ".msh", ".vtu"):
        run(["optimize", work("two.mesh"), "-o", work("copy" + extension), "--fixed-boundary", "--quiet",
             "--json", work("copy.json")])
        r = report(work("copy.json"))
        require(r["labels"] == [3, 5], f"labels {r['labels']}")
        copy = verify_tet_file(work("copy" + extension), r)
        # each label's cells fill the same volume as before (the interface is a fixed boundary)
        copy_tets = np.concatenate([b.data for b in copy.cells if b.type == "tetra"])
        copy_labels = np.concatenate([l for b, l in zip(copy.cells, labels_of(copy)) if b.type == "tetra"])
        for l in (3, 5):
            v = signed_volumes(copy.points, copy_tets[copy_labels == l]).sum()
            require(abs(v - volume[l]) <= 1e-6 * abs(volume[l]), f"{extension}: label {l} volume {volume[l]} -> {v}")
        if extension != ".vtu":  # Gmsh 4.8 does not read VTU
            gmsh_resave(work("copy" + extension), {"tetra": r["n_tets"]}, [3, 5])


def check_hexdom():
    out, _ = run(["hexdom", data("cube.off"), "-o", work("cube.vtu"), "--particles", "1000", "--json",
                  work("cube.json"), "--quiet"])
    r = report(work("cube.json"))
    require(r["n_hex"] > 0 and r["n_inverted"] == 0 and r["hex_volume_percent"] > 90, f"report {r}")
    require("hexahedra" in out, f"summary:\n{out}")
    for extension in (".msh", ".mesh"):
        run(["hexdom", data("cube.off"), "-o", work("cube" + extension), "--particles", "1000", "--quiet"])
        mesh = meshio.read(work("cube" + extension))
        for cell_type, key in (("hexahedron", "n_hex"), ("wedge", "n_prism"), ("pyramid", "n_pyramid"), ("tetra", "n_tets")):
            require(len(mesh.cells_dict.get(cell_type, [])) == r[key], f"cube{extension}: {cell_type} count")
        # Gmsh 4.8 (Debian 12) reads a MEDIT file's Tetrahedra and Hexahedra, and skips its Prisms
        # and Pyramids (checked on a one-prism file): those are compared through meshio above
        read_by_gmsh = ("tetra", "hexahedron") if extension == ".mesh" else ("tetra", "hexahedron", "wedge", "pyramid")
        gmsh_resave(work("cube" + extension), {t: len(c) for t, c in mesh.cells_dict.items() if t in read_by_gmsh})
    mesh = meshio.read(work("cube.vtu"))
    require(len(mesh.cells_dict.get("hexahedron", [])) == r["n_hex"], "cube.vtu: hexahedra")
    require(r["time_limit_reached"] is False, f"report {r}")
    # a time limit up at once: a valid mesh of the particles' tets, none merged, and said so
    out, _ = run(["hexdom", data("cube.off"), "-o", work("cut.mesh"), "--particles", "1000", "--time-limit", "1e-9",
                  "--json", work("cut.json"), "--quiet"])
    r = report(work("cut.json"))
    require(r["time_limit_reached"] is True and r["n_hex"] == 0 and r["n_inverted"] == 0 and r["n_tets"] > 0,
            f"report {r}")
    require("stopped at the time limit" in out, f"summary:\n{out}")


def check_field():
    out, _ = run(["field", data("sphere966.off"), "-o", work("cross.txt"), "--vertices", "1000", "--quiet"])
    require(os.path.getsize(work("cross.txt")) > 0 and "cross field written" in out, out)
    run(["tet", data("sphere966.off"), "-o", work("bcc.mesh"), "--method", "bcc", "--vertices", "1000",
         "--field", work("cross.txt"), "--json", work("bcc.json"), "--quiet"])
    r = report(work("bcc.json"))
    require(r["n_inverted"] == 0, f"report {r}")


def check_quality():
    run(["tet", data("sphere966.off"), "-o", work("s.mesh"), "--vertices", "1000", "--quiet", "--json",
         work("made.json")])
    out, _ = run(["quality", work("s.mesh"), "--json", work("q.json")])
    made, q = report(work("made.json")), report(work("q.json"))
    for key in ("n_vertices", "n_tets", "n_inverted", "n_min_dih_lt30", "labels"):
        require(made[key] == q[key], f"{key}: {made[key]} when made, {q[key]} read back")
    require(abs(made["theta_min"] - q["theta_min"]) < 1e-9, "smallest angle read back")
    require("histogram" in out and "radius ratio" in out, f"quality table:\n{out}")


def read_closed_surface(path):
    """(points, triangles, Euler characteristic) of a triangle surface file, checked closed and
    oriented: each edge in two triangles, once each way"""
    mesh = meshio.read(path)
    require([b.type for b in mesh.cells] == ["triangle"], f"{path}: cells {[b.type for b in mesh.cells]}")
    triangles = mesh.cells[0].data
    directed = triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    require(len(np.unique(directed, axis=0)) == len(directed), f"{path}: an edge twice the same way")
    edges, counts = np.unique(np.sort(directed, axis=1), axis=0, return_counts=True)
    require((counts == 2).all(), f"{path}: {(counts != 2).sum()} edges not in two triangles")
    return mesh.points, triangles, len(np.unique(triangles)) - len(edges) + len(triangles)


SURFACE_KEYS = ("model", "method", "field", "n_vertices", "n_faces", "r6", "xi_mean", "xi_min", "min_angle_metric_deg",
                "mean_min_angle_metric_deg", "alignment_error_mean_deg", "is_closed_manifold", "time_s")


def check_surface():
    """vvm-mesh surface: the torus in its curvature field (.off), fandisk's sharp edges (.ply), the
    cube in the identity field at an edge length (.obj) and in a frame-field file, read back closed
    and oriented, with the report's counts; no temporary file left"""
    # lower bounds of r6, xi mean, xi min, the smallest angle, under the figures of seeds 0-9 (torus:
    # 0.94-0.95, 0.95, 0.47-0.59, 27-34 degrees; fandisk: 0.65-0.67, 0.84-0.85, and next to its sharp
    # edges a sliver now and then: xi min 0-0.21, smallest angle 0.01-10.6 degrees)
    for model, out, euler, bounds in (("surfaces/torus.off", "torus.off", 0, (0.9, 0.9, 0.3, 20)),
                                      ("fandisk.off", "fandisk.ply", 2, (0.55, 0.8, 0, 0))):
        stdout, err = run(["surface", data(model), "-o", work(out), "--vertices", "1500", "--json", work(out + ".json")])
        r = report(work(out + ".json"))
        require(all(k in r for k in SURFACE_KEYS), f"keys missing in {sorted(r)}")
        require(r["method"] == "lattice" and r["field"] == "curvature" and r["is_closed_manifold"], f"report {r}")
        require(abs(r["n_vertices"] - 1500) <= 0.15 * 1500, f"{r['n_vertices']} vertices for --vertices 1500")
        figures = (r["r6"], r["xi_mean"], r["xi_min"], r["min_angle_metric_deg"])
        require(all(f >= b for f, b in zip(figures, bounds)), f"quality of {model}: {r}")
        points, triangles, chi = read_closed_surface(work(out))
        require((len(np.unique(triangles)), len(triangles), chi) == (r["n_vertices"], r["n_faces"], euler),
                f"{out}: {len(np.unique(triangles))} vertices, {len(triangles)} triangles, Euler characteristic {chi}")
        require("field: " in err and "lattice surface: " in err, f"progress:\n{err}")
        require("closed manifold" in stdout and "yes" in stdout, f"summary:\n{stdout}")
    # the vertices lie on the torus of radii 1 and 0.35 (its 160 x 60 faces are within 0.001 of it)
    points = read_closed_surface(work("torus.off"))[0]
    distance = np.abs(np.hypot(np.hypot(points[:, 0], points[:, 1]) - 1, points[:, 2]) - 0.35)
    require(distance.max() < 2e-3, f"a vertex {distance.max()} off the torus")
    run(["surface", data("cube.off"), "-o", work("cube.obj"), "--field", "identity", "--size", "0.25", "--quiet",
         "--json", work("cube.json")])
    r = report(work("cube.json"))
    points, triangles, chi = read_closed_surface(work("cube.obj"))
    require(r["is_closed_manifold"] and r["field"] == "identity" and chi == 2, f"report {r}")
    require(np.abs(points).max() <= 1 + 1e-9 and (np.abs(points).max(axis=1) >= 1 - 1e-9).all(),
            "a vertex of the cube's mesh is not on the cube")
    # the same edge length from a frame-field file: a volume field of one vertex whose axes are
    # 0.25 long (on each face, the two axes in its plane)
    with open(work("cube_field.txt"), "w") as f:
        f.write("VVMFrameField 1\nLocation Vertices\nVertices\n1\n0 0 0\nTetrahedra\n0\nFrames\n1\n"
                "0.25 0 0 0 0.25 0 0 0 0.25\nEnd\n")
    run(["surface", data("cube.off"), "-o", work("cube_file.off"), "--field", work("cube_field.txt"), "--size", "1",
         "--quiet", "--json", work("cube_file.json")])
    f = report(work("cube_file.json"))
    chi = read_closed_surface(work("cube_file.off"))[2]
    require(f["is_closed_manifold"] and f["field"] == work("cube_field.txt") and chi == 2, f"report {f}")
    require(abs(f["n_vertices"] - r["n_vertices"]) <= 0.1 * r["n_vertices"] and f["r6"] > 0.75,
            f"the field file's mesh: {f}; the identity field's: {r}")
    require(not [n for n in os.listdir(ARGS.work) if n.endswith(".tmp")], "temporary files left")


def tetgen_mesh(model):
    """TetGen's quality mesh of a bundled model (boundary kept), as MEDIT"""
    shutil.copy(data(model + ".off"), work(model + ".off"))
    run_tool([ARGS.tetgen, "-pq1.3/15", "-YgQ", work(model + ".off")])
    return work(model + ".1.mesh")


def write_stl(off_path, stl_path):
    with open(off_path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    require(tokens[0] == "OFF", "not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    v = np.array(tokens[4:4 + 3 * nv], dtype=float).reshape(-1, 3)
    faces, i = [], 4 + 3 * nv
    for _ in range(nf):
        k = int(tokens[i])
        faces.append([int(t) for t in tokens[i + 1:i + 1 + k]])
        i += 1 + k
    meshio.write(stl_path, meshio.Mesh(v, [("triangle", np.array(faces))]), binary=False)


def gmsh_mesh(model):
    """Gmsh's Delaunay mesh of a bundled model's surface, with its own optimizer"""
    write_stl(data(model + ".off"), work(model + ".stl"))
    with open(work(model + ".geo"), "w") as f:
        f.write(f'Merge "{model}.stl";\nSurface Loop(1) = {{1}};\nVolume(1) = {{1}};\nPhysical Volume(7) = {{1}};\n'
                'Mesh.Optimize = 1;\nMesh.OptimizeThreshold = 0.7;\n')
    run_tool([ARGS.gmsh, work(model + ".geo"), "-3", "-format", "msh41", "-o", work(model + "_gmsh.msh")])
    return work(model + "_gmsh.msh")


def verify_optimized(source, name, min_angle=25):
    run(["quality", source, "--json", work(name + "_in.json")])
    out, _ = run(["optimize", source, "-o", work(name + "_gsm"), "--json", work(name + ".json"), "--quiet"])
    before, after = report(work(name + "_in.json")), report(work(name + ".json"))
    extension = os.path.splitext(source)[1]
    verify_tet_file(work(name + "_gsm" + extension), after)
    require(after["n_inverted"] == 0, f"{name}: inverted tets")
    require(after["labels"] == before["labels"], f"{name}: labels {before['labels']} -> {after['labels']}")
    require(after["theta_min"] >= min_angle and after["theta_min"] > before["theta_min"],
            f"{name}: smallest angle {before['theta_min']} -> {after['theta_min']}")
    require(after["n_min_dih_lt30"] < before["n_min_dih_lt30"], f"{name}: tets under 30 not fewer")
    require(abs(after["n_vertices"] - before["n_vertices"]) <= 0.03 * before["n_vertices"],
            f"{name}: {before['n_vertices']} -> {after['n_vertices']} vertices")
    # the guard holds the boundary's facets within the bound of the input's boundary, exactly:
    # the input's corners and edges under a moved facet are measured, not only a grid on it
    require(after["boundary_hausdorff"] <= (1 + 1e-6) * after["boundary_distance_bound"],
            f"{name}: boundary moved {after['boundary_hausdorff']}, bound {after['boundary_distance_bound']}")
    require("boundary moved by" in out, out)
    # and the domain's volume stays (independently of the program's measure)
    v0, v1 = mesh_volume(source), mesh_volume(work(name + "_gsm" + extension))
    require(abs(v1 - v0) <= 1e-3 * v0, f"{name}: volume {v0} -> {v1}")


def check_optimize_tetgen():
    verify_optimized(tetgen_mesh("fandisk"), "fandisk_tetgen")


def check_optimize_gmsh():
    verify_optimized(gmsh_mesh("fandisk"), "fandisk_gmsh")


def check_optimize_two_labels():
    """a two-label MEDIT mesh written by Gmsh: a ball inside a box, without Gmsh's optimizer"""
    with open(work("two.geo"), "w") as f:
        f.write('SetFactory("OpenCASCADE");\nBox(1) = {-1, -1, -1, 2, 2, 2};\nSphere(2) = {0, 0, 0, 0.6};\n'
                'v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };\n'
                'Mesh.MeshSizeMax = 0.2;\nMesh.Optimize = 0;\n')
    run_tool([ARGS.gmsh, work("two.geo"), "-3", "-o", work("two.mesh")])
    verify_optimized(work("two.mesh"), "two_labels")
    def tet_labels(mesh):
        return np.concatenate([l for b, l in zip(mesh.cells, labels_of(mesh)) if b.type == "tetra"])
    before, after = tet_labels(meshio.read(work("two.mesh"))), tet_labels(meshio.read(work("two_labels_gsm.mesh")))
    require(len(set(before.tolist())) == 2, f"Gmsh's mesh has labels {set(before.tolist())}")
    for l in set(before.tolist()):
        n0, n1 = (before == l).sum(), (after == l).sum()
        require(abs(n1 - n0) <= 0.15 * n0, f"label {l}: {n0} -> {n1} cells")


def bad_case(args, words, output):
    """exit 2, a message with `words`, and `output` (made beforehand) untouched"""
    with open(output, "w") as f:
        f.write("keep")
    _, err = run(args, expect=2)
    require(any(w.lower() in err.lower() for w in words.split("|")) and "error" in err,
            f"vvm-mesh {' '.join(args)}: message\n{err}")
    with open(output) as f:
        require(f.read() == "keep", f"vvm-mesh {' '.join(args)} touched {output}")
    leftovers = [n for n in os.listdir(os.path.dirname(output)) if n.endswith(".tmp")]
    require(not leftovers, f"temporary files left: {leftovers}")


def check_bad_inputs():
    out, surface_out = work("out.mesh"), work("out.off")
    with open(work("empty.off"), "w"):
        pass
    with open(data("cube.off")) as f:
        lines = f.read().split("\n")
    with open(work("open.off"), "w") as f:  # the cube less one triangle
        f.write("OFF\n8 11 0\n" + "\n".join(lines[2:10] + lines[11:22]) + "\n")
    with open(work("nan.off"), "w") as f:
        f.write("OFF\n4 4 0\nnan 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    tet = "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
    with open(work("inverted.mesh"), "w") as f:  # two tets of opposite orientations
        f.write(f"MeshVersionFormatted 1\nDimension 3\nVertices\n5\n{tet}Tetrahedra\n2\n1 2 3 4 1\n3 2 4 5 1\nEnd\n")
    with open(work("flat.mesh"), "w") as f:
        f.write("MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n"
                "Tetrahedra\n1\n1 2 3 4 1\nEnd\n")
    with open(work("nan.mesh"), "w") as f:
        f.write("MeshVersionFormatted 1\nDimension 3\nVertices\n4\nnan 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                "Tetrahedra\n1\n1 2 3 4 1\nEnd\n")
    with open(work("nocell.mesh"), "w") as f:
        f.write(f"MeshVersionFormatted 1\nDimension 3\nVertices\n5\n{tet}End\n")
    with open(work("quads.off"), "w") as f:  # the cube of six quadrilaterals
        f.write("OFF\n8 6 0\n" + "\n".join(lines[2:10]) +
                "\n4 0 1 2 3\n4 4 7 6 5\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n")
    cases = [
        (["tet", work("missing.off"), "-o", out], "cannot open"),
        (["tet", work("empty.off"), "-o", out], "empty"),
        (["tet", work("open.off"), "-o", out], "open"),
        (["tet", work("nan.off"), "-o", out], "non-finite|cannot read"),
        (["tet", data("cube.off"), "-o", work("out.xyz")], "extension"),
        (["tet", data("cube.off"), "-o", out, "--vertices", "many"], "expects a number"),
        (["tet", data("cube.off"), "-o", out, "--method", "magic"], "unknown method"),
        (["tet", data("cube.off"), "-o", out, "--size", "-1"], "size"),
        (["tet", data("cube.off"), "-o", out, "--frobnicate"], "unknown option"),
        (["tet", data("cube.off"), "-o", os.path.join(work("no_folder"), "x.mesh")], "no folder"),
        (["hexdom", data("cube.off"), "-o", out, "--q-bound", "2"], "q-bound"),
        (["optimize", work("inverted.mesh"), "-o", out], "inverted"),
        (["optimize", work("flat.mesh"), "-o", out], "flat"),
        (["optimize", work("nan.mesh"), "-o", out], "non-finite"),
        (["optimize", work("nocell.mesh"), "-o", out], "no tetrahedron"),
        (["optimize", data("cube.off"), "-o", out], "extension"),
        (["optimize", work("inverted.mesh"), "-o", out, "--json", out], "overwrite"),
        (["tet", data("cube.off"), "-o", out, "--seed", "-3"], "seed"),
        (["tet", data("cube.off"), "-o", out, "--sizing", "magic"], "unknown sizing"),
        (["hexdom", data("cube.off"), "-o", out, "--sizing", "magic"], "unknown sizing"),
        (["hexdom", data("cube.off"), "-o", out, "--maximum-size-ratio", "0.5"], "size ratio"),
        (["tet", data("cube.off"), "-o", out, "--time-limit", "-1"], "time-limit"),
        (["quality", work("missing.mesh")], "cannot open"),
        (["surface", work("missing.off"), "-o", surface_out], "cannot open"),
        (["surface", work("empty.off"), "-o", surface_out], "empty"),
        (["surface", work("nan.off"), "-o", surface_out], "non-finite|cannot read"),
        (["surface", work("quads.off"), "-o", surface_out], "triangle"),
        (["surface", data("cube.off"), "-o", out], "extension"),
        (["surface", data("cube.off"), "-o", surface_out, "--field", "cross"], "unknown field"),
        (["surface", data("cube.off"), "-o", surface_out, "--field", work("empty.off")], "read_frame_field"),
        (["surface", data("cube.off"), "-o", surface_out, "--maximum-anisotropy", "0.5"], "anisotropy"),
        (["surface", data("cube.off"), "-o", surface_out, "--vertices", "10"], "vertices"),
        (["frobnicate"], "unknown command"),
    ]
    for args, words in cases:
        bad_case(args, words, surface_out if surface_out in args else out)
    require(not os.path.exists(work("out.xyz")), "out.xyz written")

def write_pinched_boxes(path, n=6, seed=3):
    """two unit boxes that touch along one edge (x = y = 1), each cut into n^3 cubes of six
    tets, the nodes inside each box moved at random (slivers); labels 1 and 2"""
    rng = np.random.default_rng(seed)
    index, grid, points, tets, labels = {}, [], [], [], []

    def node(p, jitter):
        key = tuple(np.round(p * n).astype(int))
        if key not in index:
            index[key] = len(points)
            grid.append(p)
            points.append(p + (jitter if key_inside(key) else 0))
        return index[key]

    def key_inside(key):
        return all(0 < (k % n if k != 2 * n else n) < n for k in key)

    kuhn = [(0, 1, 3, 7), (0, 1, 5, 7), (0, 2, 3, 7), (0, 2, 6, 7), (0, 4, 5, 7), (0, 4, 6, 7)]
    for label, offset in ((1, np.array([0, 0, 0])), (2, np.array([1, 1, 0]))):
        jitter = {}
        for i in range(n):
            for j in range(n):
                for k in range(n):
                    corners = []
                    for c in range(8):
                        q = np.array([i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1)])
                        key = tuple(q)
                        if key not in jitter:
                            jitter[key] = rng.uniform(-0.2, 0.2, 3) / n
                        corners.append(node(offset + q / n, jitter[key]))
                    for t in kuhn:
                        tets.append([corners[v] for v in t])
                        labels.append(label)
    points, tets = np.array(points), np.array(tets)
    negative = signed_volumes(np.array(grid), tets) < 0 # oriented on the grid, before the jitter
    tets[negative] = tets[negative][:, [1, 0, 2, 3]]
    require((signed_volumes(points, tets) > 0).all(), "the jittered boxes have a flat or inverted tet")
    meshio.write(path, meshio.Mesh(points, [("tetra", tets)], cell_data={"medit:ref": [np.array(labels)]}))


def check_optimize_pinched():
    """two parts that touch along an edge (as make_mesh_3's surface of dino and triceratops
    pinches two close parts together): four boundary facets meet at each segment of the edge"""
    write_pinched_boxes(work("pinched.mesh"))
    verify_optimized(work("pinched.mesh"), "pinched")


def check_render():
    """tools/render_mesh.py: a tet mesh coloured by its smallest angles, a hex-dominant one by cell
    type, side by side; bad input refused with exit 2 and no picture"""
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "render_mesh.py")
    import matplotlib.image
    run(["tet", data("sphere966.off"), "-o", work("sphere.mesh"), "--vertices", "1000", "--method", "perturb+exude",
         "--quiet"])
    run(["hexdom", data("cube.off"), "-o", work("cube.vtu"), "--particles", "500", "--quiet"])

    def render(meshes, png, expect=0):
        result = subprocess.run([sys.executable, script] + meshes + ["-o", png], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        require(result.returncode == expect, f"render_mesh {meshes} exited with {result.returncode}:\n{result.stderr}")
        return result.stderr

    def pixels(png):
        image = matplotlib.image.imread(png)[:, :, :3]
        return image.reshape(-1, 3)

    # its angles are vvm-mesh quality's
    sys.path.insert(0, os.path.dirname(script))
    import render_mesh
    run(["quality", work("sphere.mesh"), "--json", work("sphere.json")])
    r = report(work("sphere.json"))
    mesh = meshio.read(work("sphere.mesh"))
    angles = render_mesh.smallest_dihedral_angles(np.asarray(mesh.points, dtype=float), mesh.cells_dict["tetra"])
    require(abs(angles.min() - r["theta_min"]) < 1e-4 and (angles < 30).sum() == r["n_min_dih_lt30"],
            f"render_mesh: smallest {angles.min()}, {(angles < 30).sum()} under 30; quality: {r}")
    render([work("sphere.mesh")], work("sphere.png"))
    p = pixels(work("sphere.png"))
    coloured = p[(p < 0.9).any(axis=1)]
    require(len(coloured) > 0.05 * len(p), f"sphere.png: {len(coloured)} of {len(p)} pixels drawn")
    green = coloured[(coloured[:, 1] > coloured[:, 0] + 0.1) & (coloured[:, 1] > coloured[:, 2] + 0.1)]
    require(len(green) > 0.3 * len(coloured), f"sphere.png: {len(green)} green pixels of {len(coloured)}")
    render([work("cube.vtu"), work("sphere.mesh")], work("both.png"))
    p = pixels(work("both.png"))
    blue_grey = p[(p[:, 2] > p[:, 0] + 0.08) & (p[:, 2] < 0.95)]
    require(len(blue_grey) > 0.02 * len(p), f"both.png: {len(blue_grey)} hexahedron pixels of {len(p)}")
    for bad, words in (([work("missing.mesh")], "cannot read"), ([data("cube.off")], "no tetrahedron")):
        err = render(bad, work("bad.png"), expect=2)
        require(words in err and not os.path.exists(work("bad.png")), f"render_mesh {bad}: {err}")


CHECKS = {name[len("check_"):]: f for name, f in globals().items() if name.startswith("check_") and callable(f)}


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("--vvm-mesh")
    parser.add_argument("--data")
    parser.add_argument("--work")
    parser.add_argument("--tetgen", default="tetgen")
    parser.add_argument("--gmsh", default="gmsh")
    parser.add_argument("--registered", action="store_true")
    parser.add_argument("checks", nargs="*")
    ARGS = parser.parse_args()
    if ARGS.registered:
        missing = sorted(set(CHECKS) - set(ARGS.checks))
        require(not missing, f"checks not registered with CTest: {missing}")
        print(f"{len(CHECKS)} checks registered")
        return
    require(len(ARGS.checks) == 1 and ARGS.checks[0] in CHECKS, f"one of {sorted(CHECKS)} expected")
    shutil.rmtree(ARGS.work, ignore_errors=True)
    os.makedirs(ARGS.work)
    CHECKS[ARGS.checks[0]]()
    print(f"{ARGS.checks[0]}: passed")


if __name__ == "__main__":
    run_main(main)
