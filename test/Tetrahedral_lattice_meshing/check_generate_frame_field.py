#!/usr/bin/env python3
# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""End-to-end checks of generate_frame_field.

usage: check_generate_frame_field.py GENERATE_FRAME_FIELD DATA_DIR WORK_DIR

- runs it on data/cube.off (features at 60 deg) at about 1500 vertices: the
  JSON has every field the issue asks for, the field follows the cube's faces
  (mean and 95th percentile alignment error under 1 deg, no singular edge);
  reads the VTU back with meshio (points, tets, three unit, orthogonal axes per
  point) and the text format (same frames as the VTU), and recomputes the
  alignment error of the boundary faces from the VTU, independently;
- on data/fandisk.off at about 10,000 vertices with sharp edges at 60 deg:
  mean alignment error under 2 deg, 95th percentile under 10 deg, singular
  edges under 0.5% of the interior edges, every boundary vertex's frame on its
  constrained axis to 1e-6 rad, the smoothing energy reported per round, the
  singular curves without dead end, and their VTU polylines (read back as XML:
  one polyline per curve, as many segments as singular edges);
- a model name with a quote is escaped in the JSON;
- feeds it bad inputs (missing, empty, garbage, open surface) and bad options
  (non-positive N, NaN angle, unknown option) and expects exit code 2 and a
  message.
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from vvm_checks import Checks  # noqa: E402

import meshio
import numpy as np

EXE, DATA, WORK = sys.argv[1:4]
check = Checks("check_generate_frame_field")


def run(args):
    return subprocess.run([EXE] + args, capture_output=True, text=True, timeout=600)


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)

# --- the cube, end to end
vtu, frames, js = (os.path.join(WORK, "cube" + e) for e in (".vtu", ".frames", ".json"))
r = run([os.path.join(DATA, "cube.off"), "--vertices", "1500", "--features-angle", "60",
         "--out", vtu, "--frames", frames, "--json", js])
if not check(r.returncode == 0, "cube run exits 0"):
    print(r.stdout, r.stderr, file=sys.stderr)
    sys.exit(1)
report = json.loads(open(js).read())
check(json.loads(r.stdout) == report, "stdout carries the same JSON as --json")
for key in ["n_tets", "n_interior_edges", "n_singular_edges", "boundary_alignment_error_mean_deg",
            "boundary_alignment_error_p95_deg", "smoothness_energy", "time_s"]:
    check(key in report, "JSON has " + key)
print(json.dumps(report))
check(1200 <= report["n_vertices"] <= 1800, "about 1500 vertices: %d" % report["n_vertices"])
check(report["boundary_alignment_error_mean_deg"] < 1, "cube: mean alignment error < 1 deg")
check(report["boundary_alignment_error_p95_deg"] < 1, "cube: p95 alignment error < 1 deg")
check(report["n_singular_edges"] == 0, "cube: no singular edge")
check(report["n_interior_edges"] > report["n_vertices"], "cube: interior edges counted")
check(report["n_feature_edges"] > 12, "cube: its 12 edges are sharp features")

mesh = meshio.read(vtu)
points = mesh.points
tets = mesh.cells_dict["tetra"]
check(len(points) == report["n_vertices"], "VTU points = n_vertices")
check(len(tets) == report["n_tets"], "VTU tets = n_tets")
axes = np.stack([mesh.point_data["axis_%d" % i] for i in (1, 2, 3)], axis=2)  # (n, 3 comps, 3 axes)
gram = np.einsum("nki,nkj->nij", axes, axes)
check(np.abs(gram - np.eye(3)).max() < 1e-9, "the axes are orthonormal (a cross field of unit length)")
# every axis within 1 deg of x, y or z: the cube's own frame
cos_nearest = np.abs(axes).max(axis=1)  # for each axis, its largest |component|
check(np.degrees(np.arccos(np.clip(cos_nearest.min(), -1, 1))) < 1, "every frame follows the cube's axes")

