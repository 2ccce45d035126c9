"""gab.Attribute through compress / decompress / read_mesh / write_mesh, and
CompressStats' per-attribute figures (run by ctest and .ci/run)."""

import math
import os
import tempfile
import unittest
import warnings

import numpy as np

import gab

N, M = 30, 20  # the torus: N x M vertices


def torus():
    """A bumpy closed torus, vertex (i, j) = i M + j: (V, F)."""
    i, j = np.meshgrid(np.arange(N), np.arange(M), indexing="ij")
    u, v = 2 * math.pi * i / N, 2 * math.pi * j / M
    V = np.stack([(1 + 0.3 * np.cos(v)) * np.cos(u), (1 + 0.3 * np.cos(v)) * np.sin(u), 0.3 * np.sin(v)], -1)
    V = V.reshape(-1, 3) * (1 + 0.08 * np.sin(3.1 * V.reshape(-1, 3)[:, :1] + 1.3))
    a = (i * M + j).ravel()
    b = (((i + 1) % N) * M + j).ravel()
    c = (((i + 1) % N) * M + (j + 1) % M).ravel()
    d = (i * M + (j + 1) % M).ravel()
    F = np.stack([np.stack([a, b, c], -1), np.stack([a, c, d], -1)], 1).reshape(-1, 3).astype(np.int32)
    return V, F


def vertex_normals(V, F):
    """Area-weighted vertex normals, unit length."""
    cross = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    normals = np.zeros_like(V)
    for k in range(3):
        np.add.at(normals, F[:, k], cross)
    return normals / np.linalg.norm(normals, axis=1, keepdims=True)


def torus_uv():
    """Texture coordinates (i/N, j/M) on an (N+1) x (M+1) grid, per corner of torus()'s
    triangles: seams where the torus closes. (values, corners)."""
    i, j = np.meshgrid(np.arange(N + 1), np.arange(M + 1), indexing="ij")
    values = np.stack([i / N, j / M], -1).reshape(-1, 2)
    i, j = np.meshgrid(np.arange(N), np.arange(M), indexing="ij")
    e = lambda di, dj: ((i + di) * (M + 1) + j + dj).ravel()  # noqa: E731
    corners = np.stack([np.stack([e(0, 0), e(1, 0), e(1, 1)], -1), np.stack([e(0, 0), e(1, 1), e(0, 1)], -1)], 1)
    return values, corners.reshape(-1, 3)


def with_attributes():
    """(V, F, attributes): normals, per-corner texture coordinates, RGBA bytes and a generic 'quality'."""
    V, F = torus()
    uv, uv_corners = torus_uv()
    n = len(V)
    rgba = np.stack([np.arange(n) * 7 % 256, np.arange(n) % 200, 255 - np.arange(n) % 256, np.full(n, 255)],
                    -1).astype(np.uint8)
    quality = np.sin(0.1 * np.arange(n)) * 3 + 1
    return V, F, [gab.Attribute("normal", vertex_normals(V, F), value_type="float32"),
                  gab.Attribute("texcoord", uv, corners=uv_corners, value_type="float32"),
                  gab.Attribute("color", rgba),  # value_type from the dtype: 'uint8', coded exactly
                  gab.Attribute("generic", quality, name="quality", value_type="float64")]


def corner_values(F, attribute, mapping=None):
    """Each corner's value keyed by its triangle (rotated to start at its
    smallest vertex, each through `mapping`) and its vertex: what a decode
    keeps whatever order and first corner the coder chose."""
    F = np.asarray(F)
    mapped = F if mapping is None else np.asarray(mapping)[F]
    values = np.asarray(attribute.values, dtype=np.float64).reshape(len(attribute.values), -1)
    elements = F if attribute.corners is None else np.asarray(attribute.corners)
    table = {}
    for f in range(len(F)):
        tri = mapped[f].tolist()
        first = tri.index(min(tri))
        key = tuple(tri[first:] + tri[:first])
        for k in range(3):
            table[key + (tri[k],)] = values[elements[f, k]]
    return table


