"""gab: mesh compression with geometry-aware bases, and the sparse Cholesky
engine behind it, from Python (ctypes over libgab's C API, gab.h; numpy
arrays in and out).

    import gab
    V, F = gab.read_mesh("bunny.off")        # (n, 3) float64, (t, 3) int32
    data = gab.compress(V, F, error=1e-3)    # bytes: a .gab file
    V2, F2 = gab.decompress(data)            # same vertex numbering, V2 within the target
    V1, _ = gab.decompress(data, anchors=100)  # a coarser level: the first 100 anchors

    chol = gab.Cholesky(A)                   # A: lower triangle, scipy.sparse CSC or (indptr, indices, data)
    x = chol.solve(b)
    chol.add_anchor(j, w)                    # now the factor of A + w^2 e_j e_j^T

Every failure of the library raises GabError with its message; a file cut
short decodes to its complete chunks with a TruncatedWarning.
"""

import ctypes
import os
import warnings

import numpy as np

from ._capi import (
    GAB_W_TRUNCATED,
    LIB,
    CompressOptions,
    DecompressOptions,
    GabError,
    TruncatedWarning,
    check,
    message_buffer,
)

__all__ = ["Cholesky", "GabError", "TruncatedWarning", "compress", "decompress", "read_mesh", "version"]

_DETAIL = {"auto": 0, "on": 1, "off": 2}
_DEFAULT_ERROR = 1e-3


def version():
    """The library's version string, as gab_version() (and gab --version)."""
    return LIB.gab_version().decode()


__version__ = version()


def _array(values, dtype, name, columns=None):
    """values as a C-contiguous array of dtype; with columns, of shape (k, columns)."""
    a = np.ascontiguousarray(values, dtype=dtype)
    if columns is not None and (a.ndim != 2 or a.shape[1] != columns):
        raise ValueError(f"{name} must have shape (k, {columns}), got {a.shape}")
    return a


def _int32(values, name, columns=None):
    """values as int32: integers only (floats are not truncated), each within int32."""
    a = np.asarray(values)
    if a.size and a.dtype.kind not in "iu":
        raise TypeError(f"{name} must hold integers, got dtype {a.dtype}")
    if a.size and (a.max() > np.iinfo(np.int32).max or a.min() < np.iinfo(np.int32).min):
        raise ValueError(f"{name} has entries beyond int32")
    return _array(a, np.int32, name, columns)


def _reals(values, dtype, name, columns=None):
    """values as float64: real numbers only (no complex, no strings)."""
    a = np.asarray(values)
    if a.size and a.dtype.kind not in "iuf":
        raise TypeError(f"{name} must hold real numbers, got dtype {a.dtype}")
    return _array(a, dtype, name, columns)


