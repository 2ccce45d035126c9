"""gab: mesh compression with geometry-aware bases, and the sparse Cholesky
engine behind it, from Python (ctypes over libgab's C API, gab.h; numpy
arrays in and out).

    import gab
    V, F = gab.read_mesh("bunny.off")        # (n, 3) float64, (t, 3) int32
    data, stats = gab.compress(V, F, error=1e-3, return_stats=True)  # bytes: a .gab file
    W, G = gab.decompress(data)              # in traversal order: W[stats.order] lines up with V
    V1, _ = gab.decompress(data, anchors=100)  # a coarser level: the first 100 anchors
    data = gab.compress(V, F, reorder=False) # the input's numbering kept (priced: stats.order_bytes)
    V2, F2 = gab.decompress(data)            # V2 lines up with V, within the target

    V, F, attrs = gab.read_mesh("spider.obj", return_attributes=True)  # [gab.Attribute('normal', ...), ...]
    data = gab.compress(V, F, attributes=attrs, normal_bits=10)         # each coded in its own section
    W, G, decoded = gab.decompress(data, return_attributes=True)        # in the decoded numbering
    gab.write_mesh("out.ply", W, G, attributes=decoded)

    chol = gab.Cholesky(A)                   # A: scipy.sparse (any format), dense, or (indptr, indices, data);
    x = chol.solve(b)                        #    symmetric or its lower triangle
    chol = gab.Cholesky(A, ordering="nd", threads=0)  # another ordering, every core
    chol.add_anchor(j, w)                    # now the factor of A + w^2 e_j e_j^T

Every failure of the library raises GabError with its message; a file cut
short decodes to its complete chunks with a TruncatedWarning; what a call
does not give back (a mesh file's data gab does not carry, attributes
without return_attributes=True, sections a level of detail cannot decode)
is named by a DroppedDataWarning; a bad argument raises TypeError or
ValueError naming the call and the argument.
"""

import ctypes
import dataclasses
import os
import sys
import warnings


def _numpy_missing(error):
    """The ImportError text when numpy cannot be imported: which interpreter
    this is, which one gab was installed for, and how to get numpy."""
    installed_for = ""
    try:
        from . import _location

        installed_for = getattr(_location, "PYTHON", "")
    except ImportError:
        pass
    text = (f"gab needs numpy, and this interpreter, {sys.executable} (Python {sys.version_info[0]}."
            f"{sys.version_info[1]}), cannot import it: {error}.")
    install = (f"install numpy for this one ({sys.executable} -m pip install numpy; apt-get install python3-numpy "
               "for Debian's /usr/bin/python3)")
    if installed_for and os.path.realpath(installed_for) != os.path.realpath(sys.executable):
        return text + f" gab was installed for {installed_for}: run that one, or {install}"
    return text + " I" + install[1:]


try:
    import numpy as np
except ImportError as _error:
    raise ImportError(_numpy_missing(_error)) from _error

from ._capi import (  # noqa: E402 (after numpy's check, so its message comes first)
    GAB_W_TRUNCATED,
    LIB,
    Attribute as _CAttribute,
    CholeskyOptions,
    CompressOptions,
    CompressReport,
    DecompressOptions,
    DroppedDataWarning,
    GabError,
    TruncatedWarning,
    check,
    message_buffer,
)

__all__ = ["Attribute", "AttributeStats", "Cholesky", "CompressStats", "DroppedDataWarning", "GabError",
           "TruncatedWarning", "compress", "decompress", "read_mesh", "version", "write_mesh"]

_DETAIL = {"auto": 0, "on": 1, "off": 2}
_SOLVER_NAMES = {1: "global", 2: "iterative"}  # GAB_SOLVER_*
_ORDERING_NAMES = {1: "amd", 2: "nd"}  # GAB_ORDERING_*
_CODEC_ORDERINGS = ["auto", "amd", "nd"]  # what the codec factors with (gab.h: GAB_ORDERING_*)
_CHOLESKY_ORDERINGS = ["amd", "nd", "natural", "auto"]  # the engine's, gab factor's default first
_MAX_THREADS = 64  # gab.h: threads 0..64 (0: every core)
_DEFAULT_ERROR = 1e-3
_GAB_E_STATE = 9


def version():
    """The library's version string, as gab_version() (and gab --version)."""
    return LIB.gab_version().decode()


__version__ = version()


# The argument checks: each message starts with the Python call and names
# the argument ("gab.compress: error must be a number, got str").

def _array(call, values, dtype, name, columns=None):
    """values as a C-contiguous array of dtype; with columns, of shape (k, columns)."""
    a = np.ascontiguousarray(values, dtype=dtype)
    if columns is not None and (a.ndim != 2 or a.shape[1] != columns):
        raise ValueError(f"{call}: {name} must have shape (k, {columns}), got {a.shape}")
    return a


def _int32(call, values, name, columns=None):
    """values as int32: integers only (floats are not truncated), each within int32."""
    a = np.asarray(values)
    if a.size and a.dtype.kind not in "iu":
        raise TypeError(f"{call}: {name} must hold integers, got dtype {a.dtype}")
    if a.size and (a.max() > np.iinfo(np.int32).max or a.min() < np.iinfo(np.int32).min):
        raise ValueError(f"{call}: {name} has entries beyond int32")
    return _array(call, a, np.int32, name, columns)


def _reals(call, values, name, columns=None):
    """values as float64: real numbers only (no complex, no strings)."""
    a = np.asarray(values)
    if a.size and a.dtype.kind not in "iuf":
        raise TypeError(f"{call}: {name} must hold real numbers, got dtype {a.dtype}")
    return _array(call, a, np.float64, name, columns)


