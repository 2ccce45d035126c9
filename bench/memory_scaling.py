#!/usr/bin/env python3
"""Peak memory of gab compress and gab decompress against the mesh's size.

Run (from the repository root, after building build/apps/gab and the quick
start's data/meshes/):

    python3 bench/memory_scaling.py --svg docs/memory-scaling.svg

Subdivides data/meshes/bunny00.off (`gab subdivide --levels L`, L = 2, 3, 4:
0.6M, 2.4M and 9.6M vertices, and --levels for others) into a scratch
folder, then compresses each with default options and decodes the file,
every run its own process under /usr/bin/time (peak resident set, wall
seconds). Prints a markdown table; with --svg also writes the plot (peak
MB against vertices, both runs, and the bytes per vertex each takes).
Standard library only. Needs about 1 GB of disk and, at 9.6M vertices,
about 2.5 GB of memory.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def measured(cmd):
    """(wall seconds, peak RSS in MB, stdout) of one run of cmd."""
    t0 = time.perf_counter()
    r = subprocess.run(["/usr/bin/time", "-f", "%M"] + cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True)
    seconds = time.perf_counter() - t0
    if r.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), r.stderr))
    return seconds, int(r.stderr.strip().split("\n")[-1]) / 1024.0, r.stdout


def svg_plot(rows, path):
    """Peak MB against vertices (linear axes from 0), compress and decompress."""
    w, h, left, bottom, top, right = 760, 400, 70, 50, 30, 230
    nmax = max(r["n"] for r in rows) * 1.05
    mmax = max(max(r["compress_mb"], r["decompress_mb"]) for r in rows) * 1.1
    x = lambda n: left + (w - left - right) * n / nmax  # noqa: E731
    y = lambda mb: h - bottom - (h - bottom - top) * mb / mmax  # noqa: E731
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
           'font-size="12"><rect width="100%%" height="100%%" fill="white"/>' % (w, h)]
    out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (left, h - bottom, w - right, h - bottom))
    out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (left, h - bottom, left, top))
    step = 2 if nmax < 12e6 else 5
    for k in range(0, int(nmax / 1e6) + 1, step):
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%dM</text>' % (x(k * 1e6), h - bottom + 16, k))
    for mb in range(0, int(mmax) + 1, 500):
        out.append('<text x="%d" y="%.1f" text-anchor="end">%d</text>' % (left - 6, y(mb) + 4, mb))
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, y(mb), w - right, y(mb)))
    out.append('<text x="%d" y="%d" text-anchor="middle">vertices</text>' % ((left + w - right) // 2, h - 12))
    out.append('<text x="16" y="%d" transform="rotate(-90 16 %d)" text-anchor="middle">peak RSS, MB</text>'
               % (h // 2, h // 2))
    for key, colour, label in (("compress_mb", "#c0392b", "gab compress"), ("decompress_mb", "#2471a3",
                                                                            "gab decompress")):
        points = " ".join("%.1f,%.1f" % (x(r["n"]), y(r[key])) for r in rows)
        out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>' % (points, colour))
        for r in rows:
            out.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="%s"/>' % (x(r["n"]), y(r[key]), colour))
        last = rows[-1]
        out.append('<text x="%.1f" y="%.1f" fill="%s">%s (%.0f B/vertex)</text>'
                   % (x(last["n"]) + 8, y(last[key]) + 4, colour, label, last[key] * 1048576 / last["n"]))
    # The decoded mesh alone: 3 doubles a vertex and 3 int32 for each of its
    # about 2 triangles, what any decoder that returns it holds at the end.
    mesh_mb = lambda n: 48.0 * n / 1048576  # noqa: E731
    out.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#888" stroke-dasharray="5,4"/>'
               % (x(0), y(0), x(rows[-1]["n"]), y(mesh_mb(rows[-1]["n"]))))
    out.append('<text x="%.1f" y="%.1f" fill="#666">the mesh itself (48 B/vertex)</text>'
               % (x(rows[-1]["n"]) + 8, y(mesh_mb(rows[-1]["n"])) + 4))
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gab", default=os.path.join(ROOT, "build", "apps", "gab"))
    ap.add_argument("--mesh", default=os.path.join(ROOT, "data", "meshes", "bunny00.off"))
    ap.add_argument("--levels", default="2,3,4", help="subdivision levels, a comma list")
    ap.add_argument("--svg", default=None, help="also write the plot here")
    ap.add_argument("--json", default=None, help="also write the rows here")
    args = ap.parse_args()
    for path in (args.gab, args.mesh):
        if not os.path.exists(path):
            sys.exit("missing: %s" % path)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for level in (int(s) for s in args.levels.split(",")):
            mesh = os.path.join(work, "mesh.off")
            subprocess.run([args.gab, "subdivide", args.mesh, "-o", mesh, "--levels", str(level)], check=True,
                           stdout=subprocess.DEVNULL)
            packed = os.path.join(work, "mesh.gab")
            enc_s, enc_mb, out = measured([args.gab, "compress", "-i", mesh, "-o", packed, "--json", "--quiet"])
            stats = json.loads(out)
            dec_s, dec_mb, _ = measured([args.gab, "decompress", "-i", packed, "-o", os.path.join(work, "out.ply"),
                                         "--quiet"])
            rows.append({"levels": level, "n": stats["n"], "bytes": stats["bytes"], "compress_s": enc_s,
                         "compress_mb": enc_mb, "decompress_s": dec_s, "decompress_mb": dec_mb})
            print("[%d vertices: done]" % stats["n"], file=sys.stderr, flush=True)
            for name in ("mesh.off", "mesh.gab", "out.ply"):
                os.remove(os.path.join(work, name))
    print("\n| vertices | file bytes | compress s | compress peak MB (B/vertex) | decompress s | "
          "decompress peak MB (B/vertex) |")
    print("|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print("| %d | %d | %.1f | %.0f (%.0f) | %.1f | %.0f (%.0f) |" % (
            r["n"], r["bytes"], r["compress_s"], r["compress_mb"], r["compress_mb"] * 1048576 / r["n"],
            r["decompress_s"], r["decompress_mb"], r["decompress_mb"] * 1048576 / r["n"]))
    if args.svg:
        svg_plot(rows, args.svg)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