def _int_arg(value, name, low, high=np.iinfo(np.int32).max):
    """An integer argument within [low, high] (the C type's range at most)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name} must be in {low}..{high}, got {value}")
    return int(value)


def _real_arg(value, name):
    """A real-number argument (no strings, no complex)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} must be a number, got {type(value).__name__}")
    return float(value)


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
    (polygons fan-triangulated)."""
    positions, n, triangles, t = _mesh_outputs()
    message = message_buffer()
    code = LIB.gab_read_mesh(os.fsencode(path), ctypes.byref(positions), ctypes.byref(n), ctypes.byref(triangles),
                             ctypes.byref(t), message, len(message))
    check(code, message)
    return _take_mesh(positions, n, triangles, t)


def compress(V, F, error=None, anchors=None, linf=None, bits=None, weight=None, reorder=False, threads=1,
             detail="auto", refine=False, ordering="auto", solver="auto"):
    """Compresses a mesh to a .gab file, returned as bytes.

    V: (n, 3) coordinates, F: (t, 3) vertex indices (0-based). Stopping rules,
    any combination, the first met stops: error (relative vertex RMS over the
    bounding-box diagonal, the CLI's --error), anchors (a count), linf
    (relative max vertex error); with none of them, error=1e-3. bits: q per
    coordinate (2..24; None: from the target); weight: anchor weight w (None:
    100); reorder: number the decoded mesh in the coder's order (smaller file);
    threads: for the factorizations (0: every core; the file is the same for
    any count); detail: 'auto', 'on' or 'off'; refine: the least-squares
    refinement chunk; ordering: the factorizations' ('auto', 'amd' or 'nd',
    as the CLI's --ordering; speed only); solver: the reconstruction operator
    ('auto', 'global' or 'iterative', as the CLI's --solver: iterative decodes
    in time linear in n, global makes files about 10% smaller at 1e-3 and
    decodes an order of magnitude slower; auto is iterative, or global with
    refine). The decoded mesh keeps the vertex numbering (unless reorder)
    and the triangles as a set of oriented triangles."""
    V = _reals(V, np.float64, "V", 3)
    F = _int32(F, "F", 3)
    if detail not in _DETAIL:
        raise ValueError(f"detail must be 'auto', 'on' or 'off', got {detail!r}")
    ordering_code = LIB.gab_ordering_from_name(str(ordering).encode())
    if ordering_code < 0:
        raise ValueError(f"ordering must be 'auto', 'amd' or 'nd', got {ordering!r}")
    solver_code = LIB.gab_solver_from_name(str(solver).encode())
    if solver_code < 0:
        raise ValueError(f"solver must be 'auto', 'global' or 'iterative', got {solver!r}")
    options = CompressOptions()
    LIB.gab_compress_options_init(ctypes.byref(options), ctypes.sizeof(options))
    if error is None and anchors is None and linf is None:
        error = _DEFAULT_ERROR
    options.target_rms_rel = 0.0 if error is None else _real_arg(error, "error")
    options.target_linf_rel = 0.0 if linf is None else _real_arg(linf, "linf")
    options.max_anchors = 0 if anchors is None else _int_arg(anchors, "anchors", 1)
    options.bits = 0 if bits is None else _int_arg(bits, "bits", 0)
    if weight is not None:
        options.weight = _real_arg(weight, "weight")
    options.reorder = int(bool(reorder))
    options.threads = _int_arg(threads, "threads", 0)
    options.detail = _DETAIL[detail]
    options.refine = int(bool(refine))
    options.ordering = ordering_code
    options.solver = solver_code
    out = ctypes.POINTER(ctypes.c_ubyte)()
    size = ctypes.c_size_t()
    message = message_buffer()
    code = LIB.gab_compress_ex(V.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), V.shape[0],
                               F.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), F.shape[0], ctypes.byref(options),
                               ctypes.byref(out), ctypes.byref(size), message, len(message))
    check(code, message)
    try:
        return ctypes.string_at(out, size.value)
    finally:
        LIB.gab_free(out)


def decompress(data, anchors=None, max_memory=None, threads=1):
    """Decodes a .gab file (bytes-like) into (V, F); anchors=K decodes only the
    first K anchors (a coarser level). max_memory: the bytes the decode may
    take (None: 32 KiB per byte of the file, at least 64 MiB; -1: no limit;
    over it GabError GAB_E_RESOURCE_EXHAUSTED says how much it needs).
    threads: for the factorizations (0: every core; same shape for any
    count). A file cut short decodes to its complete chunks and warns
    (TruncatedWarning, saying how many of how many); damaged or forged
    bytes raise GabError."""
    data = bytes(data)
    options = DecompressOptions()
    LIB.gab_decompress_options_init(ctypes.byref(options), ctypes.sizeof(options))
    if anchors is not None:
        options.max_anchors = _int_arg(anchors, "anchors", 1)
    if max_memory is not None:
        options.max_memory = _int_arg(max_memory, "max_memory", -1, np.iinfo(np.int64).max)
    options.threads = _int_arg(threads, "threads", 0)
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


def _csc(A):
    """(n, indptr, indices, data or None) of a lower triangle given as a
    scipy.sparse-shaped CSC object or a tuple (indptr, indices, data)."""
    if isinstance(A, tuple):
        if len(A) != 3:
            raise ValueError("a matrix tuple is (indptr, indices, data)")
        indptr, indices, data = A
        n = len(indptr) - 1
    else:
        if getattr(A, "format", "csc") != "csc":
            raise ValueError(f"the matrix must be CSC (its lower triangle), got format {A.format!r}")
        indptr, indices, data = A.indptr, A.indices, A.data
        rows, cols = A.shape
        if rows != cols:
            raise ValueError(f"the matrix must be square, got shape {A.shape}")
        n = cols
    indptr = _int32(indptr, "indptr")
    indices = _int32(indices, "indices")
    if indptr.ndim != 1 or indices.ndim != 1 or indptr.shape[0] != n + 1:
        raise ValueError("indptr must have n + 1 entries and indices be one-dimensional")
    if indptr.shape[0] and (indptr[-1] != indices.shape[0] or indptr[0] != 0):
        raise ValueError(f"indptr must run from 0 to len(indices) = {indices.shape[0]}")
    if data is not None:
        data = _reals(data, np.float64, "data")
        if data.shape != indices.shape:
            raise ValueError(f"data has {data.shape[0]} entries, indices {indices.shape[0]}")
    return n, indptr, indices, data


def _doubles(a):
    return None if a is None else a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


class Cholesky:
    """The engine's sparse Cholesky factorization of a symmetric positive
    definite matrix, given by its lower triangle in CSC (a scipy.sparse CSC
    matrix, e.g. scipy.sparse.tril(A, format='csc'), or a tuple (indptr,
    indices, data); 0-based, rows sorted within each column).

    analyze takes the pattern (AMD ordering and symbolic analysis, once per
    pattern); factorize the values; solve solves A x = b for one or several
    right-hand sides; add_anchor(j, w) turns the factor into that of
    A + w^2 e_j e_j^T in place (Givens rotations along the elimination tree)."""

    def __init__(self, A=None):
        self._handle = None
        self._pattern = None
        if A is not None:
            self.analyze(A)
            if self._data_of(A) is not None:
                self.factorize(A)

    @staticmethod
    def _data_of(A):
        return A[2] if isinstance(A, tuple) else A.data

    @property
    def n(self):
        return 0 if self._pattern is None else self._pattern[0]

    def analyze(self, A):
        """Ordering and symbolic analysis of A's pattern (its values are not used)."""
        n, indptr, indices, _ = _csc(A)
        handle = ctypes.c_void_p()
        message = message_buffer()
        code = LIB.gab_cholesky_create(n, indptr.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)),
                                       indices.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), None,
                                       ctypes.byref(handle), message, len(message))
        check(code, message)
        self.close()
        self._handle = handle
        self._pattern = (n, indptr, indices)
        return self

    def factorize(self, A):
        """Numeric factorization: A with the analyzed pattern, or its values
        alone (a 1-D array in the pattern's order). Discards earlier updates."""
        self._require()
        if isinstance(A, np.ndarray) and A.ndim == 1:
            data = _reals(A, np.float64, "values")
        else:
            n, indptr, indices, data = _csc(A)
            if data is None:
                raise ValueError("factorize needs the matrix's values")
            if n != self._pattern[0] or not (np.array_equal(indptr, self._pattern[1])
                                             and np.array_equal(indices, self._pattern[2])):
                raise ValueError("the matrix's pattern is not the analyzed one: call analyze first")
        if data.shape != self._pattern[2].shape:
            raise ValueError(f"values has {data.shape[0]} entries, the pattern {self._pattern[2].shape[0]}")
        message = message_buffer()
        check(LIB.gab_cholesky_factorize(self._handle, _doubles(data), message, len(message)), message)
        return self

    def solve(self, b):
        """x with A x = b: b of shape (n,) or (n, k); returns a new array of b's shape."""
        self._require()
        b = _reals(b, np.float64, "b")
        if b.shape[:1] != (self.n,) or b.ndim > 2:
            raise ValueError(f"b must have shape ({self.n},) or ({self.n}, k), got {b.shape}")
        x = np.array(b, dtype=np.float64, order="F", copy=True)
        nrhs = 1 if x.ndim == 1 else x.shape[1]
        code = LIB.gab_cholesky_solve(self._handle, _doubles(x), nrhs)
        check(code, LIB.gab_cholesky_message(self._handle))
        return x

    def add_anchor(self, j, w):
        """The factor of A + w^2 e_j e_j^T, in place (j 0-based)."""
        self._require()
        j = _int_arg(j, "j", np.iinfo(np.int32).min)  # the library checks it against n
        code = LIB.gab_cholesky_add_anchor(self._handle, j, _real_arg(w, "w"))
        check(code, LIB.gab_cholesky_message(self._handle))
        return self

    def close(self):
        """Releases the factorization now (also done when the object goes)."""
        if self._handle is not None:
            LIB.gab_cholesky_destroy(self._handle)
            self._handle = None

    def _require(self):
        if self._handle is None:
            raise GabError(9, "Cholesky: no analyzed matrix: call analyze first")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()
