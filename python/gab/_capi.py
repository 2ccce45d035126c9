"""ctypes bindings of gab.h: finding libgab, the functions' signatures, and
turning an error code and message into a GabError."""

import ctypes
import os
import sys
from ctypes import POINTER, c_char_p, c_double, c_int, c_int32, c_int64, c_size_t, c_ubyte, c_void_p

MESSAGE_SIZE = 1024


class GabError(Exception):
    """A gab call failed: `code` is its GAB_E_* code, `name` the code's name
    ("GAB_E_PARSE"), and the text is the library's message."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code
        self.name = LIB.gab_error_name(code).decode()


class TruncatedWarning(UserWarning):
    """decompress: the file ends inside a chunk (a transfer cut short); the
    mesh returned is the shape of its complete chunks, the message says how
    many of how many. warnings.simplefilter("error", gab.TruncatedWarning)
    makes it an exception."""


class DroppedDataWarning(UserWarning):
    """A call succeeded without giving back all the input held; the message
    names what: read_mesh, data gab does not carry (materials, groups,
    polygons' arity, ...: "not carried") and, without return_attributes,
    the attributes it read ("not returned"); decompress, the attributes
    without return_attributes and sections a level of detail cannot decode
    ("not decoded"); write_mesh, what the format cannot hold ("not
    written"). warnings.simplefilter("error", gab.DroppedDataWarning) makes
    it an exception (as `gab compress --strict`)."""


GAB_W_TRUNCATED = 100


class CompressOptions(ctypes.Structure):
    """gab_compress_options, field for field (gab.h)."""

    _fields_ = [
        ("size", c_size_t),
        ("target_rms_rel", c_double),
        ("target_linf_rel", c_double),
        ("weight", c_double),
        ("max_anchors", c_int32),
        ("bits", c_int32),
        ("reorder", c_int32),
        ("threads", c_int32),
        ("detail", c_int32),
        ("refine", c_int32),
        ("ordering", c_int32),
        ("solver", c_int32),
        ("normal_bits", c_int32),
        ("texcoord_bits", c_int32),
        ("color_bits", c_int32),
        ("generic_bits", c_int32),
    ]


class Attribute(ctypes.Structure):
    """gab_attribute, field for field (gab.h)."""

    _fields_ = [
        ("kind", c_int32),
        ("value_type", c_int32),
        ("components", c_int32),
        ("elements", c_int32),
        ("name", c_char_p),
        ("values", POINTER(c_double)),
        ("corners", POINTER(c_int32)),
    ]


class AttributeStats(ctypes.Structure):
    """gab_attribute_stats, field for field (gab.h)."""

    _fields_ = [
        ("label", c_char_p),
        ("kind", c_int32),
        ("bits", c_int32),
        ("per_corner", c_int32),
        ("from_surface", c_int32),
        ("elements", c_int64),
        ("bytes", c_size_t),
        ("max_error", c_double),
    ]


class DecompressOptions(ctypes.Structure):
    """gab_decompress_options, field for field (gab.h)."""

    _fields_ = [
        ("size", c_size_t),
        ("max_memory", c_int64),
        ("max_anchors", c_int32),
        ("threads", c_int32),
        ("ordering", c_int32),
    ]


class CholeskyOptions(ctypes.Structure):
    """gab_cholesky_options, field for field (gab.h)."""

    _fields_ = [
        ("size", c_size_t),
        ("ordering", c_int32),
        ("threads", c_int32),
    ]


class CompressReport(ctypes.Structure):
    """gab_compress_report, field for field (gab.h)."""

    _fields_ = [("size", c_size_t)]
    _fields_ += [(name, c_int32) for name in ("n", "faces", "anchors", "chunks", "bits", "solver", "ordering",
                                              "target_met", "reordered", "detail", "refined", "levels")]
    _fields_ += [(name, c_size_t) for name in ("bytes", "geometry_bytes", "connectivity_bytes", "order_bytes",
                                               "detail_bytes", "refinement_bytes")]
    _fields_ += [(name, c_double) for name in ("rms_rel", "linf_rel", "anchor_rms_rel", "unrefined_rms_rel",
                                               "detail_step_rel", "bpv_geometry", "weight", "encode_s")]
    _fields_ += [("order", POINTER(c_int32)), ("merged_vertices", c_int32), ("num_attributes", c_int32),
                 ("attribute_bytes", c_size_t), ("attributes", POINTER(AttributeStats))]


def _candidates():
    """Where libgab may be, in order, each with what it is: $GAB_LIBRARY
    alone when it is set; else the copy the package was installed with
    (_location.py, written by cmake --install), then the dynamic loader's
    search path."""
    explicit = os.environ.get("GAB_LIBRARY")
    if explicit:
        return [(explicit, "$GAB_LIBRARY")]
    found = []
    try:
        from . import _location

        path = os.path.normpath(os.path.join(os.path.dirname(__file__), _location.LIBRARY))
        found.append((path, "the library installed with this package"))
    except ImportError:
        pass
    return found + [("libgab.so", "the dynamic loader's search path (LD_LIBRARY_PATH, ldconfig's cache, /usr/lib)")]


def _load():
    tried = []
    for path, where in _candidates():
        try:
            return ctypes.CDLL(path)
        except OSError as e:
            reason = str(e)
            if reason.startswith(path + ": "):  # the loader's message names the path: once is enough
                reason = reason[len(path) + 2:]
            tried.append(f"{where} ({path}): {reason}")
    raise ImportError(
        f"gab: cannot load libgab for {sys.executable}; looked at " + "; ".join(tried)
        + ". Set GAB_LIBRARY to the path of libgab.so, or install gab with cmake --install"
    )


def _declare(lib):
    P = POINTER
    signatures = {
        "gab_version": (c_char_p, []),
        "gab_error_name": (c_char_p, [c_int]),
        "gab_free": (None, [c_void_p]),
        "gab_read_mesh": (c_int, [c_char_p, P(P(c_double)), P(c_int32), P(P(c_int32)), P(c_int32), c_char_p, c_size_t]),
        "gab_read_mesh_with_attributes": (
            c_int,
            [c_char_p, P(P(c_double)), P(c_int32), P(P(c_int32)), P(c_int32), P(P(Attribute)), P(c_int32), c_char_p,
             c_size_t],
        ),
        "gab_write_mesh": (
            c_int,
            [c_char_p, P(c_double), c_int32, P(c_int32), c_int32, P(Attribute), c_int32, c_char_p, c_size_t],
        ),
        "gab_compress_options_init": (None, [P(CompressOptions), c_size_t]),
        "gab_ordering_from_name": (c_int, [c_char_p]),
        "gab_solver_from_name": (c_int, [c_char_p]),
        "gab_compress_ex": (
            c_int,
            [P(c_double), c_int32, P(c_int32), c_int32, P(CompressOptions), P(P(c_ubyte)), P(c_size_t), c_char_p,
             c_size_t],
        ),
        "gab_compress_report_init": (None, [P(CompressReport), c_size_t]),
        "gab_compress_with_report": (
            c_int,
            [P(c_double), c_int32, P(c_int32), c_int32, P(CompressOptions), P(P(c_ubyte)), P(c_size_t),
             P(CompressReport), c_char_p, c_size_t],
        ),
        "gab_compress_with_attributes": (
            c_int,
            [P(c_double), c_int32, P(c_int32), c_int32, P(Attribute), c_int32, P(CompressOptions), P(P(c_ubyte)),
             P(c_size_t), P(CompressReport), c_char_p, c_size_t],
        ),
        "gab_decompress_options_init": (None, [P(DecompressOptions), c_size_t]),
        "gab_decompress_ex": (
            c_int,
            [c_char_p, c_size_t, P(DecompressOptions), P(P(c_double)), P(c_int32), P(P(c_int32)), P(c_int32),
             c_char_p, c_size_t],
        ),
        "gab_decompress_with_attributes": (
            c_int,
            [c_char_p, c_size_t, P(DecompressOptions), P(P(c_double)), P(c_int32), P(P(c_int32)), P(c_int32),
             P(P(Attribute)), P(c_int32), c_char_p, c_size_t],
        ),
        "gab_cholesky_create": (
            c_int,
            [c_int32, P(c_int32), P(c_int32), P(c_double), P(c_void_p), c_char_p, c_size_t],
        ),
        "gab_cholesky_options_init": (None, [P(CholeskyOptions), c_size_t]),
        "gab_cholesky_create_ex": (
            c_int,
            [c_int32, P(c_int32), P(c_int32), P(c_double), P(CholeskyOptions), P(c_void_p), c_char_p, c_size_t],
        ),
        "gab_cholesky_factor_entries": (c_int64, [c_void_p]),
        "gab_cholesky_factorize": (c_int, [c_void_p, P(c_double), c_char_p, c_size_t]),
        "gab_cholesky_solve": (c_int, [c_void_p, P(c_double), c_int32]),
        "gab_cholesky_add_anchor": (c_int, [c_void_p, c_int32, c_double]),
        "gab_cholesky_message": (c_char_p, [c_void_p]),
        "gab_cholesky_destroy": (None, [c_void_p]),
    }
    for name, (restype, argtypes) in signatures.items():
        function = getattr(lib, name)
        function.restype = restype
        function.argtypes = argtypes
    return lib


LIB = _declare(_load())


# The Python name of each C function whose messages reach a GabError: the
# library's message starts "gab_compress_ex: ", the error's with what the
# caller called.
PYTHON_NAMES = {
    "gab_compress": "gab.compress",
    "gab_compress_ex": "gab.compress",
    "gab_compress_with_report": "gab.compress",
    "gab_compress_with_attributes": "gab.compress",
    "gab_decompress": "gab.decompress",
    "gab_decompress_ex": "gab.decompress",
    "gab_decompress_with_attributes": "gab.decompress",
    "gab_read_mesh": "gab.read_mesh",
    "gab_read_mesh_with_attributes": "gab.read_mesh",
    "gab_write_mesh": "gab.write_mesh",
    "gab_cholesky_create": "Cholesky.analyze",
    "gab_cholesky_create_ex": "Cholesky.analyze",
    "gab_cholesky_factorize": "Cholesky.factorize",
    "gab_cholesky_solve": "Cholesky.solve",
    "gab_cholesky_add_anchor": "Cholesky.add_anchor",
}


def python_message(text):
    """The library's message with its C function's name replaced by the Python one."""
    function, colon, rest = text.partition(": ")
    return PYTHON_NAMES[function] + colon + rest if colon and function in PYTHON_NAMES else text


def check(code, message):
    """Raises GabError unless code is GAB_OK; `message` is the call's buffer
    (or the handle's message as bytes)."""
    if code != 0:
        text = message.value if hasattr(message, "value") else message
        raise GabError(code, python_message(text.decode(errors="replace")))


def message_buffer():
    return ctypes.create_string_buffer(MESSAGE_SIZE)