def _int_arg(call, value, name, low, high=np.iinfo(np.int32).max):
    """An integer argument within [low, high] (the C type's range at most)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{call}: {name} must be an integer, got {type(value).__name__}")
    if not low <= int(value) <= high:
        raise ValueError(f"{call}: {name} must be in {low}..{high}, got {value}")
    return int(value)


def _real_arg(call, value, name):
    """A real-number argument (no strings, no complex)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{call}: {name} must be a number, got {type(value).__name__}")
    return float(value)


def _bool_arg(call, value, name):
    """A yes/no argument: True or False (a string such as 'no' is not False)."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{call}: {name} must be True or False, got {type(value).__name__}")
    return bool(value)


def _name_arg(call, value, name, names):
    """One of the names (strings) an argument takes."""
    spelled = ", ".join(repr(n) for n in names[:-1]) + f" or {names[-1]!r}"
    if not isinstance(value, str):
        raise TypeError(f"{call}: {name} must be {spelled}, got {type(value).__name__}")
    if value not in names:
        raise ValueError(f"{call}: {name} must be {spelled}, got {value!r}")
    return value


def _take_mesh(positions, n, triangles, t):
    """Copies the library's arrays into numpy and frees them."""
    try:
        V = np.ctypeslib.as_array(positions, shape=(n.value, 3)).copy()
        F = np.ctypeslib.as_array(triangles, shape=(t.value, 3)).copy()
    finally:
        LIB.gab_free(positions)
        LIB.gab_free(triangles)
    return V, F


def _mesh_outputs():
    return ctypes.POINTER(ctypes.c_double)(), ctypes.c_int32(), ctypes.POINTER(ctypes.c_int32)(), ctypes.c_int32()


# Attributes: gab.h's gab_attribute as numpy arrays.

_KINDS = ["normal", "texcoord", "color", "generic"]  # GAB_ATTRIBUTE_*, by code
_COMPONENTS = {"normal": (3,), "texcoord": (2, 3), "color": (3, 4), "generic": (1, 2, 3, 4)}
_VALUE_TYPES = ["int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"]  # GAB_VALUE_*
_LABELS = {"normal": "normals", "texcoord": "texture_coordinates", "color": "vertex_colors"}
_MAX_ATTRIBUTES = 64  # GAB_MAX_ATTRIBUTES
_MAX_NORMAL_BITS = 16
_MAX_GRID_BITS = 31


@dataclasses.dataclass(eq=False)
class Attribute:
    """One attribute of a mesh of n vertices and t triangles, as compress,
    write_mesh take it and read_mesh, decompress return it
    (return_attributes=True).

    kind: 'normal' (3 components, any length: the codec codes the
    direction), 'texcoord' (2 or 3), 'color' (3 or 4: 0..255 when
    integer-typed, else as given, 0..1) or 'generic' (1 to 4, named).
    values: (k, components) real numbers, one row an element (a 1-D array is
    one component); per vertex (corners None) k = n, in vertex order.
    corners: None, or (t, 3) integers in 0..k-1, row f the elements of
    triangle F[f]'s corners (per corner: where a vertex has several texture
    coordinates or normals, a seam). name: a generic's (1 to 255 letters,
    digits, '_', '-' or '.'), None for the other kinds. value_type: how the
    source stored the values, one of 'int8', 'uint8', 'int16', 'uint16',
    'int32', 'uint32', 'float32', 'float64'; integer-typed values are coded
    exactly (each must be an integer of the type's range), the others
    quantized (compress's *_bits). None: the values' numpy dtype when it is
    one of those (a uint8 array: 'uint8'; a list of floats: 'float64'), an
    integer of another width as 'int32' or 'uint32' (a list of ints: the
    library then checks each fits), else 'float32' (what OBJ and OFF text
    is).

    Returned ones hold float64 values (integers exact whatever the type),
    int32 corners, a str name for a generic (None otherwise) and their
    value_type."""

    kind: str
    values: object
    corners: object = None
    name: object = None
    value_type: object = None

    @property
    def label(self):
        """'normals', 'texture_coordinates', 'vertex_colors' or 'generic:NAME': the CLI's and the stats' name."""
        return _LABELS.get(self.kind, f"generic:{self.name}")

    @property
    def per_corner(self):
        return self.corners is not None


@dataclasses.dataclass(frozen=True, eq=False)
class AttributeStats:
    """One attribute as compress coded it (CompressStats.attributes, in the
    order given)."""

    label: str  # 'normals', 'texture_coordinates', 'vertex_colors' or 'generic:NAME'
    kind: str  # 'normal', 'texcoord', 'color' or 'generic'
    bits: int  # its quantization's (integer-typed: the span's; exact)
    per_corner: bool  # coded per corner, with seams; False: one value per vertex
    from_surface: bool  # normals predicted from the decoded surface (a level of detail then skips them)
    elements: int  # values coded: vertices, or per corner the wedges of corners sharing one
    bytes: int  # its section with its framing
    max_error: float  # the largest error of a decoded value: degrees for normals, value units otherwise


def _value_type_of(dtype):
    """An Attribute's value type when not given: the values' dtype when it
    is one of gab's, an integer of another width as int32 or uint32, else
    float32."""
    if dtype.name in _VALUE_TYPES:
        return dtype.name
    if dtype.kind in "iu":
        return "int32" if dtype.kind == "i" else "uint32"
    return "float32"


