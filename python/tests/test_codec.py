"""gab.compress / decompress / read_mesh over libgab (run by ctest and .ci/run)."""

import dataclasses
import math
import os
import tempfile
import unittest
import warnings

import numpy as np

import gab


def bumpy_torus(n, m):
    """A closed torus with a bumpy radius: (V, F)."""
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
    V = np.stack([(1 + 0.3 * np.cos(v)) * np.cos(u), (1 + 0.3 * np.cos(v)) * np.sin(u), 0.3 * np.sin(v)], -1)
    V = V.reshape(-1, 3) * (1 + 0.08 * np.sin(3.1 * V.reshape(-1, 3)[:, :1] + 1.3))
    a = (i * m + j).ravel()
    b = (((i + 1) % n) * m + j).ravel()
    c = (((i + 1) % n) * m + (j + 1) % m).ravel()
    d = (i * m + (j + 1) % m).ravel()
    F = np.concatenate([np.stack([a, b, c], -1), np.stack([a, c, d], -1)]).astype(np.int32)
    return V, F


def oriented_set(F):
    """The triangles as a set of oriented triangles (each from its smallest corner)."""
    F = np.asarray(F)
    shift = np.argmin(F, axis=1)
    rows = np.arange(len(F))[:, None]
    rolled = F[rows, (shift[:, None] + np.arange(3)) % 3]
    return sorted(map(tuple, rolled.tolist()))


def relative_rms(V, W):
    diagonal = np.linalg.norm(V.max(0) - V.min(0))
    return math.sqrt(np.mean(np.sum((V - W) ** 2, axis=1))) / diagonal


