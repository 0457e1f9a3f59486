# Copyright (c) 2026 VVM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""VVM: variational volumetric meshing for finite elements.

Tetrahedral meshes whose smallest dihedral angles are 25-30 degrees (make_mesh_3 and
GSM, Gradient-based Shape Matching), GSM on a tetrahedral mesh made by any mesher,
field-aligned BCC/FCC lattice meshes, hex-dominant meshes, and field-aligned triangle meshes of
surfaces (:func:`surface_mesh`). The same functions, options and results as the ``vvm-mesh``
program.

Surfaces are file names (OFF, OBJ, PLY, STL, ...) or ``(vertices, faces)`` pairs of
arrays; volume meshes are ``meshio.Mesh`` objects or ``(points, tetrahedra, labels)``
triples. Results are ``meshio.Mesh`` objects, one cell block per cell type and subdomain
label, with the cell data

- ``subdomain``: the label of each cell (also as ``gmsh:physical`` and ``gmsh:geometrical``,
  which meshio's Gmsh writer reads);
- ``min_dihedral_angle``: the smallest dihedral angle of each tetrahedron, in degrees
  (0 for other cells);
- ``scaled_jacobian``: the smallest scaled corner Jacobian of each cell.

Cell vertices are in meshio's order. ``mesh.info`` holds the run's report (method, times in
seconds). Bad input raises ``ValueError`` with the reason. Each function releases the GIL
while it works; ``progress=callable`` is called with a :class:`ProgressEvent` per stage and
round, and Ctrl-C stops a run at the next event (``KeyboardInterrupt``), as does an exception
raised by ``progress``. ``threads`` limits TBB for the whole process while a call runs: calls
from several Python threads at once share one limit.

Example::

    import vvm
    mesh = vvm.tet_mesh("fandisk.off", vertices=10000, features_angle=60)
    print(vvm.quality(mesh)["min_dihedral"])
    vvm.write(mesh, "fandisk.msh")   # Gmsh 4.1, one physical group per label
"""

import collections
import os
import tempfile

import numpy as np

from . import _vvm
from ._vvm import __version__

__all__ = ["tet_mesh", "hex_dominant", "surface_mesh", "optimize", "cross_field", "quality", "read", "write",
           "FrameField", "ProgressEvent", "__version__"]

ProgressEvent = collections.namedtuple("ProgressEvent", "stage fraction detail elapsed")
ProgressEvent.__doc__ = """What a run reports as it goes: the stage (e.g. ``"make_mesh_3"``, ``"gsm"``,
``"hexdom"``), the fraction done in [0, 1] (1: the stage ended; negative: unknown), a line of
detail (e.g. ``"round 3: min angle 21.4"``) and the seconds since the stage started.

Example::

    def show(event):
        print(f"{event.stage}: {event.detail} ({event.elapsed:.1f} s)")
    vvm.tet_mesh("data/fandisk.off", progress=show)
"""

# VTK cell type codes and meshio's names of the cells VVM makes and reads
_CELL_TYPES = {10: ("tetra", 4), 12: ("hexahedron", 8), 13: ("wedge", 6), 14: ("pyramid", 5)}
_CELL_CODES = {name: (code, n) for code, (name, n) in _CELL_TYPES.items()}
# meshio's cells of dimension < 3: a volume mesh file's boundary facets, edges and corners
_LOWER_DIMENSIONAL = {"vertex", "line", "line3", "triangle", "triangle6", "triangle7", "quad", "quad8", "quad9",
                      "polygon"}
# where meshio's readers put the subdomain labels, in the order they are looked for
_LABEL_KEYS = ("subdomain", "gmsh:physical", "medit:ref", "CellEntityIds", "cell_tags")
_DEFAULT_FEATURES_ANGLE = 60.0


def _meshio():
    import meshio
    return meshio


def _progress(progress):
    if progress is None:
        return None
    if not callable(progress):
        raise ValueError("progress must be callable")
    return lambda stage, fraction, detail, elapsed: progress(ProgressEvent(stage, fraction, detail, elapsed))


def _surface(surface):
    """a file name, or a (vertices, faces) pair of C-contiguous arrays"""
    if isinstance(surface, (str, os.PathLike)):
        return os.fspath(surface)
    if isinstance(surface, (tuple, list)) and len(surface) == 2:
        vertices = np.ascontiguousarray(surface[0], dtype=np.float64)
        return (vertices, _indices(surface[1], "the surface's faces"))
    raise ValueError("the surface must be a file name or a (vertices, faces) pair of arrays")


def _integer(value, name, low, high):
    """`value` as an int in [low, high], else ValueError naming `name`"""
    try:
        integral = int(value) == value
    except (TypeError, ValueError, OverflowError):
        integral = False
    if not integral or not low <= value <= high:
        raise ValueError(f"{name} must be an integer in [{low}, {high}], not {value!r}")
    return int(value)


def _size(count, size, count_name, default_count):
    """(count, size) for the front end, as vvm-mesh's --vertices/--particles N and --size H:
    size 0 or None means the count; one of the two at most"""
    if size is not None and float(size) == 0:
        size = None
    if count is not None and size is not None:
        raise ValueError(f"give {count_name} or size, not both")
    if size is not None:
        size = float(size)
        if not size > 0 or not np.isfinite(size):
            raise ValueError("the size must be positive and finite")
        return default_count, size
    if count is None:
        return default_count, 0.0
    return _integer(count, count_name, 1, 2**62), 0.0


def _threads(threads):
    """0 or None: all cores, as vvm-mesh's --threads"""
    return 0 if threads is None else _integer(threads, "threads", 0, 2**31 - 1)


def _angle(features_angle):
    return _DEFAULT_FEATURES_ANGLE if features_angle is None else float(features_angle)


def _seed(seed):
    return _integer(seed, "seed", 0, 2**32 - 1)


def _time_limit(time_limit):
    """None or 0: no limit, as vvm-mesh's --time-limit"""
    if time_limit is None:
        return 0.0
    seconds = float(time_limit)
    if not (seconds >= 0 and seconds < 1e12):
        raise ValueError("time_limit must be a non-negative number of seconds (None or 0: no limit)")
    return seconds


def _indices(array, name):
    """`array` as C-contiguous int64 indices; ValueError for non-integers and indices past int64"""
    array = np.asarray(array)
    if array.size and not np.issubdtype(array.dtype, np.integer):
        raise ValueError(f"{name} must be integer vertex indices")
    if array.size and np.issubdtype(array.dtype, np.unsignedinteger) and array.max() > 2**62:
        raise ValueError(f"{name} has a vertex index out of range ({array.max()})")
    return np.ascontiguousarray(array, dtype=np.int64)


class _Field_file:
    """the `field` argument as the front end takes it: a name or a file, written for a FrameField"""

    def __init__(self, field, default="cross"):
        self.path = None
        self._tmp = None
        if field is None:
            self.path = default
        elif isinstance(field, FrameField):
            self._tmp = tempfile.TemporaryDirectory(prefix="vvm-field-")
            self.path = os.path.join(self._tmp.name, "field.txt")
            field.write(self.path)
        elif isinstance(field, (str, os.PathLike)):
            self.path = os.fspath(field)
        else:
            raise ValueError("field must be a field's name, a frame-field file or a vvm.FrameField")

    def __enter__(self):
        return self.path

    def __exit__(self, *exc):
        if self._tmp is not None:
            self._tmp.cleanup()


def _to_meshio(arrays):
    """a meshio.Mesh of the front end's arrays: one block per cell type and label"""
    meshio = _meshio()
    types, connectivity, labels = arrays["cell_types"], arrays["connectivity"], arrays["labels"]
    quality = arrays["quality"]
    cells = []
    data = {key: [] for key in ("subdomain", "gmsh:physical", "gmsh:geometrical", *quality)}
    for code, (name, n) in _CELL_TYPES.items():
        of_type = types == code
        if not of_type.any():
            continue
        for label in np.unique(labels[of_type]):
            index = np.flatnonzero(of_type & (labels == label))
            cells.append((name, connectivity[index, :n]))
            for key in ("subdomain", "gmsh:physical", "gmsh:geometrical"):
                data[key].append(labels[index])
            for key, values in quality.items():
                data[key].append(values[index])
    mesh = meshio.Mesh(arrays["points"], cells, cell_data=data)
    mesh.info = dict(arrays.get("report", {}))
    return mesh


def _from_mesh(mesh):
    """(points, cell_types, connectivity, labels) of a meshio.Mesh or a (points, cells, labels) triple"""
    if isinstance(mesh, (tuple, list)):
        if len(mesh) != 3:
            raise ValueError("a mesh must be a meshio.Mesh or a (points, tetrahedra, labels) triple")
        points, cells, labels = mesh
        cells = np.asarray(cells)
        if cells.ndim != 2 or cells.shape[1] != 4:
            raise ValueError("the tetrahedra of a (points, tetrahedra, labels) triple must be of shape (m, 4)")
        blocks = [("tetra", cells, None if labels is None else np.asarray(labels))]
    elif hasattr(mesh, "points") and hasattr(mesh, "cells"):
        points = mesh.points
        label_key = next((key for key in _LABEL_KEYS if key in mesh.cell_data), None)
        blocks = []
        for i, block in enumerate(mesh.cells):
            if block.type in _LOWER_DIMENSIONAL:
                continue
            if block.type not in _CELL_CODES:
                raise ValueError(f"cells of type '{block.type}' are not supported "
                                 "(tetra, hexahedron, wedge and pyramid are)")
            blocks.append((block.type, block.data, None if label_key is None else mesh.cell_data[label_key][i]))
    else:
        raise ValueError("a mesh must be a meshio.Mesh or a (points, tetrahedra, labels) triple")
    points = np.ascontiguousarray(points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError("the points must be of shape (n, 3)")
    if not blocks:
        raise ValueError("the mesh has no volume cell")
    types, connectivity, all_labels = [], [], []
    for name, data, labels in blocks:
        code, n = _CELL_CODES[name]
        data = _indices(data, f"the {name} cells")
        if data.ndim != 2 or data.shape[1] != n:
            raise ValueError(f"the {name} cells must be integer arrays of shape (m, {n})")
        padded = np.full((len(data), 8), -1, dtype=np.int64)
        padded[:, :n] = data
        connectivity.append(padded)
        types.append(np.full(len(data), code, dtype=np.int64))
        if labels is None:
            labels = np.ones(len(data), dtype=np.int64)
        labels = np.asarray(labels).reshape(-1)
        if len(labels) != len(data):
            raise ValueError(f"{len(labels)} labels for {len(data)} {name} cells")
        if labels.size and not np.issubdtype(labels.dtype, np.integer):
            if not np.issubdtype(labels.dtype, np.floating) or not np.all(np.isfinite(labels)) \
                    or not np.all(labels == np.round(labels)):
                raise ValueError("the labels must be integers")
        if labels.size and (labels.min() < -2**31 or labels.max() >= 2**31):
            raise ValueError("the labels must fit in 32 bits")
        all_labels.append(labels.astype(np.int64))
    if sum(len(t) for t in types) == 0:
        raise ValueError("the mesh has no volume cell")
    return (points, np.concatenate(types), np.concatenate(connectivity), np.concatenate(all_labels))


def tet_mesh(surface, method="gsm", vertices=None, size=None, features_angle=None, field=None, threads=None, seed=0,
             progress=None, time_limit=None, sizing="uniform"):
    """A tetrahedral mesh of a closed surface or a labelled 3D image.

    ``surface``: a file (OFF, OBJ, PLY, STL, ...; or a labelled image, .inr / .inr.gz, each
    label a subdomain), or a ``(vertices, faces)`` pair: an (n, 3) float array and an (m, k)
    index array (k >= 3) of a closed, oriented, manifold surface.
    ``method``: ``"gsm"`` (make_mesh_3, then GSM), ``"odt+gsm"``, ``"perturb+exude"`` (CGAL's
    own optimizers), ``"bcc"`` or ``"fcc"`` (a lattice mesh aligned with ``field``).
    ``vertices`` (default 10000; make_mesh_3's size is searched to within 5%) or ``size``
    (the edge length). ``features_angle``: surface edges sharper than this (degrees, default
    60) are kept as feature curves; 0 keeps none. ``field``: ``"cross"`` (the
    boundary-aligned cross field), ``"identity"``, a frame-field file or a
    :class:`FrameField`; for lattices, and GSM's target metric when a file or FrameField.
    ``sizing``: ``"uniform"``, or ``"thickness"``: the size follows the surface's walls, gaps and
    the faces between its protected feature curves (``features_angle``), three cells across, growing away from them by at most 0.3 times the distance (surfaces
    only); ``size`` is then its median over the surface, ``vertices`` still the count; for
    lattices it scales the field's frames.
    ``threads``: None or 0 for all cores. ``seed``: the same seed and threads give the same mesh.
    ``time_limit``: seconds of the optimizer (or the lattice), None for none: it stops with a
    valid mesh and ``mesh.info["time_limit_reached"]`` true (make_mesh_3 is not counted).

    Returns a ``meshio.Mesh``. Raises ``ValueError`` on bad input (open, self-intersecting
    or non-manifold surfaces, NaN, unknown method, bad sizes).

    Example::

        mesh = vvm.tet_mesh("data/fandisk.off", vertices=5000)
        mesh.write("fandisk.vtu")
    """
    count, edge = _size(vertices, size, "vertices", 10000)
    source = _surface(surface)
    with _Field_file(field) as field_path:
        arrays = _vvm.tet_mesh(source, str(method), count, edge, _angle(features_angle), field_path, str(sizing),
                               _threads(threads), _seed(seed), _time_limit(time_limit), _progress(progress))
    return _to_meshio(arrays)


def hex_dominant(surface, particles=None, size=None, q_bound=0.5, boundary_distance=0.0, features_angle=None,
                 field=None, threads=None, seed=0, progress=None, time_limit=None, sizing="uniform",
                 maximum_size_ratio=2.0):
    """A hex-dominant mesh of a closed surface: hexahedra, prisms, pyramids and tetrahedra.

    Particles form a cubic lattice aligned with ``field`` (default the boundary-aligned cross
    field), are connected into tetrahedra, and these are merged greedily into hexahedra,
    prisms and pyramids whose quality is at least ``q_bound`` (in [0, 1]).
    ``particles`` (default 30000) or ``size`` (the lattice's edge length);
    ``boundary_distance``: the boundary refinement's distance (0: none). ``surface``,
    ``features_angle``, ``field``, ``sizing``, ``threads``, ``seed``, ``progress`` as in :func:`tet_mesh`.
    With ``sizing="thickness"`` the cubic lattice breaks into non-hex cells where its size changes:
    parts with walls of very different thicknesses get far fewer hexahedra.
    ``maximum_size_ratio``: the cross field's scales are corrected so that the lattice's layers
    follow its turning, within this ratio of each other (at least 1; 1: no correction).
    ``time_limit``: seconds (field, particles, merging), None for none: the tets not merged by
    then stay tetrahedra and ``mesh.info["time_limit_reached"]`` is true.

    Returns a ``meshio.Mesh`` with hexahedron, wedge, pyramid and tetra blocks.

    Example::

        mesh = vvm.hex_dominant("data/cube.off", particles=2000)
        print(vvm.quality(mesh)["hex_volume_percent"])
    """
    count, edge = _size(particles, size, "particles", 30000)
    source = _surface(surface)
    with _Field_file(field) as field_path:
        arrays = _vvm.hex_dominant(source, count, edge, float(q_bound), float(boundary_distance),
                                   _angle(features_angle), field_path, str(sizing), float(maximum_size_ratio),
                                   _threads(threads), _seed(seed), _time_limit(time_limit), _progress(progress))
    return _to_meshio(arrays)


def surface_mesh(surface, vertices=None, size=None, field="curvature", maximum_anisotropy=3.0, maximum_size_ratio=4.0,
                 features_angle=None, threads=None, seed=0, progress=None, time_limit=None):
    """A triangle mesh of a triangle surface, open or closed, whose vertices form a hexagonal
    lattice aligned with a tangent frame field (``vvm-mesh surface``).

    ``surface``: a file (OFF, OBJ, PLY, STL, ...) or a ``(vertices, faces)`` pair: an (n, 3)
    float array and an (m, 3) index array. ``vertices`` (default 10000; within about 5%) or
    ``size`` (the lattice's edge length in the field's metric). ``field``: ``"curvature"`` (the
    principal curvature directions, edges 1/sqrt|k| long), ``"isotropic"`` (the same
    directions, one length), ``"identity"`` (the x axis projected, one length everywhere), or a
    frame-field file or :class:`FrameField`: a frame per vertex of the surface (no tetrahedra;
    the columns of each frame the two tangent axes and the normal) or a volume field (such as
    :func:`cross_field` gives), of whose axes the two nearest to the tangent plane are kept;
    ``maximum_anisotropy`` (curvature: the largest ratio of a frame's two lengths, >= 1) and
    ``maximum_size_ratio`` (the largest ratio of two lengths, >= 1) bound it. Edges sharper
    than ``features_angle`` (degrees, default 60; 0: none) and the borders are kept.
    ``threads``, ``seed``, ``progress`` as in :func:`tet_mesh`;
    ``time_limit``: seconds of the particles, None for none (``mesh.info["time_limit_reached"]``).

    Returns a ``meshio.Mesh`` with one ``triangle`` block; ``mesh.info`` holds the run's report
    and, as ``mesh.info["quality"]``, the quality in the field's metric: ``vertices``,
    ``faces``, ``r6`` (the share of degree-6 vertices off the borders and sharp edges),
    ``xi_mean``, ``xi_min`` (4 sqrt(3) area / (perimeter x longest edge), 1 for equilateral),
    ``min_angle``, ``mean_min_angle`` (degrees), ``alignment_error_mean`` (degrees off the
    lattice's directions) and ``is_closed_manifold``. Raises ``ValueError`` on bad input (no
    face, faces that are not triangles, NaN, an unknown field, bad sizes).

    Example::

        mesh = vvm.surface_mesh("data/surfaces/torus.off", vertices=3000)
        print(mesh.info["quality"]["r6"])
        mesh.write("torus_lattice.off")
    """
    count, edge = _size(vertices, size, "vertices", 10000)
    with _Field_file(field, "curvature") as field_path:
        arrays = _vvm.surface_mesh(_surface(surface), count, edge, field_path, float(maximum_anisotropy),
                                   float(maximum_size_ratio), _angle(features_angle), _threads(threads), _seed(seed),
                                   _time_limit(time_limit), _progress(progress))
    mesh = _meshio().Mesh(arrays["points"], [("triangle", arrays["triangles"])])
    mesh.info = dict(arrays["report"], quality=arrays["quality"])
    return mesh


def optimize(mesh, features_angle=None, fixed_boundary=False, boundary_distance=None, threads=None, seed=0,
             progress=None, time_limit=None):
    """GSM on a tetrahedral mesh made by any mesher (TetGen, Gmsh, ...): its slivers removed
    without re-meshing.

    ``mesh``: a ``meshio.Mesh`` (its tetra blocks; lower-dimensional blocks are ignored;
    labels from the cell data ``subdomain``, ``gmsh:physical``, ``medit:ref``,
    ``CellEntityIds`` or ``cell_tags``, else 1) or a ``(points, tetrahedra, labels)`` triple
    (``labels`` may be None). The boundary and the facets between different labels are the
    surfaces boundary vertices slide on; edges of these sharper than ``features_angle``
    (default 60 degrees; 0: none) are kept. ``fixed_boundary``: only interior vertices move.
    ``boundary_distance``: how far the boundary may stray from the input's (None: 1% of the
    mean boundary edge length; 0: boundary vertices slide on flat parts only).
    ``time_limit``: seconds of GSM, None for none (``mesh.info["time_limit_reached"]``).

    Returns a ``meshio.Mesh`` with the labels kept; ``mesh.info`` has the boundary's
    two-sided distance to the input's (``boundary_hausdorff``). Raises ``ValueError`` for
    inverted or flat cells, non-manifold boundaries, cells other than tetrahedra.

    (meshio reads MEDIT files of version 1 in single precision; :func:`read` reads them in
    double.)

    Example::

        import meshio
        tetgen_mesh = meshio.read("part.1.mesh")
        better = vvm.optimize(tetgen_mesh)
    """
    points, types, connectivity, labels = _from_mesh(mesh)
    distance = -1.0 if boundary_distance is None else float(boundary_distance)
    if boundary_distance is not None and not distance >= 0:
        raise ValueError("boundary_distance must be non-negative (None: 1% of the mean boundary edge)")
    arrays = _vvm.optimize(points, types, connectivity, labels, _angle(features_angle), bool(fixed_boundary),
                           distance, _threads(threads), _seed(seed), _time_limit(time_limit), _progress(progress))
    return _to_meshio(arrays)


class FrameField:
    """A frame field on a tetrahedral mesh: at each vertex (or cell) a 3x3 matrix T whose
    columns are the lattice's axes (their lengths the edge lengths). With no tetrahedra (an
    (0, 4) array) and a frame per vertex, a field at points, such as the vertices of a surface
    for :func:`surface_mesh` (columns: the two tangent axes and the normal).

    Attributes: ``points`` (n, 3), ``tetrahedra`` (m, 4), ``frames`` (n or m, 3, 3) and
    ``location`` (``"vertices"`` or ``"cells"``).

    Example::

        field = vvm.cross_field("data/fandisk.off", vertices=3000)
        field.write("fandisk.field")
        mesh = vvm.tet_mesh("data/fandisk.off", method="bcc", field=field)
    """

    def __init__(self, points, tetrahedra, frames, location="vertices"):
        self.points = np.ascontiguousarray(points, dtype=np.float64)
        self.tetrahedra = np.ascontiguousarray(tetrahedra, dtype=np.int64)
        self.frames = np.ascontiguousarray(frames, dtype=np.float64)
        self.location = location
        self.report = {}

    def to_text(self):
        """the field in VVM's frame-field text format; ValueError if it is not a valid field"""
        return _vvm.frame_field_text(self.points, self.tetrahedra, self.frames, self.location)

    def write(self, path):
        """writes the field in the frame-field text format (the file ``vvm-mesh --field`` reads)"""
        text = self.to_text()
        with open(path, "w") as f:
            f.write(text)

    @classmethod
    def read(cls, path):
        """the field in the frame-field text file ``path``"""
        with open(path) as f:
            return cls._of(_vvm.frame_field_from_text(f.read()))

    @classmethod
    def _of(cls, d):
        field = cls(d["points"], d["tetrahedra"], d["frames"], d["location"])
        field.report = dict(d.get("report", {}))
        return field

    def to_meshio(self):
        """a ``meshio.Mesh`` of the carrier tetrahedra with the frames as ``frame`` point or cell data
        (3x3 each)"""
        meshio = _meshio()
        flat = self.frames.reshape(len(self.frames), 9)
        if self.location == "cells":
            return meshio.Mesh(self.points, [("tetra", self.tetrahedra)], cell_data={"frame": [flat]})
        return meshio.Mesh(self.points, [("tetra", self.tetrahedra)], point_data={"frame": flat})


def cross_field(surface, vertices=None, size=None, features_angle=None, seed=0, progress=None, time_limit=None):
    """The boundary-aligned cross field of a closed surface (what ``vvm-mesh field`` writes),
    on a make_mesh_3 mesh of ``vertices`` (default 10000) or of edge length ``size``.
    ``time_limit``: seconds of its smoothing, None for none (``field.report["time_limit_reached"]``).

    Returns a :class:`FrameField`, which ``tet_mesh`` and ``hex_dominant`` take as ``field``.

    Example::

        field = vvm.cross_field("data/fandisk.off", vertices=3000)
        print(field.frames.shape)
    """
    count, edge = _size(vertices, size, "vertices", 10000)
    return FrameField._of(_vvm.cross_field(_surface(surface), count, edge, _angle(features_angle), _seed(seed),
                                           _time_limit(time_limit), _progress(progress)))


def quality(mesh):
    """The quality table of a tetrahedral or hex-dominant mesh (a ``meshio.Mesh`` or a
    ``(points, tetrahedra, labels)`` triple) as a dict: counts (``vertices``, ``cells``,
    ``tetrahedra``, ``hexahedra``, ``prisms``, ``pyramids``, ``inverted``), ``labels``; for
    tetrahedra ``min_dihedral``, ``max_dihedral``, ``mean_min_dihedral`` (degrees),
    ``tets_under`` ({10: n, 20: n, 30: n, 40: n}, by smallest dihedral angle),
    ``min_radius_ratio``, ``mean_radius_ratio``, ``min_dihedral_histogram`` (18 bins of 10
    degrees); and ``hex_volume_percent``, ``min_scaled_jacobian``, ``mean_hex_scaled_jacobian``.

    Example::

        q = vvm.quality(meshio.read("part.msh"))
        print(q["min_dihedral"], q["tets_under"][30])
    """
    return _vvm.quality(*_from_mesh(mesh))


def read(path):
    """The volume mesh in ``path`` (MEDIT .mesh, Gmsh .msh 2.2 or 4.1, .vtu) as a ``meshio.Mesh``,
    read by VVM's readers (those of ``vvm-mesh``): labels from physical groups, references or
    a cell array.

    Example::

        mesh = vvm.read("part.msh")
    """
    return _to_meshio(_vvm.read(os.fspath(path)))


def write(mesh, path):
    """Writes ``mesh`` by the extension of ``path`` (as ``vvm-mesh`` does): ``.mesh`` (MEDIT),
    ``.msh`` (Gmsh 4.1, one physical group per label) or ``.vtu`` (with the quality arrays),
    through a temporary file renamed at the end.

    (meshio's own ``mesh.write("x.msh")`` writes ANSYS's .msh format; for Gmsh use this
    function, or ``file_format="gmsh22"`` with meshio.)

    Example::

        vvm.write(vvm.tet_mesh("data/fandisk.off"), "fandisk.msh")
    """
    _vvm.write(*_from_mesh(mesh), os.fspath(path))