def _attributes_arg(call, attributes, n, t):
    """The attributes argument as a ctypes array of gab_attribute (None: no
    attributes) and the numpy arrays it points into (kept alive by the
    caller for the call). Each field is checked here, naming it; the library
    checks the values (finite, integers of their type) and a name's
    spelling."""
    if attributes is None:
        return None, []
    if not isinstance(attributes, (list, tuple)):
        raise TypeError(f"{call}: attributes must be a list of gab.Attribute, got {type(attributes).__name__}")
    if len(attributes) > _MAX_ATTRIBUTES:
        raise ValueError(f"{call}: attributes holds {len(attributes)}: at most {_MAX_ATTRIBUTES}")
    structs = (_CAttribute * max(1, len(attributes)))()
    kept = []
    for i, a in enumerate(attributes):
        where = f"attributes[{i}]"
        if not isinstance(a, Attribute):
            raise TypeError(f"{call}: {where} must be a gab.Attribute, got {type(a).__name__}")
        kind = _name_arg(call, a.kind, f"{where}.kind", _KINDS)
        given = np.asarray(a.values)
        if given.size and given.dtype.kind not in "iuf":
            raise TypeError(f"{call}: {where}.values must hold real numbers, got dtype {given.dtype}")
        if a.value_type is None:
            value_type = _value_type_of(given.dtype)
        else:
            value_type = _name_arg(call, a.value_type, f"{where}.value_type", _VALUE_TYPES)
        values = np.ascontiguousarray(given, dtype=np.float64)
        if values.ndim == 1:
            values = values.reshape(-1, 1)
        if values.ndim != 2 or values.shape[1] not in _COMPONENTS[kind]:
            spelled = " or ".join(str(c) for c in _COMPONENTS[kind])
            raise ValueError(f"{call}: {where}.values must have shape (k, {spelled}) for a {kind!r} attribute, got "
                             f"{given.shape}")
        elements = values.shape[0]
        corners = None
        if a.corners is None:
            if elements != n:
                raise ValueError(f"{call}: {where}.values has {elements} rows: per vertex (corners=None) one a "
                                 f"vertex, n = {n}")
        else:
            corners = _int32(call, a.corners, f"{where}.corners", 3)
            if corners.shape[0] != t:
                raise ValueError(f"{call}: {where}.corners must have shape (t, 3) = ({t}, 3), got {corners.shape}")
            outside = np.flatnonzero((corners < 0) | (corners >= elements))
            if outside.size:
                row, column = divmod(int(outside[0]), 3)
                raise ValueError(f"{call}: {where}.corners[{row}, {column}] is {corners[row, column]}: out of range "
                                 f"[0, {elements})")
        if a.name is not None and not isinstance(a.name, str):
            raise TypeError(f"{call}: {where}.name must be a str or None, got {type(a.name).__name__}")
        if kind == "generic" and not a.name:
            raise ValueError(f"{call}: {where}.name must name a 'generic' attribute, got {a.name!r}")
        if kind != "generic" and a.name:
            raise ValueError(f"{call}: {where}.name is {a.name!r}: only a 'generic' attribute has a name")
        name = a.name.encode() if kind == "generic" else None
        s = structs[i]
        s.kind = _KINDS.index(kind)
        s.value_type = _VALUE_TYPES.index(value_type)
        s.components = values.shape[1]
        s.elements = elements
        s.name = name
        s.values = values.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        s.corners = None if corners is None else corners.ctypes.data_as(ctypes.POINTER(ctypes.c_int32))
        kept += [values, corners, name]
    return structs, kept


def _take_attributes(pointer, count, t):
    """Copies the library's attribute block into a list of Attribute and frees it."""
    try:
        taken = []
        for i in range(count.value):
            a = pointer[i]
            values = np.ctypeslib.as_array(a.values, shape=(a.elements, a.components)).copy()
            corners = np.ctypeslib.as_array(a.corners, shape=(t, 3)).copy() if a.corners else None
            kind = _KINDS[a.kind]
            taken.append(Attribute(kind=kind, values=values, corners=corners,
                                   name=a.name.decode() if kind == "generic" else None,
                                   value_type=_VALUE_TYPES[a.value_type]))
    finally:
        LIB.gab_free(pointer)
    return taken


def _attribute_outputs():
    return ctypes.POINTER(_CAttribute)(), ctypes.c_int32()


def _describe(attributes):
    """'762 normals (per corner), 12 generic:quality (per vertex)': what a call read and does not return."""
    return ", ".join(f"{len(a.values)} {a.label} ({'per corner' if a.per_corner else 'per vertex'})"
                     for a in attributes)


def _library_text(message):
    """The library's message without its C function's name."""
    return message.value.decode(errors="replace").partition(": ")[2]


def read_mesh(path, return_attributes=False):
    """Reads an .obj, .off or .ply file: (V, F), V (n, 3) float64, F (t, 3)
    int32 (polygons fan-triangulated); with return_attributes=True (V, F,
    attributes), a list of gab.Attribute in the file's order: OBJ vn and vt
    per corner and v colours, PLY normals, texture coordinates, colours and
    every other vertex property as a named generic, OFF's N, C and ST forms
    (docs/cli.md). When the file held more than what is returned, a
    DroppedDataWarning names it: data gab does not carry (materials, groups,
    polygons' arity, ...: "not carried") and, without return_attributes,
    the attributes read ("not returned")."""
    call = "gab.read_mesh"
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise TypeError(f"{call}: path must be a str, bytes or os.PathLike, got {type(path).__name__}")
    return_attributes = _bool_arg(call, return_attributes, "return_attributes")
    positions, n, triangles, t = _mesh_outputs()
    attributes, count = _attribute_outputs()
    message = message_buffer()
    code = LIB.gab_read_mesh_with_attributes(os.fsencode(path), ctypes.byref(positions), ctypes.byref(n),
                                             ctypes.byref(triangles), ctypes.byref(t), ctypes.byref(attributes),
                                             ctypes.byref(count), message, len(message))
    check(code, message)
    read = _take_attributes(attributes, count, t.value)
    V, F = _take_mesh(positions, n, triangles, t)
    text = _library_text(message)  # "PATH: not carried: ..." or ""
    if read and not return_attributes:
        text = (text + ";" if text else os.fsdecode(path) + ":") + \
            f" not returned: {_describe(read)}; read_mesh(..., return_attributes=True) returns them"
    if text:
        warnings.warn(DroppedDataWarning(text), stacklevel=2)
    return (V, F, read) if return_attributes else (V, F)