class CodecTest(unittest.TestCase):
    def test_round_trip_keeps_numbering_and_meets_the_target(self):
        V, F = bumpy_torus(40, 30)
        data = gab.compress(V, F, error=1e-3, reorder=False)
        self.assertIsInstance(data, bytes)
        self.assertLess(len(data), V.nbytes // 10)
        W, G = gab.decompress(data)
        self.assertEqual(W.shape, V.shape)
        self.assertEqual(W.dtype, np.float64)
        self.assertEqual(G.dtype, np.int32)
        self.assertEqual(oriented_set(G), oriented_set(F))
        self.assertLessEqual(relative_rms(V, W), 1e-3)
        self.assertGreater(relative_rms(V, W), 0)

    def test_the_default_numbers_in_traversal_order_and_reorder_false_keeps_the_input_s(self):
        """Since gab carries whole assets the default file is the smallest:
        the decoded mesh is numbered in the coder's traversal order and
        stats.order maps it; reorder=False keeps the input's numbering
        vertex by vertex, priced by the vertex order block."""
        V, F = bumpy_torus(30, 24)
        data, stats = gab.compress(V, F, error=1e-3, return_stats=True)
        self.assertEqual(data, gab.compress(V, F, error=1e-3, reorder=True))
        self.assertTrue(stats.reordered)
        self.assertEqual(stats.order_bytes, 0)
        self.assertEqual(sorted(stats.order.tolist()), list(range(len(V))))  # a permutation
        W, G = gab.decompress(data)
        self.assertEqual(W.shape, V.shape)
        self.assertGreater(relative_rms(V, W), 0.01)  # another numbering, unmapped
        self.assertAlmostEqual(relative_rms(V, W[stats.order]), stats.rms_rel, delta=1e-12)
        self.assertEqual(oriented_set(stats.order[F]), oriented_set(G))
        kept, kept_stats = gab.compress(V, F, error=1e-3, reorder=False, return_stats=True)
        self.assertFalse(kept_stats.reordered)
        self.assertIsNone(kept_stats.order)
        self.assertGreater(kept_stats.order_bytes, 0)
        self.assertLess(len(data), len(kept))
        U, H = gab.decompress(kept)
        self.assertEqual(oriented_set(H), oriented_set(F))
        self.assertAlmostEqual(relative_rms(V, U), kept_stats.rms_rel, delta=1e-12)
        diagonal = np.linalg.norm(V.max(0) - V.min(0))
        self.assertLessEqual(np.max(np.linalg.norm(V - U, axis=1)) / diagonal, kept_stats.linf_rel * (1 + 1e-12))

    def test_a_file_cut_short_warns_and_decodes_its_complete_chunks(self):
        V, F = bumpy_torus(60, 40)
        data = gab.compress(V, F, error=1e-3, reorder=True)
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the whole file: no warning
            W, _ = gab.decompress(data)
        errors = []
        for share in (0.5, 0.85, 0.99):
            with self.assertWarns(gab.TruncatedWarning) as caught:
                U, G = gab.decompress(data[: int(share * len(data))])
            self.assertRegex(str(caught.warning), r"^the file is truncated: decoded \d+ of \d+ chunks \(\d+ of \d+ anchors\)$")
            self.assertEqual(U.shape, V.shape)
            self.assertEqual(len(G), len(F))
            errors.append(relative_rms(W, U))
        self.assertGreater(errors[0], 0)
        with warnings.catch_warnings():
            warnings.simplefilter("error", gab.TruncatedWarning)
            with self.assertRaises(gab.TruncatedWarning):
                gab.decompress(data[: len(data) - 1])
        with self.assertRaises(gab.GabError) as cut:
            gab.decompress(data[: len(data) // 50])
        self.assertEqual(cut.exception.name, "GAB_E_PARSE")

    def test_anchor_prefixes_are_coarser_levels(self):
        V, F = bumpy_torus(30, 20)
        data, stats = gab.compress(V, F, anchors=120, detail="off", bits=12, return_stats=True)
        errors = [relative_rms(V, gab.decompress(data, anchors=k)[0][stats.order]) for k in (10, 40, 120)]
        self.assertGreater(errors[0], errors[1])
        self.assertGreater(errors[1], errors[2])
        self.assertEqual(relative_rms(V, gab.decompress(data)[0][stats.order]), errors[2])
        self.assertAlmostEqual(errors[2], stats.rms_rel, delta=1e-12)

    def test_options_change_the_file(self):
        V, F = bumpy_torus(20, 16)
        base = gab.compress(V, F)
        self.assertEqual(base, gab.compress(V, F, error=1e-3))  # the default rule
        self.assertEqual(base, gab.compress(V, F, threads=2))  # threads never change the bytes
        self.assertNotEqual(base, gab.compress(V, F, error=3e-3))
        W, _ = gab.decompress(gab.compress(V, F, linf=2e-3, reorder=False))  # vertex by vertex: the numbering kept
        self.assertLessEqual(np.max(np.linalg.norm(V - W, axis=1)) / np.linalg.norm(V.max(0) - V.min(0)), 2e-3)
        self.assertEqual(base, gab.compress(V, F, reorder=True))  # the default numbering: the traversal's
        self.assertLess(len(base), len(gab.compress(V, F, reorder=False)))  # the kept one is priced
        self.assertNotEqual(base, gab.compress(V, F, weight=10))
        # auto is AMD on a small mesh; the file records the ordering.
        self.assertEqual(base, gab.compress(V, F, ordering="amd"))
        self.assertNotEqual(base, gab.compress(V, F, ordering="nd"))
        # The iterative solver is the default; the file records the solver (header byte 12).
        self.assertEqual(base, gab.compress(V, F, solver="iterative"))
        self.assertEqual(base[12], 3)
        self.assertEqual(gab.compress(V, F, solver="global")[12], 0)
        self.assertEqual(gab.compress(V, F, refine=True)[12], 0)

    def test_inputs_of_other_types_and_layouts(self):
        V, F = bumpy_torus(12, 10)
        data, stats = gab.compress(V.astype(np.float32).tolist(), F.astype(np.int64), return_stats=True)
        W, G = gab.decompress(bytearray(data))
        self.assertEqual(oriented_set(G), oriented_set(stats.order[F]))
        self.assertEqual(gab.decompress(memoryview(data))[0].tolist(), W.tolist())

    def test_errors_raise_with_the_library_message(self):
        V, F = bumpy_torus(8, 6)
        bad = F.copy()
        bad[4, 1] = len(V)
        with self.assertRaises(gab.GabError) as e:
            gab.compress(V, bad)
        self.assertEqual(e.exception.name, "GAB_E_INVALID_ARGUMENT")
        self.assertEqual(str(e.exception), f"gab.compress: mesh: triangle 4: vertex index {len(V)} out of range [0, {len(V)})")
        with self.assertRaises(ValueError):
            gab.compress(V[:, :2], F)
        with self.assertRaises(ValueError):
            gab.compress(V, F, detail="maybe")
        with self.assertRaises(ValueError):
            gab.compress(V, F, ordering="natural")  # the benchmarks' ordering, not the codec's
        with self.assertRaisesRegex(ValueError, "solver must be 'auto', 'global' or 'iterative', got 'cholmod'"):
            gab.compress(V, F, solver="cholmod")
        with self.assertRaises(gab.GabError) as e:
            gab.compress(V, F, bits=40)
        self.assertEqual(str(e.exception), "gab.compress: bits must be in 2..24")
        with self.assertRaises(gab.GabError) as e:
            gab.decompress(b"not a gab file at all")
        self.assertEqual(e.exception.name, "GAB_E_PARSE")
        self.assertTrue(str(e.exception).startswith("gab.decompress: "))
        data = bytearray(gab.compress(V, F))
        data[-1] ^= 0x55  # inside the last chunk's payload: its checksum fails
        with self.assertRaises(gab.GabError) as e:
            gab.decompress(bytes(data))
        self.assertEqual(e.exception.code, 3)

    def test_arguments_are_checked_not_coerced(self):
        V, F = bumpy_torus(8, 6)
        with self.assertRaisesRegex(ValueError, "anchors must be in 1.."):
            gab.compress(V, F, anchors=2**32 + 5)  # not 5
        with self.assertRaisesRegex(TypeError, "error must be a number"):
            gab.compress(V, F, error="1e-3")
        with self.assertRaisesRegex(TypeError, "F must hold integers"):
            gab.compress(V, F + 0.7)  # not truncated to F
        with self.assertRaisesRegex(TypeError, "V must hold real numbers"):
            gab.compress(V + 0j, F)
        data = gab.compress(V, F)
        with self.assertRaisesRegex(ValueError, "anchors must be in 1.."):
            gab.decompress(data, anchors=-5)  # not the whole file
        with self.assertRaisesRegex(TypeError, "anchors must be an integer"):
            gab.decompress(data, anchors=2.5)

    def test_arguments_name_the_call_the_argument_and_its_type(self):
        V, F = bumpy_torus(8, 6)
        data = gab.compress(V, F)
        cases = [
            (TypeError, r"^gab\.compress: error must be a number, got str$", lambda: gab.compress(V, F, error="1e-3")),
            (ValueError, r"^gab\.decompress: anchors must be in 1\.\.2147483647, got -5$",
             lambda: gab.decompress(data, anchors=-5)),
            (TypeError, r"^gab\.compress: reorder must be True or False, got str$",
             lambda: gab.compress(V, F, reorder="no")),
            (TypeError, r"^gab\.compress: return_stats must be True or False, got int$",
             lambda: gab.compress(V, F, return_stats=1)),
            (TypeError, r"^gab\.compress: detail must be 'auto', 'on' or 'off', got int$",
             lambda: gab.compress(V, F, detail=1)),
            (ValueError, r"^gab\.compress: ordering must be 'auto', 'amd' or 'nd', got 'natural'$",
             lambda: gab.compress(V, F, ordering="natural")),
            (ValueError, r"^gab\.compress: V must have shape \(k, 3\), got \(48, 2\)$",
             lambda: gab.compress(V[:, :2], F)),
            (TypeError, r"^gab\.compress: F must hold integers, got dtype float64$", lambda: gab.compress(V, F + 0.5)),
            (TypeError, r"^gab\.decompress: data must be bytes-like \(bytes, bytearray, memoryview\), got str$",
             lambda: gab.decompress("not bytes")),
            (TypeError, r"^gab\.decompress: data must be bytes-like .*, got int$",
             lambda: gab.decompress(5)),  # not five zero bytes
            (TypeError, r"^gab\.decompress: threads must be an integer, got float$",
             lambda: gab.decompress(data, threads=2.0)),
            (TypeError, r"^gab\.read_mesh: path must be a str, bytes or os\.PathLike, got NoneType$",
             lambda: gab.read_mesh(None)),
        ]
        for error, pattern, call in cases:
            with self.subTest(pattern=pattern):
                with self.assertRaisesRegex(error, pattern):
                    call()
        self.assertEqual(gab.decompress(np.frombuffer(data, dtype=np.uint8))[0].tolist(),
                         gab.decompress(data)[0].tolist())  # any buffer of bytes
        self.assertEqual(gab.compress(V, F, reorder=np.bool_(True)), gab.compress(V, F, reorder=True))

    def test_return_stats_gives_the_cli_figures_and_the_map_onto_a_reordered_decode(self):
        V, F = bumpy_torus(40, 30)
        data, stats = gab.compress(V, F, error=1e-3, reorder=True, return_stats=True)
        self.assertIsInstance(stats, gab.CompressStats)
        self.assertEqual(data, gab.compress(V, F, error=1e-3, reorder=True))  # the same file
        self.assertEqual((stats.n, stats.faces), (len(V), len(F)))
        self.assertEqual(stats.bytes, len(data))
        self.assertEqual(stats.bytes, stats.geometry_bytes + stats.connectivity_bytes + stats.order_bytes)
        self.assertEqual(stats.order_bytes, 0)
        self.assertGreater(stats.anchors, 0)
        self.assertTrue(2 <= stats.bits <= 24)
        self.assertEqual((stats.solver, stats.ordering), ("iterative", "amd"))
        self.assertTrue(stats.reordered and stats.target_met and not stats.detail and not stats.refined)
        self.assertGreater(stats.rms_rel, 0)
        self.assertLessEqual(stats.rms_rel, 1e-3)
        self.assertLessEqual(stats.rms_rel, stats.linf_rel)
        self.assertEqual(stats.anchor_rms_rel, stats.rms_rel)
        self.assertAlmostEqual(stats.bpv_geometry, 8 * stats.geometry_bytes / len(V))
        self.assertEqual(stats.weight, 100)
        # The map: W[order] lines up with V within the error, order[F] is the decoded triangles.
        W, G = gab.decompress(data)
        order = stats.order
        self.assertEqual((order.dtype, order.shape), (np.int32, (len(V),)))
        self.assertEqual(sorted(order.tolist()), list(range(len(V))))
        self.assertAlmostEqual(relative_rms(V, W[order]), stats.rms_rel, delta=1e-12)
        self.assertGreater(relative_rms(V, W), 0.01)  # the decoded numbering is another one
        self.assertEqual(oriented_set(order[F]), oriented_set(G))
        colours = np.random.default_rng(1).random((len(V), 3))
        decoded_colours = np.empty_like(colours)
        decoded_colours[order] = colours  # per-vertex data onto the decoded mesh
        self.assertTrue(np.array_equal(decoded_colours[order], colours))
        # The CLI's JSON names (docs/cli.md), and a result that stays as made.
        fields = dataclasses.asdict(stats)
        for key in ("n", "faces", "anchors", "bits", "bytes", "geometry_bytes", "connectivity_bytes", "order_bytes",
                    "bpv_geometry", "linf_rel", "rms_rel", "encode_s", "reordered", "detail", "detail_bytes",
                    "detail_step_rel", "solver", "anchor_rms_rel", "chunks", "weight", "target_met", "refined",
                    "refinement_bytes", "unrefined_rms_rel", "levels", "ordering"):
            self.assertIn(key, fields)
        with self.assertRaises(dataclasses.FrozenInstanceError):
            stats.bits = 3
        # The numbering kept: no map, the order block priced; a detail layer by the global solver.
        kept, same = gab.compress(V, F, reorder=False, return_stats=True)
        self.assertEqual(kept, gab.compress(V, F, reorder=False))
        self.assertIsNone(same.order)
        self.assertFalse(same.reordered)
        self.assertGreater(same.order_bytes, 0)
        _, fine = gab.compress(V, F, error=1e-4, detail="on", solver="global", ordering="nd", return_stats=True)
        self.assertTrue(fine.detail)
        self.assertGreater(fine.detail_bytes, 0)
        self.assertGreater(fine.anchor_rms_rel, fine.rms_rel)
        self.assertEqual((fine.solver, fine.ordering), ("global", "nd"))

    def test_the_report_struct_matches_the_library(self):
        """gab._capi.CompressReport is gab_compress_report field for field: the library's init of a larger
        buffer says how large its struct is."""
        import ctypes
        from gab import _capi

        buffer = ctypes.create_string_buffer(4096)
        _capi.LIB.gab_compress_report_init(ctypes.cast(buffer, ctypes.POINTER(_capi.CompressReport)), len(buffer))
        self.assertEqual(ctypes.c_size_t.from_buffer(buffer).value, ctypes.sizeof(_capi.CompressReport))

    def test_max_memory_bounds_the_decode(self):
        V, F = bumpy_torus(12, 10)
        data = gab.compress(V, F)
        with self.assertRaises(gab.GabError) as e:
            gab.decompress(data, max_memory=20000)
        self.assertEqual(e.exception.name, "GAB_E_RESOURCE_EXHAUSTED")
        self.assertIn("over its memory limit of 1 MiB", str(e.exception))
        self.assertEqual(gab.decompress(data, max_memory=-1)[0].tolist(), gab.decompress(data)[0].tolist())
        self.assertEqual(gab.decompress(data, threads=2)[0].tolist(), gab.decompress(data)[0].tolist())

    def test_decompress_ordering_is_the_cli_s(self):
        """ordering= is `gab decompress --ordering`: a global-solver file's
        factorizations take it; 'auto' is the file's own (AMD on a small
        mesh); another rounds differently, the shape the same to 1e-11 of
        the diagonal."""
        V, F = bumpy_torus(40, 20)
        data = gab.compress(V, F, error=2e-3, solver="global")
        own = gab.decompress(data)[0]
        self.assertEqual(gab.decompress(data, ordering="auto")[0].tolist(), own.tolist())
        self.assertEqual(gab.decompress(data, ordering="amd")[0].tolist(), own.tolist())
        nd = gab.decompress(data, ordering="nd", threads=2)[0]
        self.assertFalse(np.array_equal(nd, own), "nd should round differently: is the ordering passed on?")
        self.assertLess(np.max(np.abs(nd - own)), 1e-11 * np.linalg.norm(V.max(0) - V.min(0)))
        self.assertEqual(gab.decompress(data, ordering="nd")[0].tolist(), nd.tolist())  # any thread count
        with self.assertRaisesRegex(ValueError, r"^gab\.decompress: ordering must be 'auto', 'amd' or 'nd', "
                                                r"got 'natural'$"):
            gab.decompress(data, ordering="natural")  # gab.Cholesky's, not the codec's
        with self.assertRaisesRegex(TypeError, r"^gab\.decompress: ordering must be 'auto', 'amd' or 'nd', "
                                               r"got int$"):
            gab.decompress(data, ordering=2)
        with self.assertRaisesRegex(ValueError, r"^gab\.decompress: threads must be in 0\.\.64, got 65$"):
            gab.decompress(data, threads=65)

    def test_the_options_structs_match_the_library(self):
        """gab._capi's option structs are gab.h's field for field: the library's init of a larger buffer says
        how large its struct is."""
        import ctypes
        from gab import _capi

        for struct, init in [(_capi.CompressOptions, _capi.LIB.gab_compress_options_init),
                             (_capi.DecompressOptions, _capi.LIB.gab_decompress_options_init),
                             (_capi.CholeskyOptions, _capi.LIB.gab_cholesky_options_init)]:
            with self.subTest(struct=struct.__name__):
                buffer = ctypes.create_string_buffer(4096)
                init(ctypes.cast(buffer, ctypes.POINTER(struct)), len(buffer))
                self.assertEqual(ctypes.c_size_t.from_buffer(buffer).value, ctypes.sizeof(struct))

    def test_read_mesh(self):
        """What a file held beyond what read_mesh returns is named by one
        DroppedDataWarning: data gab does not carry ("not carried") and,
        without return_attributes, the attributes it read ("not returned");
        a plain file, or one whose attributes are returned, warns of nothing."""
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "quad.off")
            with open(path, "w") as f:
                f.write("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
            with self.assertWarns(gab.DroppedDataWarning) as w:
                V, F = gab.read_mesh(path)
            self.assertEqual(str(w.warning), path + ": not carried: 1 polygons of 4 or more corners "
                             "(fan-triangulated)")
            self.assertEqual(V.shape, (4, 3))
            self.assertEqual(F.tolist(), [[0, 1, 2], [0, 2, 3]])
            obj = os.path.join(folder, "normals.obj")
            with open(obj, "w") as f:
                f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n")
            with self.assertWarns(gab.DroppedDataWarning) as w:
                gab.read_mesh(obj)
            self.assertEqual(str(w.warning), obj + ": not returned: 1 normals (per corner); "
                             "read_mesh(..., return_attributes=True) returns them")
            with warnings.catch_warnings():
                warnings.simplefilter("error")  # every attribute returned: nothing to name
                V, F, attributes = gab.read_mesh(obj, return_attributes=True)
            self.assertEqual(len(attributes), 1)
            self.assertEqual((attributes[0].kind, attributes[0].label), ("normal", "normals"))
            self.assertEqual(attributes[0].values.tolist(), [[0, 0, 1]])
            self.assertEqual(attributes[0].corners.tolist(), [[0, 0, 0]])
            grouped = os.path.join(folder, "grouped.obj")
            with open(grouped, "w") as f:
                f.write("g part\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n")
            with self.assertWarns(gab.DroppedDataWarning) as w:
                gab.read_mesh(grouped, return_attributes=True)
            self.assertEqual(str(w.warning), grouped + ": not carried: 1 groups (g)")
            with self.assertWarns(gab.DroppedDataWarning) as w:
                gab.read_mesh(grouped)
            self.assertEqual(str(w.warning), grouped + ": not carried: 1 groups (g); not returned: 1 normals (per "
                             "corner); read_mesh(..., return_attributes=True) returns them")
            plain = os.path.join(folder, "plain.off")
            with open(plain, "w") as f:
                f.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                V, F = gab.read_mesh(plain)
                self.assertEqual(gab.read_mesh(plain, return_attributes=True)[2], [])
            self.assertEqual(F.tolist(), [[0, 1, 2]])
            with self.assertRaises(gab.GabError) as e:
                gab.read_mesh(os.path.join(folder, "missing.off"))
            self.assertEqual(e.exception.name, "GAB_E_IO")
            self.assertIn("missing.off", str(e.exception))
            self.assertTrue(str(e.exception).startswith("gab.read_mesh: "))

    def test_version(self):
        self.assertRegex(gab.version(), r"^\d+\.\d+\.\d+$")
        self.assertEqual(gab.__version__, gab.version())

    def test_shared_meshes(self):
        """The small shared meshes round trip (GAB_PYTHON_ALL_MESHES=1: all of them)."""
        folder = os.environ.get("GAB_SHARED_MESHES", "")
        if not os.path.isdir(folder):
            self.skipTest(f"no shared meshes in {folder!r}")
        names = sorted(os.listdir(folder))
        if os.environ.get("GAB_PYTHON_ALL_MESHES") != "1":
            names = [n for n in names if n in ("bunny-small.off", "camel-head.off")]
        for name in names:
            if not name.endswith((".off", ".obj", ".ply")):
                continue
            with self.subTest(mesh=name):
                V, F = gab.read_mesh(os.path.join(folder, name))
                data, stats = gab.compress(V, F, error=1e-3, threads=0, return_stats=True)
                W, G = gab.decompress(data)
                self.assertTrue(oriented_set(G) == oriented_set(stats.order[F]))  # (a diff of them takes minutes)
                self.assertLessEqual(relative_rms(V, W[stats.order]), 1e-3)


if __name__ == "__main__":
    unittest.main()
