#!/usr/bin/env python3
"""Rate-distortion of the spectral baseline (Karni & Gotsman 2000) beside gab and Draco (issue 36).

Run (from the repository root, after building build/apps/gab and, with
-DGAB_BUILD_BENCH=ON, bench/spectral_coder; Draco 1.5.5's tools on the PATH):

    python3 bench/spectral_compare.py --coder ../build-spec/bench/spectral_coder \\
        --cache ../spec-cache --svg-dir docs --markdown docs/spectral-baseline-data.md

For every mesh (default: camel-head, bunny-small, feline and horse of
../shared/meshes, camel and fandisk_large of data/meshes):

* spectral: `spectral_coder MESH --counts ... --bits 8,9,...,20` (every k up
  to K and every b; K = n up to 4,000 vertices, else 3000, 2000 above 30,000: the
  eigendecomposition's cost, see docs/spectral-baseline.md). Plotted: the
  Pareto front over (k, b) per metric, and the front at b = 14 alone (K&G's
  bits).
* gab: `gab compress -i MESH -o F --error E --keep-order --json` at each E
  of --errors (the input's numbering, which `gab diff` pairs vertex by
  vertex, as the figures were measured before the default renumbered),
  with the default options (detail layer when it pays) and with
  `--detail off` (anchors alone; the same file when the default keeps no
  detail layer, which is then not re-run) and with `--solver global` (the
  paper's global least squares, which Sorkine et al. set against spectral
  compression; NAME.gab-global.json in the cache), bits per vertex from
  `geometry_bytes`; `gab decompress` and `gab diff MESH DECODED --json` for
  vertex RMS, L-inf and Metro RMS. Each compress runs under /usr/bin/time
  (wall, CPU seconds, peak MB).
* Draco: `draco_encoder -cl 10 -qp Q` for Q in --qp, geometry = file at Q
  minus file at -qp 1 (bench/draco_compare.py's rule and its nearest-grid
  vertex matching for vertex RMS and L-inf), Metro RMS by `gab diff` on the
  decoded PLY.

With --cache DIR every part's measurements are kept there (NAME.jsonl for
spectral_coder's output, NAME.gab.json, NAME.gab-global.json,
NAME.draco.json) and reused when
present; --only gab,draco measures those parts alone (to run beside a long
eigendecomposition). All errors are relative to the original's bounding-box diagonal. Writes one
SVG per mesh (vertex RMS, L-inf and Metro RMS against bits per vertex of
geometry, log axes), a markdown file with the tables behind them, and
with --json every number. Standard library only; one process at a time.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import draco_compare as dc  # noqa: E402  (the same Draco measurement as the benchmarks page)

SHARED = os.path.join(ROOT, "..", "shared", "meshes")
DATA = os.path.join(ROOT, "data", "meshes")
DEFAULT_MESHES = [
    os.path.join(SHARED, "camel-head.off"), os.path.join(SHARED, "bunny-small.off"),
    os.path.join(SHARED, "feline.off"), os.path.join(SHARED, "horse.off"),
    os.path.join(DATA, "camel.off"), os.path.join(DATA, "fandisk_large.off"),
]
COUNTS = [50, 100, 200, 300, 500, 700, 1000, 1500, 2000, 3000]
BITS = list(range(8, 21))
ERRORS = [2e-2, 1e-2, 5e-3, 3e-3, 2e-3, 1.4e-3, 1e-3, 7e-4, 5e-4, 3e-4, 1.5e-4, 7e-5, 3e-5]
RATES = [0.5, 1, 2, 4, 8, 16]
METRICS = [("rms_rel", "vertex RMS"), ("linf_rel", "vertex L-inf"), ("metro_rms_rel", "Metro RMS")]


def mesh_name(path):
    return os.path.splitext(os.path.basename(path))[0]


def vertex_count(path):
    with open(path) as f:
        lines = [ln.strip() for ln in f if ln.strip() and not ln.startswith("#")][:2]
    head = lines[0][3:].split() or lines[1].split()
    return int(head[0])


def timed(cmd):
    """stdout, wall s, CPU s and peak MB of one run under /usr/bin/time."""
    r = subprocess.run(["/usr/bin/time", "-f", "TIME %e %U %S %M"] + cmd, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    last = [ln for ln in r.stderr.splitlines() if ln.startswith("TIME ")][-1].split()
    return r.stdout, float(last[1]), float(last[2]) + float(last[3]), int(last[4]) / 1024.0


# ---------------------------------------------------------------- spectral

def spectral_kmax(n):
    """The most eigenpairs asked for: the whole spectrum up to 4,000 vertices, else 3,000 (2,000 above 30,000)."""
    if n <= 4000:
        return n
    return 2000 if n > 30000 else 3000


def spectral(coder, path, cache, kmax=None):
    name = mesh_name(path)
    cached = os.path.join(cache, name + ".jsonl") if cache else None
    if cached and os.path.exists(cached):
        with open(cached) as f:
            text = f.read()
    else:
        kmax = kmax or spectral_kmax(vertex_count(path))
        counts = [c for c in COUNTS if c < kmax] + [kmax]
        text, _, _, _ = timed([coder, path, "--counts", ",".join(map(str, counts)),
                               "--bits", ",".join(map(str, BITS))])
        if cached:
            os.makedirs(cache, exist_ok=True)
            with open(cached, "w") as f:
                f.write(text)
    rows = [json.loads(ln) for ln in text.splitlines() if ln.strip()]
    eigen = [r for r in rows if r.get("eigen")][0]
    return eigen, [r for r in rows if not r.get("eigen")]


def cached(cache, filename, compute):
    """compute()'s value, kept as JSON in cache/filename and read back when there."""
    path = os.path.join(cache, filename) if cache else None
    if path and os.path.exists(path):
        with open(path) as f:
            return json.load(f)
    value = compute()
    if path:
        os.makedirs(cache, exist_ok=True)
        with open(path, "w") as f:
            json.dump(value, f, indent=1)
    return value