def write_mesh(path, V, F, attributes=None):
    """Writes a mesh atomically in the format of the path's extension (.obj,
    .off or .ply: binary, double coordinates) with its attributes (a list
    of gab.Attribute, as compress takes them) in the format's spelling and
    their value types. PLY and OFF hold one value per vertex: vertices where
    per-corner attributes have seams are split. What the format cannot hold
    (generic attributes in OBJ and OFF, ...) and the vertices split are
    named by a DroppedDataWarning."""
    call = "gab.write_mesh"
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise TypeError(f"{call}: path must be a str, bytes or os.PathLike, got {type(path).__name__}")
    V = _reals(call, V, "V", 3)
    F = _int32(call, F, "F", 3)
    structs, kept = _attributes_arg(call, attributes, V.shape[0], F.shape[0])
    message = message_buffer()
    code = LIB.gab_write_mesh(os.fsencode(path), V.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), V.shape[0],
                              F.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), F.shape[0], structs,
                              len(attributes or ()), message, len(message))
    del kept
    check(code, message)
    if message.value:
        warnings.warn(DroppedDataWarning(_library_text(message)), stacklevel=2)


@dataclasses.dataclass(frozen=True, eq=False)
class CompressStats:
    """What compress(..., return_stats=True) made: the figures `gab compress
    --json` prints, under its key names and in its units (docs/cli.md;
    dataclasses.asdict(stats) gives them as a dict), and the map of a
    renumbered decode. Errors are relative to the input's bounding-box
    diagonal; byte counts include each part's framing, and bytes =
    geometry_bytes + connectivity_bytes + order_bytes + attribute_bytes.

    order: with reorder=True (the default), an (n,) int32 array, order[i]
    the decoded mesh's index of input vertex i (what `gab compress
    --order-out` writes): W[order] lines up with V, and per-vertex data moves
    onto the decoded mesh by data_decoded[order] = data. None when the
    numbering is kept (reorder=False). Its n + merged_vertices entries are
    the input's vertices: copies of a vertex at the same position (a mesh
    split along seams, a triangle soup) map onto one.

    attributes: a tuple of gab.AttributeStats, one per attribute given, in
    their order (labels, bits, bytes, largest errors); attribute_bytes their
    sections' sum."""

    n: int  # vertices (of the decoded mesh: the input's less merged_vertices)
    faces: int  # triangles
    anchors: int  # anchors in the file
    chunks: int  # chunks, a refinement or detail chunk included
    bits: int  # q, the anchors' bits per coordinate
    bytes: int  # the whole file
    geometry_bytes: int  # header and chunks (detail and refinement chunks among them)
    connectivity_bytes: int  # the triangles
    order_bytes: int  # the vertex order block (0 with reorder, the default)
    detail_bytes: int  # the detail chunk (0 without one)
    refinement_bytes: int  # the refinement chunk (0 without one)
    bpv_geometry: float  # geometry bits per vertex
    rms_rel: float  # vertex RMS of the decoded shape against the input
    linf_rel: float  # max vertex distance of the decoded shape
    anchor_rms_rel: float  # the anchors' shape alone (what a decode stopping before the detail chunk shows)
    unrefined_rms_rel: float  # before the refinement chunk (0 without one)
    detail_step_rel: float  # the detail layer's quantization step (0 without one)
    weight: float  # the anchor weight w
    encode_s: float  # seconds
    solver: str  # the file's reconstruction operator: 'global' or 'iterative'
    ordering: str  # the factorizations' ordering: 'amd' or 'nd'
    target_met: bool  # every error target met (else out of reach at these bits)
    reordered: bool  # numbered in the coder's order (reorder=True, the default): order maps it
    detail: bool  # ends with a detail chunk
    refined: bool  # ends with a refinement chunk
    levels: bool  # in the level layout
    order: object  # numpy int32 (n + merged_vertices,) with reorder, else None
    merged_vertices: int  # with reorder: input vertices merged into a copy at the same position
    attribute_bytes: int  # the attribute sections
    attributes: tuple  # of AttributeStats, one per attribute given


def _stats_of(report):
    """A CompressStats from the library's report; frees its map."""
    try:
        order = None
        if report.order:
            order = np.ctypeslib.as_array(report.order, shape=(report.n + report.merged_vertices,)).copy()
        attributes = tuple(
            AttributeStats(label=a.label.decode(), kind=_KINDS[a.kind], bits=a.bits, per_corner=bool(a.per_corner),
                           from_surface=bool(a.from_surface), elements=a.elements, bytes=a.bytes,
                           max_error=a.max_error)
            for a in (report.attributes[i] for i in range(report.num_attributes)))
    finally:
        LIB.gab_free(report.order)
        LIB.gab_free(report.attributes)
    fields = {f.name: getattr(report, f.name) for f in dataclasses.fields(CompressStats)
              if f.name not in ("solver", "ordering", "order", "attributes")}
    for name in ("target_met", "reordered", "detail", "refined", "levels"):
        fields[name] = bool(fields[name])
    return CompressStats(solver=_SOLVER_NAMES.get(report.solver, str(report.solver)),
                         ordering=_ORDERING_NAMES.get(report.ordering, str(report.ordering)), order=order,
                         attributes=attributes, **fields)


