#!/usr/bin/env bash
# Regenerates tests/fuzz/corpus/gab (the .gab fuzzer's seeds and the golden
# files of tests/codec/pipeline/golden_file_test.cpp) with the gab binary given as $1:
#   bash tests/fuzz/make_gab_seeds.sh build/apps/gab
# Each seed is one options byte (see gab_fuzzer.cpp) then a file made from
# the 10 x 6 torus of gab_fuzz_mesh.h: one per variant of format version 2;
# torus-iterative-large from its 192 x 180 torus (past 2^14 vertices, where
# operators 2 and 3 predict a chunk around its vertices alone).
# The seeds are golden files (their bytes are pinned): regenerate them only
# for a new format version, then update the pinned figures in the golden
# test. A new variant adds its line and seed beside the others. The files
# that keep the input's numbering say --keep-order (the default numbers the
# vertices in traversal order since issue 34; torus-reordered is that one).
# torus-operator1* and torus-operator2* are not made here: operators 1 and
# 2's files (the iterative operators before 3, header byte 12), which
# today's encoder no longer writes, kept as earlier encoders made them
# (torus-iterative*'s options with those encoders).
set -euo pipefail
gab="$1"
here="$(cd "$(dirname "$0")" && pwd)"
out="$here/corpus/gab"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
torus() {
python3 - "$@" <<'PY'
import math, sys
n, m = int(sys.argv[2]), int(sys.argv[3])
with open(sys.argv[1], "w") as f:
    f.write("OFF\n%d %d 0\n" % (n * m, 2 * n * m))
    for i in range(n):
        for j in range(m):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
            f.write("%.17g %.17g %.17g\n" % ((1 + 0.3 * math.cos(v)) * math.cos(u),
                                            (1 + 0.3 * math.cos(v)) * math.sin(u), 0.3 * math.sin(v)))
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            f.write("3 %d %d %d\n3 %d %d %d\n" % (a, b, c, a, c, d))
PY
}
# The 10 x 6 torus with an attribute of each kind (gab_fuzz_mesh.h's
# attributed_seed_torus): binary PLY, float32 normals, uchar colours, a float
# "quality", per-corner texture coordinates as MeshLab's face texcoord list.
attributed() {
python3 - "$@" <<'PY'
import math, struct, sys
n, m = 10, 6
with open(sys.argv[1], "wb") as out:
    out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
               "property double x\nproperty double y\nproperty double z\n"
               "property float nx\nproperty float ny\nproperty float nz\n"
               "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float quality\n"
               "element face %d\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
               "end_header\n" % (n * m, 2 * n * m)).encode())
    for i in range(n):
        for j in range(m):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
            out.write(struct.pack("<3d", (1 + 0.3 * math.cos(v)) * math.cos(u), (1 + 0.3 * math.cos(v)) * math.sin(u),
                                  0.3 * math.sin(v)))
            out.write(struct.pack("<3f", math.cos(v) * math.cos(u), math.cos(v) * math.sin(u), math.sin(v)))
            out.write(struct.pack("<3Bf", 25 * i, 40 * j, 128, i + j / 4.0))
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            ua, ub, uc, ud = (i / 10, j / 6), ((i + 1) / 10, j / 6), ((i + 1) / 10, (j + 1) / 6), (i / 10, (j + 1) / 6)
            for tri, uv in (((a, b, c), (ua, ub, uc)), ((a, c, d), (ua, uc, ud))):
                out.write(struct.pack("<B3i", 3, *tri))
                out.write(struct.pack("<B6f", 6, *[x for p in uv for x in p]))
