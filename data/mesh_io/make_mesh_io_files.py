#!/usr/bin/env python3
# Makes the files of data/mesh_io/ that test_volume_mesh_io reads (run once by hand,
# from this folder, with Debian's python3-meshio, python3-vtk9 and gmsh):
# - meshio_mixed*: the hand-made mixed mesh of the test (a hexahedron, a prism, a
#   pyramid and two tetrahedra; subdomains 3 and 7, volume entities 1, 2, 4, 5; an
#   unused point) as meshio 5 writes it: VTU compressed (its default) and ASCII, MSH 2.2 and 4.1 ASCII and binary, MEDIT;
# - vtk_mixed_*.vtu: the same mesh as VTK's vtkXMLUnstructuredGridWriter (ParaView's
#   writer) writes it: appended raw zlib with UInt64 headers (ParaView's default),
#   appended base64, inline binary, ASCII; the subdomains as CellEntityIds;
# - gmsh_tiny*: gmsh_tiny.geo meshed by Gmsh 4.8 (MSH 2.2 and 4.1, ASCII and binary,
#   and MEDIT).
# It prints what meshio reads back, the counts the test expects.
import subprocess

import meshio
import numpy as np

points = np.array([
    [0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
    [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
    [2, 0, 0], [2, 0, 1],
    [0.5, 0.5, 1.6180339887498949],
    [-0.7, 1.0 / 3.0, 0.1],
    [3.0000000000000004, -2.5e-7, 12345.678]], dtype=float)
cells = [("hexahedron", [[0, 1, 2, 3, 4, 5, 6, 7]]),
         ("wedge", [[1, 8, 2, 5, 9, 6]]),
         ("pyramid", [[4, 5, 6, 7, 10]]),
         ("tetra", [[0, 7, 3, 11], [0, 4, 7, 11]])]
physical = [[3], [7], [3], [7, 7]]
geometrical = [[1], [2], [4], [5, 5]]  # meshio 4.1: one entity per block
# the volume entity of each node, for MSH 4.1 (the unused point in entity 5)
dim_tags = np.array([[3, 1]] * 8 + [[3, 2], [3, 2], [3, 4], [3, 5], [3, 5]])
mesh = meshio.Mesh(points, cells, point_data={"gmsh:dim_tags": dim_tags}, cell_data={
    "gmsh:physical": [np.array(p, dtype=np.int32) for p in physical],
    "gmsh:geometrical": [np.array(g, dtype=np.int32) for g in geometrical]})
plain = meshio.Mesh(points, cells, cell_data={
    "gmsh:physical": [np.array(p, dtype=np.int32) for p in physical],
    "gmsh:geometrical": [np.array(g, dtype=np.int32) for g in geometrical]})

meshio.write("meshio_mixed.vtu", plain)
meshio.write("meshio_mixed_ascii.vtu", plain, binary=False)
meshio.write("meshio_mixed_22.msh", plain, file_format="gmsh22", binary=False)
meshio.write("meshio_mixed_22_binary.msh", plain, file_format="gmsh22", binary=True)
meshio.write("meshio_mixed_41.msh", mesh, file_format="gmsh", binary=False)
meshio.write("meshio_mixed_41_binary.msh", mesh, file_format="gmsh", binary=True)
medit = meshio.Mesh(points, cells, cell_data={"medit:ref": physical})
meshio.write("meshio_mixed.mesh", medit)

import vtk  # noqa: E402

grid = vtk.vtkUnstructuredGrid()
vtk_points = vtk.vtkPoints()
vtk_points.SetDataTypeToDouble()
for p in points:
    vtk_points.InsertNextPoint(*p)
grid.SetPoints(vtk_points)
vtk_types = {"hexahedron": vtk.VTK_HEXAHEDRON, "wedge": vtk.VTK_WEDGE,
             "pyramid": vtk.VTK_PYRAMID, "tetra": vtk.VTK_TETRA}
ids = vtk.vtkIntArray()
ids.SetName("CellEntityIds")
for (kind, block), tags in zip(cells, physical):
    for c, tag in zip(block, tags):
        if kind == "wedge":  # VTK's wedge order
            c = [c[0], c[2], c[1], c[3], c[5], c[4]]
        grid.InsertNextCell(vtk_types[kind], len(c), c)
        ids.InsertNextValue(tag)
grid.GetCellData().AddArray(ids)


def write_vtk(name, mode, header64, compress, encode=False):
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(name)
    w.SetInputData(grid)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended}[mode]()
    w.SetEncodeAppendedData(encode)
    if header64:
        w.SetHeaderTypeToUInt64()
    else:
        w.SetHeaderTypeToUInt32()
    if compress:
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    assert w.Write() == 1


write_vtk("vtk_mixed_appended_zlib.vtu", "appended", True, True)
write_vtk("vtk_mixed_appended_base64.vtu", "appended", False, False, encode=True)
write_vtk("vtk_mixed_binary.vtu", "binary", True, False)
write_vtk("vtk_mixed_binary_zlib.vtu", "binary", False, True)
write_vtk("vtk_mixed_ascii.vtu", "ascii", False, False)

for fmt, name in [("msh22", "gmsh_tiny_22.msh"), ("msh41", "gmsh_tiny_41.msh"), ("mesh", "gmsh_tiny.mesh")]:
    subprocess.run(["gmsh", "-3", "gmsh_tiny.geo", "-format", fmt, "-o", name], check=True,
                   stdout=subprocess.DEVNULL)
for fmt, name in [("msh22", "gmsh_tiny_22_binary.msh"), ("msh41", "gmsh_tiny_41_binary.msh")]:
    subprocess.run(["gmsh", "-3", "gmsh_tiny.geo", "-format", fmt, "-bin", "-o", name], check=True,
                   stdout=subprocess.DEVNULL)

for name in ["meshio_mixed.vtu", "meshio_mixed_ascii.vtu", "meshio_mixed_22.msh",
             "meshio_mixed_22_binary.msh", "meshio_mixed_41.msh", "meshio_mixed_41_binary.msh",
             "meshio_mixed.mesh", "vtk_mixed_appended_zlib.vtu", "vtk_mixed_appended_base64.vtu",
             "vtk_mixed_binary.vtu", "vtk_mixed_binary_zlib.vtu", "vtk_mixed_ascii.vtu",
             "gmsh_tiny_22.msh", "gmsh_tiny_22_binary.msh", "gmsh_tiny_41.msh",
             "gmsh_tiny_41_binary.msh", "gmsh_tiny.mesh"]:
    m = meshio.read(name)
    counts = {b.type: 0 for b in m.cells}
    for b in m.cells:
        counts[b.type] += len(b.data)
    tags = {}
    for key in ["gmsh:physical", "medit:ref", "CellEntityIds"]:
        if key in m.cell_data:
            tags[key] = [int(v) for b, d in zip(m.cells, m.cell_data[key])
                         if b.type in ("tetra", "hexahedron", "wedge", "pyramid") for v in d]
    print(name, len(m.points), counts, tags)