def compress(V, F, error=None, anchors=None, linf=None, bits=None, weight=None, reorder=True, threads=1,
             detail="auto", refine=False, ordering="auto", solver="auto", return_stats=False, attributes=None,
             normal_bits=None, uv_bits=None, color_bits=None, generic_bits=None):
    """Compresses a mesh to a .gab file, returned as bytes; with
    return_stats=True, as (bytes, CompressStats): sizes, anchors, bits, the
    achieved errors and the map onto the decoded mesh's numbering
    (stats.order; None with reorder=False).

    V: (n, 3) coordinates, F: (t, 3) vertex indices (0-based). Stopping rules,
    any combination, the first met stops: error (relative vertex RMS over the
    bounding-box diagonal, the CLI's --error), anchors (a count), linf
    (relative max vertex error); with none of them, error=1e-3. bits: q per
    coordinate (2..24; None: from the target); weight: anchor weight w (None:
    100); reorder: True (the default) numbers the decoded mesh in the coder's
    traversal order, the smallest file; False keeps the input's numbering,
    priced by the vertex order block (the CLI's --keep-order, once the
    default);
    threads: for the factorizations (0: every core; the file is the same for
    any count); detail: 'auto', 'on' or 'off'; refine: the least-squares
    refinement chunk; ordering: the factorizations' ('auto', 'amd' or 'nd',
    as the CLI's --ordering; speed only); solver: the reconstruction operator
    ('auto', 'global' or 'iterative', as the CLI's --solver: iterative decodes
    in time linear in n, global makes files about 10% smaller at 1e-3 and
    decodes an order of magnitude slower; auto is iterative, or global with
    refine). The triangles come back as a set of oriented triangles, on the
    decoded numbering.

    attributes: a list of gab.Attribute (normals, texture coordinates,
    colours, named generics; per vertex or per corner), each coded in its
    own section after the geometry; decompress(..., return_attributes=True)
    gives them back on the decoded numbering. Their quantization:
    normal_bits (a lattice of about 4^bits directions, 2..16; None: 8),
    uv_bits (texture coordinates), color_bits, generic_bits (a grid of
    2^bits - 1 steps over each attribute's span, 1..31; None: 10, 8, 16), as
    the CLI's --normal-bits, --uv-bits, --color-bits and --generic-bits;
    integer-typed values are coded exactly."""
    call = "gab.compress"
    V = _reals(call, V, "V", 3)
    F = _int32(call, F, "F", 3)
    structs, kept = _attributes_arg(call, attributes, V.shape[0], F.shape[0])
    options = CompressOptions()
    LIB.gab_compress_options_init(ctypes.byref(options), ctypes.sizeof(options))
    if error is None and anchors is None and linf is None:
        error = _DEFAULT_ERROR
    options.target_rms_rel = 0.0 if error is None else _real_arg(call, error, "error")
    options.target_linf_rel = 0.0 if linf is None else _real_arg(call, linf, "linf")
    options.max_anchors = 0 if anchors is None else _int_arg(call, anchors, "anchors", 1)
    options.bits = 0 if bits is None else _int_arg(call, bits, "bits", 0)
    if weight is not None:
        options.weight = _real_arg(call, weight, "weight")
    options.reorder = _bool_arg(call, reorder, "reorder")
    options.threads = _int_arg(call, threads, "threads", 0, _MAX_THREADS)
    options.detail = _DETAIL[_name_arg(call, detail, "detail", list(_DETAIL))]
    options.refine = _bool_arg(call, refine, "refine")
    options.ordering = _ordering_code(call, ordering, _CODEC_ORDERINGS)
    options.solver = LIB.gab_solver_from_name(
        _name_arg(call, solver, "solver", ["auto", "global", "iterative"]).encode())
    for field, name, value, least, most in (("normal_bits", "normal_bits", normal_bits, 2, _MAX_NORMAL_BITS),
                                            ("texcoord_bits", "uv_bits", uv_bits, 1, _MAX_GRID_BITS),
                                            ("color_bits", "color_bits", color_bits, 1, _MAX_GRID_BITS),
                                            ("generic_bits", "generic_bits", generic_bits, 1, _MAX_GRID_BITS)):
        if value is not None:
            setattr(options, field, _int_arg(call, value, name, least, most))
    report = None
    if _bool_arg(call, return_stats, "return_stats"):
        report = CompressReport()
        LIB.gab_compress_report_init(ctypes.byref(report), ctypes.sizeof(report))
    out = ctypes.POINTER(ctypes.c_ubyte)()
    size = ctypes.c_size_t()
    message = message_buffer()
    code = LIB.gab_compress_with_attributes(V.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), V.shape[0],
                                            F.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), F.shape[0], structs,
                                            len(attributes or ()), ctypes.byref(options), ctypes.byref(out),
                                            ctypes.byref(size), None if report is None else ctypes.byref(report),
                                            message, len(message))
    del kept
    check(code, message)
    try:
        data = ctypes.string_at(out, size.value)
    finally:
        LIB.gab_free(out)
    return data if report is None else (data, _stats_of(report))


def _ordering_code(call, name, names):
    """The GAB_ORDERING_* code of an ordering argument, one of `names`."""
    return LIB.gab_ordering_from_name(_name_arg(call, name, "ordering", names).encode())