PY
}
torus "$tmp/torus.off" 10 6
attributed "$tmp/attributed.ply"
torus "$tmp/large.off" 192 180
c() { "$gab" compress -i "$tmp/torus.off" "$@" 2>/dev/null; }
c -o "$tmp/full.gab" --anchors 20 --chunk-growth 1.5 --layout selection --solver global --keep-order
c -o "$tmp/geo.gab" --anchors 12 --geometry-only --bits 8 --chunk-growth 2 --layout selection --solver global
c -o "$tmp/coarse.gab" --error 0.01 --bits 6 --chunk-growth 2 --layout selection --solver global --keep-order
c -o "$tmp/refined.gab" --anchors 16 --refine --chunk-growth 2 --layout selection --keep-order
c -o "$tmp/levels.gab" --anchors 40 --initial 4 --layout levels --chunk-growth 1.5 --solver global --keep-order
c -o "$tmp/levels-refined.gab" --anchors 24 --initial 3 --layout levels --refine --keep-order
c -o "$tmp/ordered.gab" --anchors 20 --chunk-growth 1.5 --solver global --keep-order
c -o "$tmp/reordered.gab" --anchors 20 --chunk-growth 1.5 --reorder --solver global
c -o "$tmp/nd.gab" --anchors 20 --chunk-growth 1.5 --ordering nd --solver global --keep-order
c -o "$tmp/detail.gab" --error 1e-4 --detail on --solver global --keep-order
c -o "$tmp/detail-geo.gab" --error 1e-4 --detail on --geometry-only --solver global
c -o "$tmp/iterative.gab" --anchors 20 --chunk-growth 1.5 --solver iterative --keep-order
c -o "$tmp/iterative-selection.gab" --anchors 20 --chunk-growth 1.5 --layout selection --solver iterative --keep-order
c -o "$tmp/iterative-detail.gab" --error 1e-4 --detail on --solver iterative --keep-order
"$gab" compress -i "$tmp/large.off" -o "$tmp/iterative-large.gab" --anchors 300 --solver iterative --keep-order 2>/dev/null
"$gab" compress -i "$tmp/attributed.ply" -o "$tmp/attributes.gab" --anchors 20 --chunk-growth 1.5 2>/dev/null
"$gab" compress -i "$tmp/attributed.ply" -o "$tmp/attributes-detail.gab" --error 1e-4 --detail on 2>/dev/null
mkdir -p "$out"
find "$out" -name 'torus-*' ! -name 'torus-operator[12]*' -delete
{ printf '\x00'; cat "$tmp/full.gab"; } > "$out/torus-full"
{ printf '\x16'; cat "$tmp/full.gab"; } > "$out/torus-prefix-5"
{ printf '\x01'; cat "$tmp/geo.gab"; } > "$out/torus-geometry-only"
{ printf '\x00'; cat "$tmp/coarse.gab"; } > "$out/torus-coarse"
{ printf '\x00'; cat "$tmp/refined.gab"; } > "$out/torus-refined"
{ printf '\x00'; cat "$tmp/levels.gab"; } > "$out/torus-levels"
{ printf '\x2a'; cat "$tmp/levels.gab"; } > "$out/torus-levels-prefix-10"
{ printf '\x00'; cat "$tmp/levels-refined.gab"; } > "$out/torus-levels-refined"
{ printf '\x00'; cat "$tmp/ordered.gab"; } > "$out/torus-ordered"
{ printf '\x00'; cat "$tmp/reordered.gab"; } > "$out/torus-reordered"
{ printf '\x00'; cat "$tmp/nd.gab"; } > "$out/torus-nd"
{ printf '\x00'; cat "$tmp/detail.gab"; } > "$out/torus-detail"
{ printf '\x01'; cat "$tmp/detail-geo.gab"; } > "$out/torus-detail-geometry-only"
{ printf '\x00'; cat "$tmp/iterative.gab"; } > "$out/torus-iterative"
{ printf '\x2a'; cat "$tmp/iterative.gab"; } > "$out/torus-iterative-prefix-10"
{ printf '\x00'; cat "$tmp/iterative-selection.gab"; } > "$out/torus-iterative-selection"
{ printf '\x00'; cat "$tmp/iterative-detail.gab"; } > "$out/torus-iterative-detail"
{ printf '\x00'; cat "$tmp/iterative-large.gab"; } > "$out/torus-iterative-large"
{ printf '\x00'; cat "$tmp/attributes.gab"; } > "$out/torus-attributes"
{ printf '\x2a'; cat "$tmp/attributes.gab"; } > "$out/torus-attributes-prefix-10"
{ printf '\x00'; cat "$tmp/attributes-detail.gab"; } > "$out/torus-attributes-detail"
