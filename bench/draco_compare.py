#!/usr/bin/env python3
"""Geometry rate of Google Draco vs gab at relative vertex RMS targets (default 1e-3).

Run (from the repository root, after building build/apps/gab):

    apt-get install -y draco            # provides draco_encoder / draco_decoder
    python3 bench/draco_compare.py      # all of ../shared/meshes/*.off, gab with --keep-order
    python3 bench/draco_compare.py --meshes ../shared/meshes/horse.off --target 1e-3
    python3 bench/draco_compare.py --reorder      # gab's default files: traversal order (issue 17; default since 34)
    python3 bench/draco_compare.py --reorder --target 3e-4,1e-4,3e-5   # the detail layer (issue 18)

What it measures, for every mesh (ASCII OFF):

* Draco (`draco_encoder -cl 10 -qp Q`): the mesh is written as OBJ with the
  OFF's coordinate text copied verbatim. Geometry bytes at Q are
  size(.drc at -qp Q) - size(.drc at -qp 1) (the -qp 1 file is taken to hold
  the header and the connectivity). The file is decoded with draco_decoder to
  binary PLY and the relative vertex RMS is
  sqrt(mean_i |p_dec(i) - p_i|^2) / bbox diagonal of the original, where, as
  Draco reorders vertices, p_dec(i) is the decoded vertex nearest to original
  vertex i (exact: Draco rounds each position to the nearest point of a
  uniform grid, and every decoded vertex is a grid point; a grid hash with the
  grid's step finds it among 27 cells). Reported: the smallest Q with
  RMS <= target, the Q just below it, and the bits/vertex linearly
  interpolated in log(RMS) between the two to exactly the target.
* gab: `gab compress --error TARGET --keep-order --json` (without
  --reorder: the input's numbering, which the per-vertex check needs, and
  the figures measured before the default became the traversal order; with
  --reorder, gab's default) (bits/vertex of the geometry
  block, rms_rel, anchors, q, detail layer bytes, encode time), `gab
  decompress --json` (decode time, detail time) and `gab diff ORIGINAL
  DECODED --json --samples 0` (rms_rel of the decoded file, checked against
  the compress JSON).

Also whole files: gab's .gab (connectivity + order + geometry) beside
Draco's whole .drc at the same error (its -qp 1 file plus the interpolated
geometry), and their ratio, summed too. With --reorder, gab drops the vertex
order (and `gab diff` per vertex no longer applies: its check is skipped).

Prints markdown tables (summary, whole files, then the per-Q Draco detail). Standard
library only; runs one process at a time. If draco_encoder is not installed it
prints a message and exits 0.
"""

import argparse
import glob
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def read_off(path):
    """Return (coordinate text lines, float positions, faces) of an ASCII OFF."""
    with open(path) as f:
        tokens_lines = [ln for ln in (l.strip() for l in f) if ln and not ln.startswith("#")]
    if not tokens_lines[0].startswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    head = tokens_lines[0][3:].split()
    k = 1
    if not head:
        head = tokens_lines[1].split()
        k = 2
    nv, nf = int(head[0]), int(head[1])
    text, pos = [], []
    for ln in tokens_lines[k:k + nv]:
        t = ln.split()[:3]
        text.append(" ".join(t))
        pos.append((float(t[0]), float(t[1]), float(t[2])))
    faces = []
    for ln in tokens_lines[k + nv:k + nv + nf]:
        t = ln.split()
        m = int(t[0])
        idx = [int(x) for x in t[1:1 + m]]
        for j in range(1, m - 1):  # fan, in case of polygons
            faces.append((idx[0], idx[j], idx[j + 1]))
    return text, pos, faces