def largest_error(F, given, G, decoded, mapping=None, directions=False, decoded_mapping=None):
    """The largest difference at the same corners (degrees for directions):
    `given` on F (its vertices through `mapping`) against `decoded` on G
    (through `decoded_mapping`)."""
    a, b = corner_values(F, given, mapping), corner_values(G, decoded, decoded_mapping)
    assert a.keys() == b.keys(), "the decoded corners are not the input's"
    largest = 0.0
    for key, x in a.items():
        y = b[key]
        if directions:
            cosine = np.dot(x, y) / (np.linalg.norm(x) * np.linalg.norm(y))
            largest = max(largest, math.degrees(math.acos(min(1.0, max(-1.0, cosine)))))
        else:
            largest = max(largest, float(np.max(np.abs(x - y))))
    return largest


class AttributeTest(unittest.TestCase):
    def test_every_kind_round_trips_within_its_quantization(self):
        V, F, attributes = with_attributes()
        for reorder in (True, False):
            with self.subTest(reorder=reorder):
                data, stats = gab.compress(V, F, attributes=attributes, reorder=reorder, return_stats=True)
                with warnings.catch_warnings():
                    warnings.simplefilter("error")  # everything returned: nothing to name
                    W, G, decoded = gab.decompress(data, return_attributes=True)
                self.assertEqual(W.shape, V.shape)
                mapping = stats.order if reorder else None
                self.assertEqual([a.kind for a in decoded], ["normal", "texcoord", "color", "generic"])
                self.assertEqual([a.value_type for a in decoded], ["float32", "float32", "uint8", "float64"])
                self.assertEqual([a.name for a in decoded], [None, None, None, "quality"])
                self.assertEqual([a.label for a in decoded],
                                 ["normals", "texture_coordinates", "vertex_colors", "generic:quality"])
                self.assertEqual([a.per_corner for a in decoded], [False, True, False, False])
                self.assertEqual([a.values.shape[1] for a in decoded], [3, 2, 4, 1])
                for a in decoded:
                    self.assertEqual(a.values.dtype, np.float64)
                self.assertEqual(decoded[1].corners.shape, F.shape)
                self.assertEqual(decoded[1].corners.dtype, np.int32)
                errors = [largest_error(F, attributes[k], G, decoded[k], mapping, directions=k == 0) for k in range(4)]
                quality = attributes[3].values
                self.assertLessEqual(errors[0], 0.6)  # 8 bits: a lattice of about 4^8 directions
                self.assertLessEqual(errors[1], 0.5 / 1023 * (1 + 1e-9))  # half a step of 2^10 - 1 over the span
                self.assertEqual(errors[2], 0)  # uint8: exact
                self.assertLessEqual(errors[3], 0.5 * np.ptp(quality) / 65535 * (1 + 1e-9))
                # What the stats say was coded: the errors seen here, the bytes of the file.
                self.assertEqual(len(stats.attributes), 4)
                self.assertIsInstance(stats.attributes[0], gab.AttributeStats)
                self.assertEqual([a.label for a in stats.attributes],
                                 ["normals", "texture_coordinates", "vertex_colors", "generic:quality"])
                self.assertEqual([a.kind for a in stats.attributes], ["normal", "texcoord", "color", "generic"])
                self.assertEqual([a.per_corner for a in stats.attributes], [False, True, False, False])
                self.assertEqual([stats.attributes[k].bits for k in (0, 1, 3)], [8, 10, 16])
                self.assertEqual(stats.attributes[0].elements, len(V))
                self.assertEqual(stats.attributes[1].elements, len(decoded[1].values))
                self.assertAlmostEqual(stats.attributes[0].max_error, errors[0], delta=1e-6)
                self.assertAlmostEqual(stats.attributes[1].max_error, errors[1], delta=1e-12)
                self.assertEqual(stats.attributes[2].max_error, 0)
                self.assertAlmostEqual(stats.attributes[3].max_error, errors[3], delta=1e-12)
                self.assertEqual(stats.attribute_bytes, sum(a.bytes for a in stats.attributes))
                self.assertEqual(stats.bytes, len(data))
                self.assertEqual(stats.bytes, stats.geometry_bytes + stats.connectivity_bytes + stats.order_bytes
                                 + stats.attribute_bytes)
                self.assertEqual(stats.merged_vertices, 0)
                self.assertEqual(data, gab.compress(V, F, attributes=attributes, reorder=reorder))  # the same file

    def test_inputs_of_other_types_and_shapes(self):
        """Lists, 2-D generics, int32 colours and int64 corners are the same
        attributes; the value type follows the values' dtype unless given."""
        V, F, attributes = with_attributes()
        uv, corners = attributes[1].values, attributes[1].corners
        same = [gab.Attribute("normal", attributes[0].values.tolist(), value_type="float32"),
                gab.Attribute("texcoord", uv.tolist(), corners=corners.astype(np.int64).tolist(), value_type="float32"),
                gab.Attribute("color", attributes[2].values.astype(np.int32), value_type="uint8"),
                gab.Attribute("generic", attributes[3].values.reshape(-1, 1), name="quality", value_type="float64")]
        data = gab.compress(V, F, attributes=same)
        self.assertEqual(data, gab.compress(V, F, attributes=attributes))
        self.assertEqual(gab.compress(V, F, attributes=[]), gab.compress(V, F))  # none: the plain file
        # The value type, when not given: the values' dtype (an integer of another width: int32 or uint32).
        for values, value_type in [(V[:, :2], "float64"), (V[:, :2].astype(np.float32), "float32"),
                                   (V[:, :2].tolist(), "float64"), (np.arange(2 * len(V)).reshape(-1, 2) % 100, "int32"),
                                   ((np.arange(2 * len(V)).reshape(-1, 2) % 100).astype(np.uint64), "uint32"),
                                   ((np.arange(2 * len(V)).reshape(-1, 2) % 100).astype(np.int16), "int16")]:
            with self.subTest(value_type=value_type):
                data, stats = gab.compress(V, F, attributes=[gab.Attribute("generic", values, name="g")],
                                           return_stats=True)
                _, _, decoded = gab.decompress(data, return_attributes=True)
                self.assertEqual(decoded[0].value_type, value_type)
                if value_type.startswith(("int", "uint")):
                    self.assertEqual(stats.attributes[0].max_error, 0)  # integers: exact

    def test_copies_of_a_vertex_are_merged_and_the_map_covers_the_input(self):
        """A triangle soup (as a file split along seams): the traversal
        order merges the copies, stats.merged_vertices counts them, the map
        has a row per input vertex; per-vertex values that differ between
        copies come back per corner."""
        V, F = torus()
        soup_V = V[F.ravel()]
        soup_F = np.arange(3 * len(F), dtype=np.int32).reshape(-1, 3)
        shade = gab.Attribute("generic", (np.arange(len(soup_V)) % 7).astype(np.uint8), name="shade")
        data, stats = gab.compress(soup_V, soup_F, attributes=[shade], return_stats=True)
        self.assertEqual(stats.n, len(V))
        self.assertEqual(stats.n + stats.merged_vertices, len(soup_V))
        self.assertEqual(stats.order.shape, (len(soup_V),))
        self.assertEqual(stats.order.max(), len(V) - 1)
        self.assertTrue(stats.attributes[0].per_corner)
        W, G, decoded = gab.decompress(data, return_attributes=True)
        self.assertEqual(len(W), len(V))
        self.assertTrue(decoded[0].per_corner)
        self.assertEqual(largest_error(soup_F, shade, G, decoded[0], stats.order), 0)

    def test_attribute_bits_are_keywords(self):
        V, F, attributes = with_attributes()
        base, coarse = gab.compress(V, F, attributes=attributes, return_stats=True)
        self.assertEqual(base, gab.compress(V, F, attributes=attributes, normal_bits=8, uv_bits=10,
                                            color_bits=8, generic_bits=16))  # the defaults
        fine = gab.compress(V, F, attributes=attributes, normal_bits=12, uv_bits=14, generic_bits=20,
                            return_stats=True)[1]
        self.assertEqual([a.bits for a in fine.attributes][:2], [12, 14])
        self.assertLess(fine.attributes[0].max_error, coarse.attributes[0].max_error / 4)
        self.assertLess(fine.attributes[1].max_error, coarse.attributes[1].max_error / 4)
        self.assertGreater(fine.attribute_bytes, coarse.attribute_bytes)
        self.assertEqual(fine.attributes[2].bytes, coarse.attributes[2].bytes)  # uint8: exact at any bits
        cases = [(ValueError, r"^gab\.compress: normal_bits must be in 2\.\.16, got 17$", dict(normal_bits=17)),
                 (ValueError, r"^gab\.compress: uv_bits must be in 1\.\.31, got 0$", dict(uv_bits=0)),
                 (TypeError, r"^gab\.compress: color_bits must be an integer, got float$", dict(color_bits=8.0)),
                 (ValueError, r"^gab\.compress: generic_bits must be in 1\.\.31, got 32$", dict(generic_bits=32))]
        for error, pattern, keywords in cases:
            with self.subTest(pattern=pattern):
                with self.assertRaisesRegex(error, pattern):
                    gab.compress(V, F, attributes=attributes, **keywords)

    def test_bad_attributes_are_named(self):
        V, F = torus()
        n, t = len(V), len(F)
        uv, corners = torus_uv()
        good = gab.Attribute("texcoord", uv[:n])
        bad_corners = corners.copy()
        bad_corners[2, 1] = len(uv)
        not_finite = uv[:n].copy()
        not_finite[2, 1] = np.nan
        call = r"^gab\.compress: "
        cases = [
            (TypeError, call + r"attributes must be a list of gab\.Attribute, got dict$", {"normal": V}),
            (TypeError, call + r"attributes\[1\] must be a gab\.Attribute, got tuple$", [good, ("normal", V)]),
            (ValueError, call + r"attributes holds 65: at most 64$", [good] * 65),
            (ValueError, call + r"attributes\[0\]\.kind must be 'normal', 'texcoord', 'color' or 'generic', "
                                r"got 'uv'$", [gab.Attribute("uv", uv[:n])]),
            (TypeError, call + r"attributes\[0\]\.kind must be .*, got int$", [gab.Attribute(0, V)]),
            (ValueError, call + r"attributes\[0\]\.values must have shape \(k, 3\) for a 'normal' attribute, "
                                r"got \(600, 2\)$", [gab.Attribute("normal", uv[:n])]),
            (ValueError, call + r"attributes\[0\]\.values must have shape \(k, 3 or 4\) for a 'color' attribute, "
                                r"got \(600,\)$", [gab.Attribute("color", V[:, 0])]),
            (TypeError, call + r"attributes\[0\]\.values must hold real numbers, got dtype complex128$",
             [gab.Attribute("normal", V + 0j)]),
            (ValueError, call + r"attributes\[0\]\.values has 651 rows: per vertex \(corners=None\) one a vertex, "
                                r"n = 600$", [gab.Attribute("texcoord", uv)]),
            (ValueError, call + r"attributes\[0\]\.corners must have shape \(t, 3\) = \(1200, 3\), got \(1199, 3\)$",
             [gab.Attribute("texcoord", uv, corners=corners[1:])]),
            (ValueError, call + r"attributes\[0\]\.corners must have shape \(k, 3\), got \(3600,\)$",
             [gab.Attribute("texcoord", uv, corners=corners.ravel())]),
            (TypeError, call + r"attributes\[0\]\.corners must hold integers, got dtype float64$",
             [gab.Attribute("texcoord", uv, corners=corners + 0.5)]),
            (ValueError, call + r"attributes\[0\]\.corners\[2, 1\] is 651: out of range \[0, 651\)$",
             [gab.Attribute("texcoord", uv, corners=bad_corners)]),
            (ValueError, call + r"attributes\[0\]\.name must name a 'generic' attribute, got None$",
             [gab.Attribute("generic", V[:, 0])]),
            (TypeError, call + r"attributes\[0\]\.name must be a str or None, got int$",
             [gab.Attribute("generic", V[:, 0], name=5)]),
            (ValueError, call + r"attributes\[0\]\.name is 'uv': only a 'generic' attribute has a name$",
             [gab.Attribute("texcoord", uv[:n], name="uv")]),
            (ValueError, call + r"attributes\[0\]\.value_type must be 'int8', .* or 'float64', got 'half'$",
             [gab.Attribute("texcoord", uv[:n], value_type="half")]),
        ]
        for error, pattern, attributes in cases:
            with self.subTest(pattern=pattern):
                with self.assertRaisesRegex(error, pattern):
                    gab.compress(V, F, attributes=attributes)
        # The values' own checks are the library's, named the same way.
        library = [
            (r"gab.compress: attributes[0]: texture_coordinates: element 2: value is not finite",
             [gab.Attribute("texcoord", not_finite)]),
            (r"gab.compress: attributes[0]: generic:two words: a generic attribute's name is 1 to 255 letters, "
             r"digits, '_', '-' or '.'", [gab.Attribute("generic", V[:, 0], name="two words")]),
            (r"gab.compress: attributes[0]: vertex_colors: element 0: 0.500000 is not a value of its integer type",
             [gab.Attribute("color", np.full((n, 3), 0.5), value_type="uint8")]),
        ]
        for text, attributes in library:
            with self.subTest(text=text):
                with self.assertRaises(gab.GabError) as e:
                    gab.compress(V, F, attributes=attributes)
                self.assertEqual(e.exception.name, "GAB_E_INVALID_ARGUMENT")
                self.assertEqual(str(e.exception), text)
        self.assertEqual(t, 2 * n)

    def test_decompress_names_what_it_does_not_return(self):
        V, F, attributes = with_attributes()
        data, stats = gab.compress(V, F, attributes=attributes, return_stats=True)
        with self.assertWarns(gab.DroppedDataWarning) as w:
            W, G = gab.decompress(data)  # the attributes not asked for
        listed = (f"600 normals (per vertex), {stats.attributes[1].elements} texture_coordinates (per corner), "
                  "600 vertex_colors (per vertex), 600 generic:quality (per vertex)")
        self.assertEqual(str(w.warning), f"not returned: {listed}; decompress(..., return_attributes=True) "
                                         "returns them")
        self.assertEqual(W.shape, V.shape)
        # A level of detail: normals predicted from the surface need every anchor.
        self.assertTrue(stats.attributes[0].from_surface)
        with self.assertWarns(gab.DroppedDataWarning) as w:
            _, _, coarse = gab.decompress(data, anchors=10, return_attributes=True)
        self.assertEqual(str(w.warning), "not decoded: normals (predicted from the whole shape, which this decode "
                                         "does not have: every anchor of a complete file)")
        self.assertEqual([a.kind for a in coarse], ["texcoord", "color", "generic"])
        with self.assertWarns(gab.DroppedDataWarning) as w:
            gab.decompress(data, anchors=10)
        self.assertEqual(str(w.warning), "not decoded: normals (predicted from the whole shape, which this decode "
                                         "does not have: every anchor of a complete file); not returned: "
                                         f"{stats.attributes[1].elements} texture_coordinates (per corner), 600 "
                                         "vertex_colors (per vertex), 600 generic:quality (per vertex); "
                                         "decompress(..., return_attributes=True) returns them")
        # A cut inside the last section: the file's shape, three attributes, the cut said.
        cut = data[: len(data) - stats.attributes[3].bytes // 2]
        with self.assertWarns(gab.TruncatedWarning) as w:
            _, _, partial = gab.decompress(cut, return_attributes=True)
        self.assertEqual(str(w.warning), f"the file is truncated: decoded {stats.chunks} of {stats.chunks} chunks "
                                         f"({stats.anchors} of {stats.anchors} anchors); not decoded: 1 sections "
                                         "past the cut")
        self.assertEqual(len(partial), 3)
        with self.assertRaisesRegex(TypeError, r"^gab\.decompress: return_attributes must be True or False, "
                                               r"got int$"):
            gab.decompress(data, return_attributes=1)

    def test_write_mesh_writes_what_the_format_holds_and_names_the_rest(self):
        V, F, attributes = with_attributes()
        with tempfile.TemporaryDirectory() as folder:
            ply = os.path.join(folder, "torus.ply")
            split = (N + 1) * (M + 1) - N * M  # the seams' copies
            with self.assertWarns(gab.DroppedDataWarning) as w:
                gab.write_mesh(ply, V, F, attributes=attributes)
            self.assertEqual(str(w.warning), f"{ply}: {split} vertices added where per-corner attributes have seams "
                                             "(the format holds them per vertex)")
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                U, H, read = gab.read_mesh(ply, return_attributes=True)
            self.assertEqual(len(U), len(V) + split)
            self.assertEqual([(a.kind, a.value_type, a.name) for a in read],
                             [("normal", "float32", None), ("texcoord", "float32", None), ("color", "uint8", None),
                              ("generic", "float64", "quality")])
            # Corner by corner the same values, the split vertices mapped back by position.
            back = {tuple(p): k for k, p in enumerate(V.tolist())}
            to_input = np.array([back[tuple(p)] for p in U.tolist()])
            self.assertLess(largest_error(F, attributes[0], H, read[0], decoded_mapping=to_input), 1e-6)  # float32
            self.assertLess(largest_error(F, attributes[1], H, read[1], decoded_mapping=to_input), 1e-7)
            self.assertEqual(largest_error(F, attributes[2], H, read[2], decoded_mapping=to_input), 0)
            self.assertEqual(largest_error(F, attributes[3], H, read[3], decoded_mapping=to_input), 0)
            obj = os.path.join(folder, "torus.obj")
            with self.assertWarns(gab.DroppedDataWarning) as w:
                gab.write_mesh(obj, V, F, attributes=attributes)
            self.assertTrue(str(w.warning).startswith(f"{obj}: not written: "), str(w.warning))
            self.assertIn("quality", str(w.warning))
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                gab.write_mesh(os.path.join(folder, "plain.off"), V, F)
            with self.assertRaisesRegex(ValueError, r"^gab\.write_mesh: attributes\[0\]\.kind must be "):
                gab.write_mesh(ply, V, F, attributes=[gab.Attribute("uv", V)])
            with self.assertRaisesRegex(TypeError, r"^gab\.write_mesh: path must be a str, bytes or os\.PathLike, "
                                                   r"got NoneType$"):
                gab.write_mesh(None, V, F)
            with self.assertRaises(gab.GabError) as e:
                gab.write_mesh(os.path.join(folder, "mesh.stl"), V, F)
            self.assertTrue(str(e.exception).startswith("gab.write_mesh: "), str(e.exception))

    def test_the_attribute_structs_match_the_library(self):
        """gab._capi's Attribute and AttributeStats are gab.h's field for
        field: a round trip through both reads every field where the
        library wrote it."""
        import ctypes
        from gab import _capi

        self.assertEqual(ctypes.sizeof(_capi.Attribute), 16 + 3 * ctypes.sizeof(ctypes.c_void_p))
        self.assertEqual(ctypes.sizeof(_capi.AttributeStats), ctypes.sizeof(ctypes.c_void_p) + 16 + 8 + 8 + 8)
        V, F, attributes = with_attributes()
        _, stats = gab.compress(V, F, attributes=attributes[3:], return_stats=True)
        self.assertEqual(stats.attributes[0].label, "generic:quality")
        self.assertGreater(stats.attributes[0].bytes, 0)


if __name__ == "__main__":
    unittest.main()
