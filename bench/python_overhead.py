#!/usr/bin/env python3
"""The Python module's overhead over the library (issue 20: at most 5% over
the CLI's library time).

    GAB_LIBRARY=build/capi/libgab.so PYTHONPATH=python /usr/bin/python3 bench/python_overhead.py \
        --gab build/apps/gab --mesh ../shared/meshes/igea.off [--runs 5]

Per run, alternating: `gab compress --threads 1 --json` and `gab decompress
--threads 1 --json` (encode_s / decode_s: the library's own time, file I/O
excluded), then gab.compress(V, F, threads=1) and gab.decompress(data) on
the same mesh, timed around the call (numpy in, numpy or bytes out).
Prints the medians and the ratios."""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

import gab


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gab", required=True)
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    V, F = gab.read_mesh(args.mesh)
    tmp = tempfile.mkdtemp(prefix="gab-python-overhead-")
    path, out = os.path.join(tmp, "m.gab"), os.path.join(tmp, "m.off")
    cli_enc, cli_dec, py_enc, py_dec = [], [], [], []
    for _ in range(args.runs):
        r = json.loads(subprocess.run([args.gab, "compress", "-i", args.mesh, "-o", path, "--threads", "1", "--json"],
                                      stdout=subprocess.PIPE, check=True).stdout)
        cli_enc.append(r["encode_s"])
        r = json.loads(subprocess.run([args.gab, "decompress", "-i", path, "-o", out, "--threads", "1", "--json"],
                                      stdout=subprocess.PIPE, check=True).stdout)
        cli_dec.append(r["decode_s"])
        t = time.perf_counter()
        data = gab.compress(V, F, threads=1)
        py_enc.append(time.perf_counter() - t)
        t = time.perf_counter()
        gab.decompress(data)
        py_dec.append(time.perf_counter() - t)
    ce, cd = statistics.median(cli_enc), statistics.median(cli_dec)
    pe, pd = statistics.median(py_enc), statistics.median(py_dec)
    print("%s: compress: library %.3f s, Python %.3f s (%.3fx); decompress: library %.3f s, Python %.3f s (%.3fx)"
          % (os.path.basename(args.mesh), ce, pe, pe / ce, cd, pd, pd / cd))


if __name__ == "__main__":
    main()