# ---------------------------------------------------------------- gab

def gab_points(gab, path, errors, work, modes=(("default", []), ("anchors", ["--detail", "off"]))):
    name = mesh_name(path)
    out = os.path.join(work, name + ".gab")
    dec = os.path.join(work, name + ".dec.off")
    points = {mode: [] for mode, _ in modes}
    for e in errors:
        for mode, extra in modes:
            if mode == "anchors" and not points["default"][-1]["detail"]:
                points["anchors"].append(dict(points["default"][-1], mode="anchors"))
                continue
            text, wall, cpu, mb = timed([gab, "compress", "-i", path, "-o", out, "--error", repr(e), "--keep-order",
                                         "--json"] + extra)
            c = json.loads(text)
            dc.run([gab, "decompress", "-i", out, "-o", dec, "--json"])
            d = json.loads(dc.run([gab, "diff", path, dec, "--json"]))
            points[mode].append({
                "mode": mode, "target": e, "bytes": c["geometry_bytes"], "bpv": 8.0 * c["geometry_bytes"] / c["n"],
                "rms_rel": d["rms_rel"], "linf_rel": d["linf_rel"], "metro_rms_rel": d["metro_rms_rel"],
                "detail": c["detail"], "anchors": c["anchors"], "q": c["bits"], "encode_s": c["encode_s"],
                "wall_s": wall, "cpu_s": cpu, "peak_mb": mb,
            })
            print(f"  gab {mode} {e:g}: {points[mode][-1]['bpv']:.3f} bpv rms {d['rms_rel']:.3e}", file=sys.stderr)
    for p in (out, dec):
        if os.path.exists(p):
            os.remove(p)
    return points


# ---------------------------------------------------------------- Draco