# the boundary faces: faces of exactly one tet; their normal against the nearest axis of the
# frame at their first vertex
faces = {}
for t in tets:
    for f in ([t[0], t[1], t[2]], [t[0], t[1], t[3]], [t[0], t[2], t[3]], [t[1], t[2], t[3]]):
        key = tuple(sorted(f))
        faces[key] = faces.get(key, 0) + 1
boundary = np.array([f for f, n in faces.items() if n == 1])
check(len(boundary) == report["n_boundary_facets"], "boundary faces of the VTU = n_boundary_facets")
n = np.cross(points[boundary[:, 1]] - points[boundary[:, 0]], points[boundary[:, 2]] - points[boundary[:, 0]])
n /= np.linalg.norm(n, axis=1)[:, None]
worst = 0.0
for k in range(3):
    a = axes[boundary[:, k]]  # (m, 3, 3)
    c = np.abs(np.einsum("mk,mki->mi", n, a)).max(axis=1)
    worst = max(worst, np.degrees(np.arccos(np.clip(c.min(), -1, 1))))
check(worst < 1, "recomputed: each boundary face's normal is on an axis of its vertices' frames (%.3g deg)" % worst)

# the text format: the same points and frames as the VTU
tokens = open(frames).read().split()
check(tokens[:4] == ["VVMFrameField", "1", "Location", "Vertices"], "text format header")
i = tokens.index("Vertices", 4)  # the section, after "Location Vertices"
nv = int(tokens[i + 1])
xyz = np.array(tokens[i + 2:i + 2 + 3 * nv], dtype=float).reshape(nv, 3)
j = tokens.index("Frames")
nf = int(tokens[j + 1])
T = np.array(tokens[j + 2:j + 2 + 9 * nf], dtype=float).reshape(nf, 3, 3)
check(tokens[j + 2 + 9 * nf] == "End", "text format ends with End")
check(nv == len(points) and np.abs(xyz - points).max() < 1e-12, "text format: same vertices")
check(nf == nv and np.abs(T - axes).max() < 1e-12, "text format: T's columns are the VTU's axes")

# --- fandisk at about 10,000 vertices, sharp edges at 60 deg: the bounds
fjs, fsing = os.path.join(WORK, "fandisk.json"), os.path.join(WORK, "fandisk_singular.vtu")
fcurves = os.path.join(WORK, "fandisk_curves.vtu")
r = run([os.path.join(DATA, "fandisk.off"), "--features-angle", "60", "--json", fjs, "--singular", fsing,
         "--curves", fcurves])
if check(r.returncode == 0, "fandisk run exits 0"):
    f = json.loads(open(fjs).read())
    print(json.dumps(f))
    check(9000 <= f["n_vertices"] <= 11000, "fandisk: about 10000 vertices")
    check(f["n_feature_edges"] > 100, "fandisk: sharp edges found")
    check(f["boundary_alignment_error_mean_deg"] < 2, "fandisk: mean alignment error < 2 deg")
    check(f["boundary_alignment_error_p95_deg"] < 10, "fandisk: p95 alignment error < 10 deg")
    check(f["n_singular_edges"] < 0.005 * f["n_interior_edges"], "fandisk: singular edges < 0.5% of interior edges")
    check(f["vertex_alignment_error_max_deg"] < np.degrees(1e-6), "fandisk: boundary frames on their axes to 1e-6 rad")
    check(0 <= f["vertex_alignment_error_p95_deg"] <= f["vertex_alignment_error_max_deg"],
          "fandisk: vertex view p95 <= max")
    check(0 <= f["facet_normal_deviation_mean_deg"] <= f["facet_normal_deviation_p95_deg"] <= 90,
          "fandisk: facet normal deviation reported")
    check(f["smoothing_rounds"] >= 1, "fandisk: smoothing rounds reported")
    check(f["n_dead_ends"] == 0, "fandisk: no singular curve ends inside")
    check(f["n_singular_curves"] >= 1 and f["longest_singular_curve"] <= f["singular_curves_length"],
          "fandisk: singular curves reported")
    import xml.etree.ElementTree as ET
    piece = ET.parse(fcurves).getroot().find("UnstructuredGrid/Piece")
    arrays = {a.get("Name"): np.array(a.text.split(), dtype=float) for a in piece.iter("DataArray") if a.get("Name")}
    types = np.array(piece.find("Cells/DataArray[@Name='types']").text.split(), dtype=int)
    check(int(piece.get("NumberOfCells")) == f["n_singular_curves"] and (types == 4).all(),
          "curves VTU: one polyline per singular curve")
    sizes = np.diff(np.concatenate([[0], arrays["offsets"]]))
    check(int((sizes - 1).sum()) == f["n_singular_edges"], "curves VTU: the polylines hold every singular edge once")
    check(abs(arrays["length"].sum() - f["singular_curves_length"]) < 1e-6 * max(1, f["singular_curves_length"]),
          "curves VTU: lengths as in the JSON")
    check(f["solver_error"] <= 1e-6, "fandisk: the least-squares solve converged")
    check(f["boundary_alignment_error_mean_deg"] <= f["boundary_alignment_error_p95_deg"] <=
          f["boundary_alignment_error_max_deg"] <= 54.8, "fandisk: mean <= p95 <= max <= 54.7 deg")
    lines = meshio.read(fsing)
    check(len(lines.points) == f["n_vertices"], "singular edges VTU: the mesh's points")
    check(len(lines.cells_dict.get("line", [])) == f["n_singular_edges"], "singular edges VTU: one line per singular edge")