def write_obj(path, text, faces):
    with open(path, "w") as f:
        for t in text:
            f.write("v " + t + "\n")
        for a, b, c in faces:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_ply_vertices(path):
    """x, y, z of the vertex element of a PLY (binary little/big endian or ascii)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt = None
    elements = []  # (name, count, [(name, type or ('list', ct, it))])
    for ln in header:
        t = ln.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            elements.append((t[1], int(t[2]), []))
        elif t[0] == "property":
            if t[1] == "list":
                elements[-1][2].append((t[4], ("list", t[2], t[3])))
            else:
                elements[-1][2].append((t[2], t[1]))
    if elements[0][0] != "vertex":
        raise ValueError(f"{path}: first element is not vertex")
    name, count, props = elements[0]
    names = [p[0] for p in props]
    ix, iy, iz = names.index("x"), names.index("y"), names.index("z")
    if fmt == "ascii":
        lines = data[end:].decode("ascii").split("\n")
        out = []
        for ln in lines[:count]:
            t = ln.split()
            out.append((float(t[ix]), float(t[iy]), float(t[iz])))
        return out
    if any(isinstance(p[1], tuple) for p in props):
        raise ValueError(f"{path}: list property in vertex element")
    order = "<" if fmt == "binary_little_endian" else ">"
    rec = struct.Struct(order + "".join(PLY_TYPES[p[1]] for p in props))
    out = []
    for v in rec.iter_unpack(data[end:end + rec.size * count]):
        out.append((v[ix], v[iy], v[iz]))
    return out


def bbox(pos):
    lo = [min(p[k] for p in pos) for k in range(3)]
    hi = [max(p[k] for p in pos) for k in range(3)]
    return lo, hi


def match_rms(orig, dec, lo, step):
    """Squared error sum and stats, matching each original to the nearest decoded vertex.

    Decoded vertices are bucketed by round((d - lo) / step); the nearest grid point
    of an original vertex lies within one cell of its own rounded cell, so the 27
    cells around it hold its nearest decoded vertex. Falls back to a widening
    search if they are empty (never expected)."""
    inv = 1.0 / step
    grid = {}
    for j, d in enumerate(dec):
        key = (round((d[0] - lo[0]) * inv), round((d[1] - lo[1]) * inv), round((d[2] - lo[2]) * inv))
        grid.setdefault(key, []).append(j)
    offs = [(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)]
    offs.sort(key=lambda o: abs(o[0]) + abs(o[1]) + abs(o[2]))
    used = {}
    sse = 0.0
    linf = 0.0
    fallback = 0
    off_center = 0
    for i, p in enumerate(orig):
        kx = round((p[0] - lo[0]) * inv)
        ky = round((p[1] - lo[1]) * inv)
        kz = round((p[2] - lo[2]) * inv)
        best, bj, bo = math.inf, -1, None
        r = 1
        while True:
            cells = offs if r == 1 else [
                (a, b, c) for a in range(-r, r + 1) for b in range(-r, r + 1) for c in range(-r, r + 1)]
            for o in cells:
                lst = grid.get((kx + o[0], ky + o[1], kz + o[2]))
                if lst is None:
                    continue
                for j in lst:
                    d = dec[j]
                    e = (d[0] - p[0]) ** 2 + (d[1] - p[1]) ** 2 + (d[2] - p[2]) ** 2
                    if e < best:
                        best, bj, bo = e, j, o
            # every decoded point closer than r * step lies in the cells searched
            if (bj >= 0 and math.sqrt(best) <= r * step) or r > 64:
                break
            r += 1
            fallback += 1
        if bo != (0, 0, 0):
            off_center += 1
        used[bj] = used.get(bj, 0) + 1
        sse += best
        linf = max(linf, best)
    return {
        "sse": sse, "linf": math.sqrt(linf), "fallback": fallback, "off_center": off_center,
        "decoded_used": len(used),
    }


def simulated_rms(orig, lo, step, diag):
    """RMS of Draco's quantizer applied to the input directly (cross-check)."""
    inv = 1.0 / step
    sse = 0.0
    for p in orig:
        for k in range(3):
            q = math.floor((p[k] - lo[k]) * inv + 0.5)
            sse += (lo[k] + q * step - p[k]) ** 2
    return math.sqrt(sse / len(orig)) / diag


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    return r.stdout


class DracoMesh:
    def __init__(self, name, obj, pos, work):
        self.name, self.obj, self.pos, self.work = name, obj, pos, work
        self.n = len(pos)
        self.lo, hi = bbox(pos)
        self.diag = math.sqrt(sum((hi[k] - self.lo[k]) ** 2 for k in range(3)))
        self.extent = max(hi[k] - self.lo[k] for k in range(3))
        self.base = self.size(1)
        self.cache = {}

    def size(self, qp):
        out = os.path.join(self.work, f"{self.name}.q{qp}.drc")
        run(["draco_encoder", "-i", self.obj, "-o", out, "-cl", "10", "-qp", str(qp)])
        return os.path.getsize(out)

    def measure(self, qp):
        if qp in self.cache:
            return self.cache[qp]
        drc = os.path.join(self.work, f"{self.name}.q{qp}.drc")
        size = self.size(qp)
        ply = os.path.join(self.work, f"{self.name}.q{qp}.ply")
        run(["draco_decoder", "-i", drc, "-o", ply])
        dec = read_ply_vertices(ply)
        step = self.extent / ((1 << qp) - 1)
        m = match_rms(self.pos, dec, self.lo, step)
        geo = size - self.base
        res = {
            "qp": qp, "bytes": size, "geometry_bytes": geo, "bpv": 8.0 * geo / self.n,
            "rms_rel": math.sqrt(m["sse"] / self.n) / self.diag, "linf_rel": m["linf"] / self.diag,
            "sim_rms_rel": simulated_rms(self.pos, self.lo, step, self.diag),
            "n_decoded": len(dec), "decoded_distinct": len(set(dec)),
            **{k: m[k] for k in ("fallback", "off_center", "decoded_used")},
        }
        for f in (drc, ply):
            os.remove(f)
        self.cache[qp] = res
        return res