def draco_points(gab, path, qps, work):
    name = mesh_name(path)
    text, pos, faces = dc.read_off(path)
    obj = os.path.join(work, name + ".obj")
    dc.write_obj(obj, text, faces)
    dm = dc.DracoMesh(name, obj, pos, work)
    points = []
    for qp in qps:
        drc = os.path.join(work, f"{name}.q{qp}.drc")
        ply = os.path.join(work, f"{name}.q{qp}.ply")
        size = dm.size(qp)
        dc.run(["draco_decoder", "-i", drc, "-o", ply])
        decoded = dc.read_ply_vertices(ply)
        step = dm.extent / ((1 << qp) - 1)
        m = dc.match_rms(pos, decoded, dm.lo, step)
        d = json.loads(dc.run([gab, "diff", path, ply, "--json"]))
        geo = size - dm.base
        points.append({"qp": qp, "bytes": geo, "bpv": 8.0 * geo / dm.n,
                       "rms_rel": math.sqrt(m["sse"] / dm.n) / dm.diag, "linf_rel": m["linf"] / dm.diag,
                       "metro_rms_rel": d["metro_rms_rel"]})
        for f in (drc, ply):
            os.remove(f)
        print(f"  draco qp {qp}: {points[-1]['bpv']:.3f} bpv rms {points[-1]['rms_rel']:.3e}", file=sys.stderr)
    os.remove(obj)
    return points


# ---------------------------------------------------------------- curves

def front(points, key):
    """The points no other beats in both bits per vertex and `key`, by rate."""
    pts = sorted((p for p in points if p.get(key) is not None), key=lambda p: (p["bpv"], p[key]))
    out = []
    for p in pts:
        if not out or p[key] < out[-1][key]:
            out.append(p)
    return out


def rate_at(curve, key, target):
    """Bits per vertex where the front reaches `target` (log-linear between points), or None."""
    for a, b in zip(curve, curve[1:]):
        if a[key] >= target >= b[key]:
            la, lb, lt = math.log(a[key]), math.log(b[key]), math.log(target)
            t = (la - lt) / (la - lb) if la != lb else 0.0
            return a["bpv"] + t * (b["bpv"] - a["bpv"])
    if curve and curve[0][key] <= target:
        return curve[0]["bpv"]  # reached at the front's first point already (an upper bound)
    return None


def log_error_at(curve, key, bpv):
    for a, b in zip(curve, curve[1:]):
        if a["bpv"] <= bpv <= b["bpv"]:
            t = (bpv - a["bpv"]) / (b["bpv"] - a["bpv"]) if b["bpv"] > a["bpv"] else 0.0
            return math.log10(a[key]) + t * (math.log10(b[key]) - math.log10(a[key]))
    return None


def crossings(c1, c2, key):
    """Rates (bpv) where two fronts cross, over the rates both reach, and who is lower before each."""
    if len(c1) < 2 or len(c2) < 2:
        return []
    lo = max(c1[0]["bpv"], c2[0]["bpv"])
    hi = min(c1[-1]["bpv"], c2[-1]["bpv"])
    out, prev = [], None
    steps = 400
    first = None
    for i in range(steps + 1):
        x = lo + (hi - lo) * i / steps
        a, b = log_error_at(c1, key, x), log_error_at(c2, key, x)
        if a is None or b is None:
            continue
        sign = a < b
        if first is None:
            first = (x, sign)
        if prev is not None and sign != prev[1]:
            out.append((0.5 * (x + prev[0]), "first" if prev[1] else "second"))
        prev = (x, sign)
    if not out and first is not None:
        return [(lo, hi, "first" if first[1] else "second")]  # no crossing: who is lower over [lo, hi]
    return out


# ---------------------------------------------------------------- SVG

COLORS = {"spectral": "#1f77b4", "spectral14": "#7fb8e0", "gab": "#d62728", "gab_anchors": "#ff9f1c",
          "gab_global": "#9467bd",
          "draco": "#2ca02c"}
LABELS = {"spectral": "spectral (best k, b)", "spectral14": "spectral, 14 bits", "gab": "gab (default)",
          "gab_anchors": "gab, --detail off", "gab_global": "gab, --solver global", "draco": "Draco -cl 10"}
DASHED = {"spectral14", "gab_anchors", "gab_global"}


