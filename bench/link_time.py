#!/usr/bin/env python3
"""Full mesh over a link, gab against Google Draco: bytes / link speed + decode time.

Run (from the repository root, after building build/apps/gab; Draco's tools
installed: apt-get install -y draco):

    python3 bench/link_time.py                       # every ../shared/meshes/*.off, 1e-3
    python3 bench/link_time.py --rounds 7 --threads 2 --meshes ../shared/meshes/igea.off

For every mesh, at one relative vertex RMS target (default 1e-3):

* Draco: `draco_encoder -cl 10 -qp Q` at the smallest Q whose decoded RMS
  meets the target (found as bench/draco_compare.py finds it); its real file.
* gab: `gab compress --error TARGET --reorder` (default options otherwise;
  --compress-args adds more, e.g. "--solver global" for the paper's operator).

Both files are then decoded ROUNDS times, interleaved (gab, Draco, gab, ...),
each `gab decompress --threads T` / `draco_decoder` writing binary PLY to a
fresh path; the median wall time of the process is the decode time. The
time to have the whole mesh is bytes * 8 / speed + decode, printed for 1 and
10 Mbit/s (and --speeds), with gab / Draco. Standard library only; prints a
markdown table. Exits 0 with a message when Draco or the gab binary is
missing.
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ left in bench/
import draco_compare  # noqa: E402  (its OFF reading and Draco quantization search)


def timed(cmd):
    """Wall seconds of one run of cmd (its output discarded)."""
    t0 = time.perf_counter()
    draco_compare.run(cmd)
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--meshes", nargs="*", default=None,
                    help="OFF files (default: ../shared/meshes/*.off next to the repository)")
    ap.add_argument("--gab", default=os.path.join(ROOT, "build", "apps", "gab"))
    ap.add_argument("--target", type=float, default=1e-3, help="relative vertex RMS")
    ap.add_argument("--rounds", type=int, default=5, help="decodes of each file (the median is kept)")
    ap.add_argument("--threads", type=int, default=1, help="gab decompress --threads (Draco has one)")
    ap.add_argument("--speeds", default="1,10", help="link speeds in Mbit/s, a comma list")
    ap.add_argument("--compress-args", default="", help="more gab compress options, one string (e.g. \"--solver global\")")
    args = ap.parse_args()

    missing = draco_compare.tools_missing(args.gab)
    if missing:
        print(missing)
        return 0
    meshes = args.meshes if args.meshes is not None else draco_compare.default_meshes()
    if not meshes:
        print("no meshes found: skipping")
        return 0
    speeds = [float(s) for s in args.speeds.split(",")]

    rows = []
    with tempfile.TemporaryDirectory(prefix="link_time.") as work:
        for mesh in meshes:
            name = os.path.splitext(os.path.basename(mesh))[0]
            text, pos, faces = draco_compare.read_off(mesh)
            obj = os.path.join(work, name + ".obj")
            draco_compare.write_obj(obj, text, faces)
            dm = draco_compare.DracoMesh(name, obj, pos, work)
            qp = draco_compare.draco_at(dm, args.target)[0]["qp"]
            drc = os.path.join(work, name + ".drc")
            draco_compare.run(["draco_encoder", "-i", obj, "-o", drc, "-cl", "10", "-qp", str(qp)])
            gab = os.path.join(work, name + ".gab")
            draco_compare.run([args.gab, "compress", "-i", mesh, "-o", gab, "--error", repr(args.target),
                               "--reorder"] + args.compress_args.split())
            out = os.path.join(work, "out.ply")
            gab_s, draco_s = [], []
            for _ in range(args.rounds):
                for cmd, times in (([args.gab, "decompress", "-i", gab, "-o", out, "--threads", str(args.threads)],
                                    gab_s),
                                   (["draco_decoder", "-i", drc, "-o", out], draco_s)):
                    if os.path.exists(out):
                        os.remove(out)
                    times.append(timed(cmd))
            rows.append({"mesh": name, "n": dm.n, "qp": qp,
                         "gab_bytes": os.path.getsize(gab), "draco_bytes": os.path.getsize(drc),
                         "gab_s": statistics.median(gab_s), "draco_s": statistics.median(draco_s)})
            print(f"[{name}: done]", file=sys.stderr, flush=True)

    options = " ".join(["--reorder"] + args.compress_args.split())
    print(f"\n### Full mesh over a link at relative RMS {args.target:g} (gab {options}, "
          f"{args.threads} thread(s); Draco -cl 10 at the qp meeting the target; median of {args.rounds})\n")
    head = "| mesh | n | gab bytes | Draco bytes (qp) | gab decode s | Draco decode s |"
    rule = "|---|---:|---:|---:|---:|---:|"
    for s in speeds:
        head += f" at {s:g} Mbit/s: gab / Draco s |"
        rule += "---|"
    print(head)
    print(rule)
    for r in rows:
        line = (f"| {r['mesh']} | {r['n']} | {r['gab_bytes']} | {r['draco_bytes']} ({r['qp']}) | "
                f"{r['gab_s']:.3f} | {r['draco_s']:.3f} |")
        for s in speeds:
            g = r["gab_bytes"] * 8 / (s * 1e6) + r["gab_s"]
            d = r["draco_bytes"] * 8 / (s * 1e6) + r["draco_s"]
            line += f" {g:.3f} / {d:.3f} = {g / d:.2f} |"
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
