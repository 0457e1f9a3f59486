#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""vvm-mesh optimize on the tet meshes of TetGen and Gmsh, against their own output.

usage: optimize_other_meshers.py VVM_MESH DATA_DIR OUT_DIR [--vertices N] [--models a,b,...]

For every closed surface DATA_DIR/*.off, both tools get the same surface, sized for a volume
mesh of about N vertices: the boundary of make_mesh_3's mesh at N vertices (vvm-mesh tet
--method perturb+exude, sharp edges protected at 60 degrees). Then:
  - TetGen's quality mesh: tetgen -pq1.3/15 -Y -a<A> -g (the surface kept), A corrected
    twice for about N vertices;
  - Gmsh's: the surface kept (STL, discrete), Delaunay, its optimizer with
    Mesh.OptimizeThreshold=0.7, Mesh.MeshSizeMax from the volume for about N vertices;
then vvm-mesh optimize on each. One line per model and tool: the tool's figures, GSM's, and
the bars of issue #45 (smallest angle >= 25, no tet under 20, fewer tets under 30 and 40,
higher mean smallest angle, vertex count within 3%, boundary moved no more than the bound,
GSM time at most twice Gmsh's time to mesh and optimize).
"""

import json
import os
import subprocess
import sys
import time

import numpy as np


def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    start = 1 if tokens[0] == "OFF" else 0
    nv, nf = int(tokens[start]), int(tokens[start + 1])
    i = start + 3
    v = np.array(tokens[i:i + 3 * nv], dtype=float).reshape(-1, 3)
    i += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(tokens[i])
        poly = [int(t) for t in tokens[i + 1:i + 1 + k]]
        faces += [[poly[0], poly[j], poly[j + 1]] for j in range(1, k - 1)]
        i += 1 + k
    return v, np.array(faces)


def boundary_of(mesh_path):
    """the facets of exactly one tetrahedron, oriented outwards, and their vertices"""
    import meshio
    mesh = meshio.read(mesh_path)
    tets = np.concatenate([b.data for b in mesh.cells if b.type == "tetra"])
    faces = {}
    for t in tets:
        for i, (a, b, c) in enumerate(((1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1))):
            tri = (t[a], t[b], t[c])
            key = tuple(sorted(tri))
            faces[key] = None if key in faces else tri
    tris = np.array([tri for tri in faces.values() if tri is not None])
    used, index = np.unique(tris, return_inverse=True)
    return mesh.points[used], index.reshape(-1, 3)


def volume(v, f):
    return abs(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]])).sum() / 6.0)


def write_stl(v, f, path):
    with open(path, "w") as out:
        out.write("solid s\n")
        for t in f:
            n = np.cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]])
            out.write(f"facet normal {n[0]} {n[1]} {n[2]}\nouter loop\n")
            for k in t:
                out.write(f"vertex {v[k][0]!r} {v[k][1]!r} {v[k][2]!r}\n")
            out.write("endloop\nendfacet\n")
        out.write("endsolid s\n")


def timed(args, cwd=None):
    start = time.time()
    r = subprocess.run(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return r.returncode, time.time() - start, r.stdout


def report(path):
    with open(path) as f:
        return json.loads(f.readline())


def main():
    vvm, data, out = sys.argv[1:4]
    target = 10000
    models = None
    args = sys.argv[4:]
    for i, a in enumerate(args):
        if a == "--vertices":
            target = int(args[i + 1])
        if a == "--models":
            models = args[i + 1].split(",")
    os.makedirs(out, exist_ok=True)
    names = sorted(n[:-4] for n in os.listdir(data) if n.endswith(".off"))
    if models:
        names = [n for n in names if n in models]
    rows = []
    header = (f"{'model':12} {'tool':6} {'verts':>6} {'v_gsm':>6} {'th_min':>6} {'gsm':>6} {'<20':>5} {'gsm':>4} "
              f"{'<30':>6} {'gsm':>5} {'<40':>6} {'gsm':>6} {'mean':>5} {'gsm':>5} {'moved/bd':>8} {'t_tool':>6} "
              f"{'t_gsm':>6} result")
    print(header, flush=True)
    for name in names:
        prefix = os.path.join(out, name)
        code, _, log = timed([vvm, "tet", os.path.join(data, name + ".off"), "-o", prefix + "_surface.mesh",
                              "--method", "perturb+exude", "--vertices", str(target), "--quiet"])
        if code != 0:
            print(f"{name:12} vvm-mesh tet failed: {log.strip()[-300:]}", flush=True)
            continue
        v, f = boundary_of(prefix + "_surface.mesh")
        vol = volume(v, f)
        # about 5.5 tets per vertex, TetGen's -a is a bound: twice the mean
        a = 2 * vol / (5.5 * target)
        h = (vol / target * 6 * np.sqrt(2)) ** (1 / 3)  # the regular tet edge of that density
        inputs = {}
        write_stl(v, f, prefix + ".stl")
        with open(prefix + ".poly.off", "w") as g:  # TetGen wants triangles
            g.write(f"OFF\n{len(v)} {len(f)} 0\n" + "".join(f"{p[0]!r} {p[1]!r} {p[2]!r}\n" for p in v) +
                    "".join(f"3 {t[0]} {t[1]} {t[2]}\n" for t in f))
        for attempt in range(3):  # -a corrected by the vertex count TetGen gave
            code, t, log = timed(["tetgen", "-pq1.3/15", "-Y", f"-a{a:.6g}", "-gQ", prefix + ".poly.off"])
            if code != 0 or not os.path.exists(prefix + ".poly.1.node"):
                break
            with open(prefix + ".poly.1.node") as g:
                n = int(g.readline().split()[0])
            if abs(n - target) <= 0.1 * target or (n > target and attempt == 2):
                break
            a *= n / target
        if code == 0 and os.path.exists(prefix + ".poly.1.mesh"):
            inputs["tetgen"] = (prefix + ".poly.1.mesh", t)
        else:
            print(f"{name:12} tetgen failed ({code}): {log.strip()[-200:]}", flush=True)
        with open(prefix + ".geo", "w") as g:
            g.write(f'Merge "{name}.stl";\nSurface Loop(1) = {{1}};\nVolume(1) = {{1}};\nPhysical Volume(1) = {{1}};\n'
                    f"Mesh.MeshSizeMax = {h:.6g};\nMesh.Optimize = 1;\nMesh.OptimizeThreshold = 0.7;\n")
        code, t, log = timed(["gmsh", name + ".geo", "-3", "-format", "msh41", "-o", name + "_gmsh.msh"], cwd=out)
        if code == 0 and os.path.exists(prefix + "_gmsh.msh"):
            inputs["gmsh"] = (prefix + "_gmsh.msh", t)
        else:
            print(f"{name:12} gmsh failed ({code}): {log.strip()[-200:]}", flush=True)
        gmsh_time = inputs["gmsh"][1] if "gmsh" in inputs else None
        for tool, (path, tool_time) in inputs.items():
            q_in = prefix + f"_{tool}_in.json"
            code, _, log = timed([vvm, "quality", path, "--json", q_in])
            if code != 0:
                print(f"{name:12} {tool:6} quality failed: {log.strip()[-300:]}", flush=True)
                continue
            q_out = prefix + f"_{tool}_gsm.json"
            extension = os.path.splitext(path)[1]
            code, t_gsm, log = timed([vvm, "optimize", path, "-o", prefix + f"_{tool}_gsm{extension}", "--quiet",
                                      "--json", q_out])
            if code != 0:
                print(f"{name:12} {tool:6} optimize exit {code}: {log.strip()[-300:]}", flush=True)
                rows.append({"model": name, "tool": tool, "error": log.strip()[-300:]})
                continue
            b, g = report(q_in), report(q_out)
            moved = g["boundary_hausdorff"] / g["boundary_distance_bound"] if g["boundary_distance_bound"] > 0 else 0
            bars = {
                "angle>=25": g["theta_min"] >= 25,
                "none<20": g["n_min_dih_lt20"] == 0,
                "fewer<30": g["n_min_dih_lt30"] < b["n_min_dih_lt30"] or g["n_min_dih_lt30"] == 0,
                "fewer<40": g["n_min_dih_lt40"] < b["n_min_dih_lt40"],
                "mean": g["mean_min_dihedral"] > b["mean_min_dihedral"],
                "verts3%": abs(g["n_vertices"] - b["n_vertices"]) <= 0.03 * b["n_vertices"],
                "boundary": moved <= 1.0,
                "time": gmsh_time is not None and t_gsm <= 2 * gmsh_time,
            }
            missed = [k for k, ok in bars.items() if not ok]
            print(f"{name:12} {tool:6} {b['n_vertices']:6d} {g['n_vertices']:6d} {b['theta_min']:6.2f} "
                  f"{g['theta_min']:6.2f} {b['n_min_dih_lt20']:5d} {g['n_min_dih_lt20']:4d} {b['n_min_dih_lt30']:6d} "
                  f"{g['n_min_dih_lt30']:5d} {b['n_min_dih_lt40']:6d} {g['n_min_dih_lt40']:6d} "
                  f"{b['mean_min_dihedral']:5.1f} {g['mean_min_dihedral']:5.1f} {moved:8.2f} {tool_time:6.2f} "
                  f"{t_gsm:6.2f} {'PASS' if not missed else 'miss: ' + ','.join(missed)}", flush=True)
            rows.append({"model": name, "tool": tool, "tool_time_s": tool_time, "gsm_wall_s": t_gsm,
                         "gmsh_time_s": gmsh_time, "before": b, "after": g, "missed": missed})
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