def svg_plot(name, n, series, path, xmin=1.0 / 16, xmax=32.0):
    pw, ph, ml, mt, mb = 360, 300, 62, 40, 46
    width, height = 3 * (pw + ml) + 30, ph + mt + mb + 40
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{width / 2}" y="18" text-anchor="middle" font-size="15">{name} ({n:,} vertices): '
           f'error over the bounding-box diagonal against bits per vertex of geometry (log scales)</text>']
    for panel, (key, label) in enumerate(METRICS):
        x0 = ml + panel * (pw + ml)
        curves = {s: front(pts, key) for s, pts in series.items()}
        vals = [p[key] for c in curves.values() for p in c if xmin <= p["bpv"] <= xmax and p[key] > 0]
        if not vals:
            continue
        ylo, yhi = math.floor(math.log10(min(vals))), math.ceil(math.log10(max(vals)))
        if yhi == ylo:
            yhi += 1

        def sx(v):  # log2 rate axis: the low rates, where spectral lives, get room
            return x0 + pw * math.log2(max(v, xmin / 2) / xmin) / math.log2(xmax / xmin)

        def sy(e):
            return mt + ph * (yhi - math.log10(e)) / (yhi - ylo)

        out.append(f'<rect x="{x0}" y="{mt}" width="{pw}" height="{ph}" fill="none" stroke="#444"/>')
        t = xmin
        while t <= xmax:
            tick = f"1/{round(1 / t)}" if t < 1 else f"{t:g}"
            out.append(f'<line x1="{sx(t):.1f}" y1="{mt}" x2="{sx(t):.1f}" y2="{mt + ph}" stroke="#eee"/>')
            out.append(f'<text x="{sx(t):.1f}" y="{mt + ph + 15}" text-anchor="middle">{tick}</text>')
            t *= 2
        for d in range(ylo, yhi + 1):
            y = mt + ph * (yhi - d) / (yhi - ylo)
            out.append(f'<line x1="{x0}" y1="{y:.1f}" x2="{x0 + pw}" y2="{y:.1f}" stroke="#ddd"/>')
            out.append(f'<text x="{x0 - 5}" y="{y + 4:.1f}" text-anchor="end">1e{d}</text>')
            for m in range(2, 10):
                ym = mt + ph * (yhi - d - math.log10(m)) / (yhi - ylo)
                if d < yhi and ym > mt:
                    out.append(f'<line x1="{x0}" y1="{ym:.1f}" x2="{x0 + 4}" y2="{ym:.1f}" stroke="#888"/>')
        out.append(f'<text x="{x0 + pw / 2}" y="{mt + ph + 32}" text-anchor="middle">bits per vertex</text>')
        out.append(f'<text x="{x0 + pw / 2}" y="{mt - 8}" text-anchor="middle" font-weight="bold">{label}</text>')
        out.append(f'<clipPath id="c{panel}"><rect x="{x0}" y="{mt}" width="{pw}" height="{ph}"/></clipPath>')
        for s, c in curves.items():
            c = [p for p in c if p[key] > 0]
            if not c:
                continue
            pts = " ".join(f"{sx(p['bpv']):.1f},{sy(p[key]):.1f}" for p in c)
            dash = ' stroke-dasharray="5,3"' if s in DASHED else ""
            out.append(f'<g clip-path="url(#c{panel})"><polyline points="{pts}" fill="none" '
                       f'stroke="{COLORS[s]}" stroke-width="1.8"{dash}/>')
            for p in c:
                out.append(f'<circle cx="{sx(p["bpv"]):.1f}" cy="{sy(p[key]):.1f}" r="2.5" fill="{COLORS[s]}"/>')
            out.append('</g>')
    ly = height - 14
    lx = ml
    for s in series:
        dash = ' stroke-dasharray="5,3"' if s in DASHED else ""
        out.append(f'<line x1="{lx}" y1="{ly - 4}" x2="{lx + 24}" y2="{ly - 4}" stroke="{COLORS[s]}" '
                   f'stroke-width="2"{dash}/>')
        out.append(f'<text x="{lx + 30}" y="{ly}">{LABELS[s]}</text>')
        lx += 40 + 7 * len(LABELS[s])
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


# ---------------------------------------------------------------- report

def fmt(v, spec=".2f"):
    return "-" if v is None else format(v, spec)


def series_of(result):
    sp = result["spectral"]
    return {
        "spectral": sp, "spectral14": [p for p in sp if p["bits"] == 14],
        "gab": result["gab"]["default"], "gab_anchors": result["gab"]["anchors"],
        "gab_global": result["gab"]["global"], "draco": result["draco"],
    }