def tools_missing(gab):
    """Why a comparison cannot run (Draco's tools or the gab binary missing), or None."""
    if shutil.which("draco_encoder") is None or shutil.which("draco_decoder") is None:
        return "draco_encoder/draco_decoder not installed (apt-get install -y draco): skipping"
    if not os.access(gab, os.X_OK):
        return f"gab binary not found at {gab} (build it first): skipping"
    return None


def default_meshes():
    """Every OFF of ../shared/meshes next to the repository."""
    return sorted(glob.glob(os.path.join(ROOT, "..", "shared", "meshes", "*.off")))


def draco_at(dm, target):
    """Smallest qp with rms <= target, and the qp just below it."""
    # uniform quantization: rms ~ step / 2 (sqrt(3 / 12)); start from that guess
    guess = max(2, min(29, math.ceil(math.log2(dm.extent / (2 * target * dm.diag) + 1))))
    qp = guess
    if dm.measure(qp)["rms_rel"] <= target:
        while qp > 2 and dm.measure(qp - 1)["rms_rel"] <= target:
            qp -= 1
    else:
        while dm.measure(qp)["rms_rel"] > target:
            qp += 1
            if qp > 29:
                raise RuntimeError(f"{dm.name}: no qp <= 29 reaches {target}")
    hi = dm.measure(qp)
    lo = dm.measure(qp - 1)
    la, lb, lt = math.log(lo["rms_rel"]), math.log(hi["rms_rel"]), math.log(target)
    t = (la - lt) / (la - lb) if la != lb else 1.0
    interp = lo["bpv"] + t * (hi["bpv"] - lo["bpv"])
    return hi, lo, interp