else:
    print(r.stdout, r.stderr, file=sys.stderr)

# --- a model name that needs escaping in JSON
quoted = os.path.join(WORK, 'q"uote.off')
shutil.copy(os.path.join(DATA, "cube.off"), quoted)
r = run([quoted, "--vertices", "300", "--iterations", "1"])
if check(r.returncode == 0, "quoted name: exits 0"):
    try:
        check(json.loads(r.stdout)["model"] == 'q"uote', "quoted name: the JSON model name is escaped")
    except ValueError as e:
        check(False, "quoted name: the JSON parses (%s): %s" % (e, r.stdout[:200]))
else:
    print(r.stdout, r.stderr, file=sys.stderr)

# --- bad input and options: exit code 2 and a message
bad = os.path.join(WORK, "bad")
os.makedirs(bad)
empty = os.path.join(bad, "empty.off")
open(empty, "w").close()
garbage = os.path.join(bad, "garbage.off")
open(garbage, "w").write("this is not a mesh\n")
open_surface = os.path.join(bad, "open.off")
lines = open(os.path.join(DATA, "cube.off")).read().split("\n")
# drop the last face of the cube: a hole
body = [l for l in lines if l.strip()]
header = body[1].split() if body[0].strip() == "OFF" else body[0].split()[1:]
nv_off, nf_off = int(header[0]), int(header[1])
start = 2 if body[0].strip() == "OFF" else 1
face_lines = body[start + nv_off:start + nv_off + nf_off]
open(open_surface, "w").write("OFF\n%d %d 0\n" % (nv_off, nf_off - 1) +
                              "\n".join(body[start:start + nv_off] + face_lines[:-1]) + "\n")
cube = os.path.join(DATA, "cube.off")
cases = [
    ([os.path.join(bad, "missing.off")], "cannot open"),
    ([empty], "empty"),
    ([garbage], "cannot read"),
    ([open_surface], "open"),
    ([cube, "--vertices", "0"], "--vertices"),
    ([cube, "--vertices", "-5"], "--vertices"),
    ([cube, "--vertices", "ten"], "--vertices"),
    ([cube, "--features-angle", "nan"], "--features-angle"),
    ([cube, "--features-angle", "200"], "--features-angle"),
    ([cube, "--iterations", "-1"], "--iterations"),
    ([cube, "--tolerance", "-1"], "--tolerance"),
    ([cube, "--bogus"], "unknown option"),
    ([cube, "--out"], "needs a value"),
]
for args, words in cases:
    r = run(args)
    check(r.returncode == 2, "exit code 2 for %s (got %d)" % (args, r.returncode))
    check(words in r.stderr, "message with '%s' for %s: %s" % (words, args, r.stderr.strip()[:200]))

sys.exit(check.summary())