def summary(result, target):
    s = series_of(result)
    row = {}
    for key, _ in METRICS:
        row[key] = {name: rate_at(front(pts, key), key, target) for name, pts in s.items()}
    return row


def markdown(results, command, target):
    lines = ["# Spectral baseline: the data behind the plots", "",
             "Generated by `" + command + "` (see [spectral-baseline.md](spectral-baseline.md) for the method "
             "and the verdict). Errors are relative to the bounding-box diagonal; rates are bits per vertex "
             "of geometry (connectivity not counted).", ""]
    for r in results:
        name, n, e = r["name"], r["n"], r["eigen"]
        lines += [f"## {name} ({n:,} vertices)", "", f"![{name}](spectral-{name}.svg)", ""]
        lines += [f"Eigendecomposition: {e['count']:,} pairs in {e['seconds']:.1f} s "
                  f"({e.get('cpu_s', 0):.1f} CPU s), peak {e['peak_rss_mb']:.0f} MB, worst relative residual "
                  f"{e['max_residual']:.1e}.", ""]
        sm = summary(r, target)
        lines += [f"Bits per vertex at {target:g} (log-linear between the front's points; - : not reached):", "",
                  "| metric | spectral | spectral 14 bits | gab | gab --detail off | gab --solver global | Draco |",
                  "|---|---:|---:|---:|---:|---:|---:|"]
        for key, label in METRICS:
            v = sm[key]
            lines.append(f"| {label} | {fmt(v['spectral'])} | {fmt(v['spectral14'])} | {fmt(v['gab'])} | "
                         f"{fmt(v['gab_anchors'])} | {fmt(v['gab_global'])} | {fmt(v['draco'])} |")
        lines.append("")
        s = series_of(r)
        lines += ["Error at a rate (on each front, log-linear between its points; - : outside the rates it "
                  "reaches), spectral / gab / Draco:", "",
                  "| metric | " + " | ".join(f"{x:g} bpv" for x in RATES) + " |",
                  "|---|" + "---:|" * len(RATES)]
        for key, label in METRICS:
            cells = []
            for x in RATES:
                vals = [log_error_at(front(s[m], key), key, x) for m in ("spectral", "gab", "draco")]
                cells.append(" / ".join("-" if v is None else f"{10 ** v:.2e}" for v in vals))
            lines.append(f"| {label} | " + " | ".join(cells) + " |")
        lines.append("")
        for (series, who_gab), (key, label) in [(g, m) for g in (("gab", "gab"), ("gab_global", "gab --solver global"))
                                                for m in METRICS]:
            cr = crossings(front(s[series], key), front(s["spectral"], key), key)
            if cr and len(cr[0]) == 3:
                lo, hi, who = cr[0]
                txt = f"none; {'gab' if who == 'first' else 'spectral'} lower over {lo:.2f}-{hi:.2f} bpv"
            elif cr:
                txt = "; ".join(f"{x:.2f} bpv ({'gab' if who == 'first' else 'spectral'} lower below it)"
                                for x, who in cr)
            else:
                txt = "none over the rates both reach"
            lines.append(f"- {who_gab} and spectral cross in {label}: {txt}")
        lines += ["", "Spectral, the front in vertex RMS or L-inf (Metro RMS measured on these):", "",
                  "| k | bits | bytes | bpv | vertex RMS | L-inf | Metro RMS |", "|---:|---:|---:|---:|---:|---:|---:|"]
        for p in sorted(r["spectral"], key=lambda p: p["bpv"]):
            if "metro_rms_rel" in p:
                lines.append(f"| {p['k']} | {p['bits']} | {p['bytes']:,} | {p['bpv']:.3f} | {p['rms_rel']:.3e} | "
                             f"{p['linf_rel']:.3e} | {p['metro_rms_rel']:.3e} |")
        lines += ["", "gab (default; `--detail off` where it differs; `--solver global`):", "",
                  "| --error | mode | anchors | q | detail | geometry bytes | bpv | vertex RMS | L-inf | Metro RMS "
                  "| encode wall s | CPU s | peak MB |", "|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for mode in ("default", "anchors", "global"):
            for p in r["gab"][mode]:
                if mode == "anchors" and not any(q["target"] == p["target"] and q["detail"]
                                                 for q in r["gab"]["default"]):
                    continue
                lines.append(f"| {p['target']:g} | {mode} | {p['anchors']:,} | {p['q']} | "
                             f"{'yes' if p['detail'] else 'no'} | {p['bytes']:,} | {p['bpv']:.3f} | "
                             f"{p['rms_rel']:.3e} | {p['linf_rel']:.3e} | {p['metro_rms_rel']:.3e} | "
                             f"{p['wall_s']:.2f} | {p['cpu_s']:.2f} | {p['peak_mb']:.0f} |")
        lines += ["", "Draco (geometry = file at -qp Q minus file at -qp 1):", "",
                  "| qp | geometry bytes | bpv | vertex RMS | L-inf | Metro RMS |", "|---:|---:|---:|---:|---:|---:|"]
        for p in r["draco"]:
            lines.append(f"| {p['qp']} | {p['bytes']:,} | {p['bpv']:.3f} | {p['rms_rel']:.3e} | "
                         f"{p['linf_rel']:.3e} | {p['metro_rms_rel']:.3e} |")
        lines.append("")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--meshes", nargs="*", default=DEFAULT_MESHES)
    ap.add_argument("--gab", default=os.path.join(ROOT, "build", "apps", "gab"))
    ap.add_argument("--coder", default=os.path.join(ROOT, "build-bench", "bench", "spectral_coder"))
    ap.add_argument("--cache", default=None, help="folder for spectral_coder's output (NAME.jsonl), reused")
    ap.add_argument("--errors", default=",".join(repr(e) for e in ERRORS), help="gab --error targets")
    ap.add_argument("--qp", default="5-16", help="Draco quantization bits, A-B")
    ap.add_argument("--target", type=float, default=1e-3, help="the error of the summary table")
    ap.add_argument("--svg-dir", default=None, help="write spectral-NAME.svg here")
    ap.add_argument("--markdown", default=None, help="write the tables here")
    ap.add_argument("--json", default=None, help="write every number here")
    ap.add_argument("--kmax", default="", help="NAME=K,...: the most eigenpairs for these meshes")
    ap.add_argument("--only", default="spectral,gab,draco",
                    help="measure these parts only (into --cache; the report needs all three)")
    args = ap.parse_args()

    missing = dc.tools_missing(args.gab)
    if missing:
        print(missing)
        return 0
    errors = [float(e) for e in args.errors.split(",")]
    parts = args.only.split(",")
    kmax = {k: int(v) for k, v in (item.split("=") for item in args.kmax.split(",") if item)}
    qa, qb = (int(x) for x in args.qp.split("-"))
    results = []
    with tempfile.TemporaryDirectory() as work:
        for path in args.meshes:
            name = mesh_name(path)
            if "gab" in parts:
                print(f"{name}: gab", file=sys.stderr)
                g = cached(args.cache, f"{name}.gab.json", lambda: gab_points(args.gab, path, errors, work))
                g.update(cached(args.cache, f"{name}.gab-global.json", lambda: gab_points(
                    args.gab, path, errors, work, modes=(("global", ["--solver", "global"]),))))
            if "draco" in parts:
                print(f"{name}: Draco", file=sys.stderr)
                d = cached(args.cache, f"{name}.draco.json",
                           lambda: draco_points(args.gab, path, range(qa, qb + 1), work))
            if "spectral" not in parts:
                continue
            print(f"{name}: spectral", file=sys.stderr)
            eigen, sp = spectral(args.coder, path, args.cache, kmax.get(name))
            if "gab" not in parts or "draco" not in parts:
                continue
            r = {"name": name, "path": path, "n": eigen["n"], "eigen": eigen, "spectral": sp, "gab": g, "draco": d}
            results.append(r)
            if args.svg_dir:
                svg_plot(name, r["n"], series_of(r), os.path.join(args.svg_dir, f"spectral-{name}.svg"))
    if set(parts) != {"spectral", "gab", "draco"}:
        return 0
    command = "python3 bench/spectral_compare.py " + " ".join(sys.argv[1:])
    text = markdown(results, command, args.target)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text + "\n")
    else:
        print(text)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