def gab_at(gab, mesh, target, work, reorder):
    name = os.path.splitext(os.path.basename(mesh))[0]
    out = os.path.join(work, name + ".gab")
    dec = os.path.join(work, name + ".gab.off")
    c = json.loads(run([gab, "compress", "-i", mesh, "-o", out, "--error", repr(target), "--json"] +
                       (["--reorder"] if reorder else ["--keep-order"])))
    d = json.loads(run([gab, "decompress", "-i", out, "-o", dec, "--json"]))
    # Per-vertex distances need the input's numbering, which --reorder drops.
    f = None if reorder else json.loads(run([gab, "diff", mesh, dec, "--json", "--samples", "0"]))
    for p in (out, dec):
        os.remove(p)
    c["decode_s"] = d["decode_s"]
    c["detail_s"] = d.get("detail_s", 0.0)
    c["diff_rms_rel"] = c["rms_rel"] if f is None else f["rms_rel"]
    return c


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--meshes", nargs="*", default=None,
                    help="OFF files (default: ../shared/meshes/*.off next to the repository)")
    ap.add_argument("--gab", default=os.path.join(ROOT, "build", "apps", "gab"))
    ap.add_argument("--target", default="1e-3", help="relative vertex RMS, or a comma list of them")
    ap.add_argument("--json", default=None, help="also write all numbers to this JSON file")
    ap.add_argument("--reorder", action="store_true",
                    help="gab's default files, in traversal order (else gab compress --keep-order)")
    args = ap.parse_args()

    missing = tools_missing(args.gab)
    if missing:
        print(missing)
        return 0
    meshes = args.meshes if args.meshes is not None else default_meshes()
    if not meshes:
        print("no meshes found: skipping")
        return 0

    targets = [float(x) for x in str(args.target).split(",")]
    by_target = {t: [] for t in targets}
    with tempfile.TemporaryDirectory(prefix="draco_compare.") as work:
        for mesh in meshes:
            name = os.path.splitext(os.path.basename(mesh))[0]
            text, pos, faces = read_off(mesh)
            obj = os.path.join(work, name + ".obj")
            write_obj(obj, text, faces)
            dm = DracoMesh(name, obj, pos, work)
            for t in targets:
                t0 = time.time()
                hi, lo, interp = draco_at(dm, t)
                g = gab_at(args.gab, mesh, t, work, args.reorder)
                by_target[t].append({"mesh": name, "n": dm.n, "diag": dm.diag, "draco_base_bytes": dm.base,
                                     "draco": hi, "draco_below": lo, "draco_bpv_interp": interp,
                                     "draco_all": [dm.cache[k] for k in sorted(dm.cache)], "gab": g})
                print(f"[{name} at {t:g}: {time.time() - t0:.1f} s]", file=sys.stderr, flush=True)

    sys.stderr.flush()
    for t in targets:
        report(by_target[t], t, args.reorder)
    if len(targets) > 1:
        print("\n### Whole files, gab / Draco, every target\n")
        print("| mesh | " + " | ".join(f"{t:g}" for t in targets) + " |")
        print("|---|" + "---:|" * len(targets))
        for i, r in enumerate(by_target[targets[0]]):
            cells = []
            for t in targets:
                q = by_target[t][i]
                whole = q["draco_base_bytes"] + q["draco_bpv_interp"] * q["n"] / 8.0
                cells.append(f"{q['gab']['bytes']} / {whole:.0f} = {q['gab']['bytes'] / whole:.3f}")
            print(f"| {r['mesh']} | " + " | ".join(cells) + " |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({f"{t:g}": by_target[t] for t in targets}, f, indent=1)
    return 0


def report(rows, t, reorder):
    """The tables of one target."""
    print(f"\n### Geometry bits/vertex at relative vertex RMS {t:g} (Draco -cl 10)\n")
    print("| mesh | n | draco qp | draco bits/v @qp | draco rms @qp | draco qp-1 bits/v (rms) "
          f"| draco bits/v @{t:g} (interp) | gab bits/v | gab rms_rel | gab anchors | gab q "
          "| gab/draco (interp) | gab/draco (@qp) | gab encode s | gab decode s | gab detail bytes | gab detail s |")
    print("|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        d, b, g = r["draco"], r["draco_below"], r["gab"]
        print(f"| {r['mesh']} | {r['n']} | {d['qp']} | {d['bpv']:.3f} | {d['rms_rel']:.3e} "
              f"| {b['bpv']:.3f} ({b['rms_rel']:.3e}) | {r['draco_bpv_interp']:.3f} "
              f"| {g['bpv_geometry']:.3f} | {g['rms_rel']:.3e} | {g['anchors']} | {g['bits']} "
              f"| {g['bpv_geometry'] / r['draco_bpv_interp']:.3f} | {g['bpv_geometry'] / d['bpv']:.3f} "
              f"| {g['encode_s']:.2f} | {g['decode_s']:.2f} | {g.get('detail_bytes', 0)} "
              f"| {g.get('detail_s', 0.0):.3f} |")

    print(f"\n### Whole files at relative vertex RMS {t:g}" + (" (gab --reorder)" if reorder else "") + "\n")
    print("| mesh | n | gab bytes | gab connectivity | gab order | gab geometry | draco bytes (interp) "
          "| draco bytes @qp | gab/draco |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    gab_sum = draco_sum = 0.0
    for r in rows:
        g, d = r["gab"], r["draco"]
        draco_whole = r["draco_base_bytes"] + r["draco_bpv_interp"] * r["n"] / 8.0
        order = g.get("order_bytes")
        gab_sum += g["bytes"]
        draco_sum += draco_whole
        print(f"| {r['mesh']} | {r['n']} | {g['bytes']} | {g['connectivity_bytes']} "
              f"| {'-' if order is None else order} | {g['geometry_bytes']} | {draco_whole:.0f} "
              f"| {d['bytes']} | {g['bytes'] / draco_whole:.3f} |")
    print(f"| sum | | {gab_sum:.0f} | | | | {draco_sum:.0f} | | {gab_sum / draco_sum:.3f} |")

    print("\n### Draco detail (every qp measured)\n")
    print("| mesh | qp | .drc bytes | geometry bytes | bits/v | rms_rel | linf_rel | rms_rel of own "
          "quantizer | decoded vertices | distinct decoded positions | off-centre matches |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        for m in r["draco_all"]:
            print(f"| {r['mesh']} | {m['qp']} | {m['bytes']} | {m['geometry_bytes']} | {m['bpv']:.3f} "
                  f"| {m['rms_rel']:.4e} | {m['linf_rel']:.3e} | {m['sim_rms_rel']:.4e} "
                  f"| {m['n_decoded']} | {m['decoded_distinct']} | {m['off_center']} |")
    print("\n-qp 1 file sizes (subtracted as header + connectivity): " +
          ", ".join(f"{r['mesh']} {r['draco_base_bytes']} B" for r in rows))

    bad = [r["mesh"] for r in rows if abs(r["gab"]["rms_rel"] - r["gab"]["diff_rms_rel"]) > 1e-9]
    print("gab rms_rel of the decoded file (gab diff) vs compress JSON: " +
          ("all agree to 1e-9" if not bad else "DIFFER for " + ", ".join(bad)) + " (max |delta| "
          f"{max(abs(r['gab']['rms_rel'] - r['gab']['diff_rms_rel']) for r in rows):.1e})")


if __name__ == "__main__":
    sys.exit(main())
