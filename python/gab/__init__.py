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

    chol = gab.Cholesky(A)                   # A: scipy.sparse (any format), dense, or (indptr, indices, data);
    x = chol.solve(b)                        #    symmetric or its lower triangle
    chol = gab.Cholesky(A, ordering="nd", threads=0)  # another ordering, every core
    chol.add_anchor(j, w)                    # now the factor of A + w^2 e_j e_j^T

Every failure of the library raises GabError with its message; a file cut
short decodes to its complete chunks with a TruncatedWarning, a mesh file's
data gab does not carry is named by a DroppedDataWarning; a bad argument
raises TypeError or ValueError naming the call and the argument.
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

__all__ = ["Cholesky", "CompressStats", "DroppedDataWarning", "GabError", "TruncatedWarning", "compress", "decompress",
           "read_mesh", "version"]

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


def read_mesh(path):
    """Reads an .obj, .off or .ply file: (V, F), V (n, 3) float64, F (t, 3) int32
    (polygons fan-triangulated). When the file held more than positions and
    triangles (normals, texture coordinates, colours, ...), a
    DroppedDataWarning names it."""
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise TypeError(f"gab.read_mesh: path must be a str, bytes or os.PathLike, got {type(path).__name__}")
    positions, n, triangles, t = _mesh_outputs()
    message = message_buffer()
    code = LIB.gab_read_mesh(os.fsencode(path), ctypes.byref(positions), ctypes.byref(n), ctypes.byref(triangles),
                             ctypes.byref(t), message, len(message))
    check(code, message)
    mesh = _take_mesh(positions, n, triangles, t)
    if message.value:
        text = message.value.decode(errors="replace").partition(": ")[2]
        warnings.warn(DroppedDataWarning(text), stacklevel=2)
    return mesh


@dataclasses.dataclass(frozen=True, eq=False)
class CompressStats:
    """What compress(..., return_stats=True) made: the figures `gab compress
    --json` prints, under its key names and in its units (docs/cli.md;
    dataclasses.asdict(stats) gives them as a dict), and the map of a
    renumbered decode. Errors are relative to the input's bounding-box
    diagonal; byte counts include each part's framing, and bytes =
    geometry_bytes + connectivity_bytes + order_bytes.

    order: with reorder=True (the default), an (n,) int32 array, order[i]
    the decoded mesh's index of input vertex i (what `gab compress
    --order-out` writes): W[order] lines up with V, and per-vertex data moves
    onto the decoded mesh by data_decoded[order] = data. None when the
    numbering is kept (reorder=False)."""

    n: int  # vertices
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
    order: object  # numpy int32 (n,) with reorder, else None


def _stats_of(report):
    """A CompressStats from the library's report; frees its map."""
    try:
        order = None
        if report.order:
            order = np.ctypeslib.as_array(report.order, shape=(report.n,)).copy()
    finally:
        LIB.gab_free(report.order)
    fields = {f.name: getattr(report, f.name) for f in dataclasses.fields(CompressStats)
              if f.name not in ("solver", "ordering", "order")}
    for name in ("target_met", "reordered", "detail", "refined", "levels"):
        fields[name] = bool(fields[name])
    return CompressStats(solver=_SOLVER_NAMES.get(report.solver, str(report.solver)),
                         ordering=_ORDERING_NAMES.get(report.ordering, str(report.ordering)), order=order, **fields)


def compress(V, F, error=None, anchors=None, linf=None, bits=None, weight=None, reorder=True, threads=1,
             detail="auto", refine=False, ordering="auto", solver="auto", return_stats=False):
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
    decoded numbering."""
    call = "gab.compress"
    V = _reals(call, V, "V", 3)
    F = _int32(call, F, "F", 3)
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
    report = None
    if _bool_arg(call, return_stats, "return_stats"):
        report = CompressReport()
        LIB.gab_compress_report_init(ctypes.byref(report), ctypes.sizeof(report))
    out = ctypes.POINTER(ctypes.c_ubyte)()
    size = ctypes.c_size_t()
    message = message_buffer()
    code = LIB.gab_compress_with_report(V.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), V.shape[0],
                                        F.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), F.shape[0],
                                        ctypes.byref(options), ctypes.byref(out), ctypes.byref(size),
                                        None if report is None else ctypes.byref(report), message, len(message))
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


def decompress(data, anchors=None, max_memory=None, threads=1, ordering="auto"):
    """Decodes a .gab file (bytes-like) into (V, F); anchors=K decodes only the
    first K anchors (a coarser level). max_memory: the bytes the decode may
    take (None: 32 KiB per byte of the file, at least 64 MiB; -1: no limit;
    over it GabError GAB_E_RESOURCE_EXHAUSTED says how much it needs).
    threads: for the factorizations (0: every core; same shape for any
    count). ordering: a global-solver file's factorizations' ('auto': the
    one the file records, 'amd' or 'nd', as the CLI's decompress
    --ordering): speed and memory only, the same anchors and a shape the
    same up to rounding. A file cut short decodes to its complete chunks and
    warns (TruncatedWarning, saying how many of how many); damaged or forged
    bytes raise GabError."""
    call = "gab.decompress"
    data = _bytes_arg(call, data, "data")
    options = DecompressOptions()
    LIB.gab_decompress_options_init(ctypes.byref(options), ctypes.sizeof(options))
    if anchors is not None:
        options.max_anchors = _int_arg(call, anchors, "anchors", 1)
    if max_memory is not None:
        options.max_memory = _int_arg(call, max_memory, "max_memory", -1, np.iinfo(np.int64).max)
    options.threads = _int_arg(call, threads, "threads", 0, _MAX_THREADS)
    options.ordering = _ordering_code(call, ordering, _CODEC_ORDERINGS)
    positions, n, triangles, t = _mesh_outputs()
    message = message_buffer()
    code = LIB.gab_decompress_ex(data, len(data), ctypes.byref(options), ctypes.byref(positions),
                                 ctypes.byref(n), ctypes.byref(triangles), ctypes.byref(t), message, len(message))
    if code == GAB_W_TRUNCATED:
        mesh = _take_mesh(positions, n, triangles, t)
        text = message.value.decode(errors="replace").partition(": ")[2]
        warnings.warn(TruncatedWarning(text), stacklevel=2)
        return mesh
    check(code, message)
    return _take_mesh(positions, n, triangles, t)


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