def _bytes_arg(call, data, name):
    """A bytes-like argument (bytes, bytearray, memoryview, a uint8 array) as bytes."""
    try:
        return bytes(memoryview(data))
    except TypeError:
        raise TypeError(f"{call}: {name} must be bytes-like (bytes, bytearray, memoryview), "
                        f"got {type(data).__name__}") from None


def decompress(data, anchors=None, max_memory=None, threads=1, ordering="auto", return_attributes=False):
    """Decodes a .gab file (bytes-like) into (V, F); with
    return_attributes=True into (V, F, attributes), a list of gab.Attribute
    in the order compress was given them, on the decoded numbering
    (per-corner ones following F). anchors=K decodes only the first K
    anchors (a coarser level; attributes decode whole at any level, except
    normals predicted from the decoded surface, which need every anchor).
    max_memory: the bytes the decode may take (None: 32 KiB per byte of the
    file, at least 64 MiB; -1: no limit; over it GabError
    GAB_E_RESOURCE_EXHAUSTED says how much it needs). threads: for the
    factorizations (0: every core; same shape for any count). ordering: a
    global-solver file's factorizations' ('auto': the one the file records,
    'amd' or 'nd', as the CLI's decompress --ordering): speed and memory
    only, the same anchors and a shape the same up to rounding. A file cut
    short decodes to its complete chunks and warns (TruncatedWarning, saying
    how many of how many); damaged or forged bytes raise GabError. What the
    file holds and the call does not give back (the attributes without
    return_attributes, sections a level of detail cannot decode) is named
    by a DroppedDataWarning."""
    call = "gab.decompress"
    data = _bytes_arg(call, data, "data")
    return_attributes = _bool_arg(call, return_attributes, "return_attributes")
    options = DecompressOptions()
    LIB.gab_decompress_options_init(ctypes.byref(options), ctypes.sizeof(options))
    if anchors is not None:
        options.max_anchors = _int_arg(call, anchors, "anchors", 1)
    if max_memory is not None:
        options.max_memory = _int_arg(call, max_memory, "max_memory", -1, np.iinfo(np.int64).max)
    options.threads = _int_arg(call, threads, "threads", 0, _MAX_THREADS)
    options.ordering = _ordering_code(call, ordering, _CODEC_ORDERINGS)
    positions, n, triangles, t = _mesh_outputs()
    attributes, count = _attribute_outputs()
    message = message_buffer()
    code = LIB.gab_decompress_with_attributes(data, len(data), ctypes.byref(options), ctypes.byref(positions),
                                              ctypes.byref(n), ctypes.byref(triangles), ctypes.byref(t),
                                              ctypes.byref(attributes), ctypes.byref(count), message, len(message))
    if code != GAB_W_TRUNCATED:
        check(code, message)
    decoded = _take_attributes(attributes, count, t.value)
    V, F = _take_mesh(positions, n, triangles, t)
    text = _library_text(message)  # the cut, and sections not decoded; or ""
    if code == GAB_W_TRUNCATED:
        warnings.warn(TruncatedWarning(text), stacklevel=2)
        text = ""
    if decoded and not return_attributes:
        text = (text + "; " if text else "") + \
            f"not returned: {_describe(decoded)}; decompress(..., return_attributes=True) returns them"
    if text:
        warnings.warn(DroppedDataWarning(text), stacklevel=2)
    return (V, F, decoded) if return_attributes else (V, F)


# Matrices for Cholesky: any form in, the lower triangle in CSC out.

_SYMMETRY_TOLERANCE = 1e-10  # |A[i, j] - A[j, i]| allowed, relative to A's largest entry
_MATRIX_FORMS = "a scipy.sparse matrix, a dense 2-D numpy array or a tuple (indptr, indices, data)"


def _csc(call, A):
    """(n, indptr, indices, data or None) of A in CSC, whatever of it was
    given: a tuple (indptr, indices, data), a dense 2-D ndarray (its
    nonzeros), an object shaped like scipy.sparse (duck typed: any format
    converted by its tocsc(), duplicates summed by sum_duplicates() on a
    copy; no scipy import)."""
    if isinstance(A, tuple):
        if len(A) != 3:
            raise ValueError(f"{call}: a matrix tuple is (indptr, indices, data), got {len(A)} items")
        indptr, indices, data = A
        n = len(indptr) - 1
    elif isinstance(A, np.ndarray):
        if A.ndim != 2 or A.shape[0] != A.shape[1]:
            raise ValueError(f"{call}: a dense matrix must be square and 2-D, got shape {A.shape}")
        dense = _reals(call, A, "A")
        n = dense.shape[0]
        columns, indices = np.nonzero(dense.T)  # column by column, rows increasing
        indptr = np.concatenate([[0], np.cumsum(np.bincount(columns, minlength=n))])
        data = dense[indices, columns]
    elif hasattr(A, "indptr") or hasattr(A, "tocsc"):
        if getattr(A, "format", "csc") != "csc":
            if not hasattr(A, "tocsc"):
                raise TypeError(f"{call}: A is in format {A.format!r} and has no tocsc() to convert it")
            A = A.tocsc()
        if not getattr(A, "has_canonical_format", True):  # scipy: unsorted rows or duplicates
            A = A.copy()
            A.sum_duplicates()
        rows, cols = A.shape
        if rows != cols:
            raise ValueError(f"{call}: the matrix must be square, got shape {A.shape}")
        indptr, indices, data = A.indptr, A.indices, A.data
        n = cols
    else:
        raise TypeError(f"{call}: A must be {_MATRIX_FORMS}, got {type(A).__name__}")
    indptr = _int32(call, indptr, "indptr")
    indices = _int32(call, indices, "indices")
    if indptr.ndim != 1 or indices.ndim != 1 or indptr.shape[0] != n + 1:
        raise ValueError(f"{call}: indptr must have n + 1 entries and indices be one-dimensional")
    if indptr.shape[0] and (indptr[-1] != indices.shape[0] or indptr[0] != 0):
        raise ValueError(f"{call}: indptr must run from 0 to len(indices) = {indices.shape[0]}")
    if np.any(np.diff(indptr) < 0):
        raise ValueError(f"{call}: indptr must be nondecreasing")
    if indices.size and (indices.min() < 0 or indices.max() >= n):
        bad = indices.min() if indices.min() < 0 else indices.max()
        raise ValueError(f"{call}: indices must be in 0..{n - 1}, got {bad}")
    if data is not None:
        data = _reals(call, data, "data")
        if data.shape != indices.shape:
            raise ValueError(f"{call}: data has {data.shape[0]} entries, indices {indices.shape[0]}")
    return n, indptr, indices, data


def _lower_triangle(call, n, indptr, indices, data):
    """(indptr, indices, data) of the lower triangle: as given when nothing
    is above the diagonal; else A must be symmetric (its values to 1e-10 of
    its largest entry; its pattern when data is None), checked in
    O(nnz log nnz), and its lower triangle is taken."""
    column = np.repeat(np.arange(n, dtype=np.int64), np.diff(indptr))
    above = indices < column
    if not above.any():
        return indptr, indices, data
    below = indices > column
    # Each strictly lower entry (i, j) under the key j n + i, each strictly
    # upper one under its mirror's: symmetric when both sides give every key
    # the same value.
    lower_keys = column[below] * n + indices[below]
    mirror_keys = indices[above].astype(np.int64) * n + column[above]
    by_key = np.argsort(mirror_keys, kind="stable")
    tolerance = 0.0 if data is None else _SYMMETRY_TOLERANCE * float(np.max(np.abs(data)))
    if np.array_equal(lower_keys, mirror_keys[by_key]):  # one pattern (and rows sorted): compare entry by entry
        if data is not None and np.any(np.abs(data[below] - data[above][by_key]) > tolerance):
            _refuse_asymmetry(call, n, np.concatenate([lower_keys, mirror_keys]), below, above, data, tolerance)
    else:
        _refuse_asymmetry(call, n, np.concatenate([lower_keys, mirror_keys]), below, above, data, tolerance)
    keep = ~above
    lower_indptr = np.concatenate([[0], np.cumsum(np.bincount(column[keep], minlength=n))]).astype(np.int32)
    return lower_indptr, np.ascontiguousarray(indices[keep]), None if data is None else np.ascontiguousarray(data[keep])


def _refuse_asymmetry(call, n, keys, below, above, data, tolerance):
    """Raises ValueError naming the pair of entries that differ most, unless
    every key's entries (lower side first in `keys`, duplicates summed, a
    missing entry zero) agree within tolerance (then the patterns differ by
    explicit zeros or duplicates only)."""
    unique, which = np.unique(keys, return_inverse=True)
    split = int(np.count_nonzero(below))
    if data is None:
        lower_side, upper_side = np.ones(split), np.ones(keys.size - split)
    else:
        lower_side, upper_side = data[below], data[above]
    lower_sum = np.bincount(which[:split], weights=lower_side, minlength=unique.size)
    upper_sum = np.bincount(which[split:], weights=upper_side, minlength=unique.size)
    difference = np.abs(lower_sum - upper_sum)
    worst = int(np.argmax(difference))
    if difference[worst] <= tolerance:
        return
    j, i = divmod(int(unique[worst]), n)
    hint = "give the whole symmetric matrix or its lower triangle"
    if data is None:
        present, missing = ((i, j), (j, i)) if lower_sum[worst] > upper_sum[worst] else ((j, i), (i, j))
        raise ValueError(f"{call}: A is not symmetric: it has entry {present} and not {missing} ({hint})")
    raise ValueError(f"{call}: A is not symmetric: A[{i}, {j}] = {float(lower_sum[worst])!r} but "
                     f"A[{j}, {i}] = {float(upper_sum[worst])!r} ({hint})")


def _lower_csc(call, A):
    """(n, indptr, indices, data or None): A's lower triangle in CSC, from any form _csc takes."""
    n, indptr, indices, data = _csc(call, A)
    return (n,) + _lower_triangle(call, n, indptr, indices, data)


def _doubles(a):
    return None if a is None else a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


class Cholesky:
    """The engine's sparse Cholesky factorization of a symmetric positive
    definite matrix A. A may be a scipy.sparse matrix of any format (read by
    duck typing: format, tocsc, indptr, indices, data, shape), a dense 2-D
    numpy array, or a tuple (indptr, indices, data) in CSC (0-based); either
    the whole symmetric matrix (checked: symmetric to 1e-10 of its largest
    entry, else ValueError naming the first pair that differs) or its lower
    triangle (e.g. scipy.sparse.tril(A, format='csc')). Only the lower
    triangle is used.

    Cholesky(A) analyzes and factorizes; analyze takes the pattern (ordering
    and symbolic analysis, once per pattern); factorize the values; solve (or
    calling the object, chol(b)) solves A x = b for one or several
    right-hand sides; add_anchor(j, w) turns the factor into that of
    A + w^2 e_j e_j^T in place (Givens rotations along the elimination tree).
    close() (or the end of a with block) releases it.

    ordering: the fill-reducing ordering every analyze uses, as `gab factor
    --ordering`: 'amd' (approximate minimum degree, the default), 'nd'
    (nested dissection: less fill on large meshes, several times AMD's
    ordering time), 'natural' (A's own order, for a matrix already ordered
    well) or 'auto' (nd from 100,000 columns, amd below). It sets the fill,
    hence factor_entries (the memory) and the time; the solutions are the
    same up to rounding. threads: for the factorizations, solves and the
    nested dissection (0: every core; the same factor for any count)."""

    def __init__(self, A=None, ordering="amd", threads=1):
        call = "gab.Cholesky"
        self._handle = None
        self._pattern = None
        self._closed = False
        self._options = CholeskyOptions()
        LIB.gab_cholesky_options_init(ctypes.byref(self._options), ctypes.sizeof(self._options))
        self._options.ordering = _ordering_code(call, ordering, _CHOLESKY_ORDERINGS)
        self._options.threads = _int_arg(call, threads, "threads", 0, _MAX_THREADS)
        if A is not None:
            n, indptr, indices, data = _lower_csc("Cholesky.analyze", A)
            self._analyze(n, indptr, indices)
            if data is not None:
                self._factorize(data)

    @property
    def n(self):
        return 0 if self._pattern is None else self._pattern[0]

    @property
    def factor_entries(self):
        """The doubles the factor is stored in (8 bytes each: the bulk of its
        memory): nnz(L) and the explicit zeros of its supernodes' blocks,
        what the ordering is chosen to keep small. Known once analyzed."""
        self._require("Cholesky.factor_entries")
        return int(LIB.gab_cholesky_factor_entries(self._handle))

    def analyze(self, A):
        """Ordering (the one the constructor took) and symbolic analysis of
        A's pattern (its values are not used)."""
        n, indptr, indices, _ = _lower_csc("Cholesky.analyze", A)
        return self._analyze(n, indptr, indices)

    def _analyze(self, n, indptr, indices):
        handle = ctypes.c_void_p()
        message = message_buffer()
        code = LIB.gab_cholesky_create_ex(n, indptr.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)),
                                          indices.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), None,
                                          ctypes.byref(self._options), ctypes.byref(handle), message, len(message))
        check(code, message)
        self.close()
        self._handle = handle
        self._closed = False
        self._pattern = (n, indptr, indices)
        return self

    def factorize(self, A):
        """Numeric factorization: A with the analyzed pattern (in any form the
        constructor takes), or the values of its lower triangle alone (a 1-D
        array in the order of the analyzed lower triangle's CSC entries:
        A.data when analyze was given that lower triangle). Discards earlier
        updates."""
        call = "Cholesky.factorize"
        self._require(call)
        if isinstance(A, np.ndarray) and A.ndim == 1:
            data = _reals(call, A, "values")
        else:
            n, indptr, indices, data = _lower_csc(call, A)
            if data is None:
                raise ValueError(f"{call}: the matrix has no values")
            if n != self._pattern[0] or not (np.array_equal(indptr, self._pattern[1])
                                             and np.array_equal(indices, self._pattern[2])):
                raise ValueError(f"{call}: the matrix's pattern is not the analyzed one: call analyze first")
        return self._factorize(data)

    def _factorize(self, data):
        if data.shape != self._pattern[2].shape:
            raise ValueError(f"Cholesky.factorize: values has {data.shape[0]} entries, the analyzed lower "
                             f"triangle {self._pattern[2].shape[0]} (give the matrix itself when analyze had "
                             "more than its lower triangle)")
        message = message_buffer()
        check(LIB.gab_cholesky_factorize(self._handle, _doubles(data), message, len(message)), message)
        return self

    def solve(self, b):
        """x with A x = b: b of shape (n,) or (n, k); returns a new array of b's shape."""
        call = "Cholesky.solve"
        self._require(call)
        b = _reals(call, b, "b")
        if b.shape[:1] != (self.n,) or b.ndim > 2:
            raise ValueError(f"{call}: b must have shape ({self.n},) or ({self.n}, k), got {b.shape}")
        x = np.array(b, dtype=np.float64, order="F", copy=True)
        nrhs = 1 if x.ndim == 1 else x.shape[1]
        code = LIB.gab_cholesky_solve(self._handle, _doubles(x), nrhs)
        check(code, LIB.gab_cholesky_message(self._handle))
        return x

    def __call__(self, b):
        """chol(b) is chol.solve(b) (scikit-sparse's Factor is called the same way)."""
        return self.solve(b)

    def add_anchor(self, j, w):
        """The factor of A + w^2 e_j e_j^T, in place (j 0-based)."""
        call = "Cholesky.add_anchor"
        self._require(call)
        j = _int_arg(call, j, "j", np.iinfo(np.int32).min)  # the library checks it against n
        code = LIB.gab_cholesky_add_anchor(self._handle, j, _real_arg(call, w, "w"))
        check(code, LIB.gab_cholesky_message(self._handle))
        return self

    def close(self):
        """Releases the factorization now (also done when the object goes);
        a later call other than analyze raises GabError GAB_E_STATE saying
        it is closed."""
        if self._handle is not None:
            LIB.gab_cholesky_destroy(self._handle)
            self._handle = None
            self._closed = True

    def _require(self, call):
        if self._handle is None and self._closed:
            raise GabError(_GAB_E_STATE, f"{call}: this Cholesky is closed (close() or the end of its with "
                                         "block released it): analyze a matrix again to reuse it")
        if self._handle is None:
            raise GabError(_GAB_E_STATE, f"{call}: no analyzed matrix: call analyze first")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()
