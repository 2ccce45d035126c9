#!/usr/bin/env python3
"""The viewer's WebAssembly decoder against the native one on the same file
(issue 20: "within 3x the native decoder's time on the same machine").

    python3 bench/web_vs_native.py --gab build/apps/gab --mesh ../shared/meshes/igea.off [--runs 5]

Builds the page (scripts/build-web.sh) into build/web-bench/site, compresses
the mesh (default options), then decodes the file natively with one thread
(`gab decompress --threads 1`, decode_s) and in headless Chromium (the page's
own timing of its last level, data-decode-ms), `runs` times each,
alternating, and prints the medians and their ratio. Needs emscripten and
chromium (apt-get install emscripten chromium)."""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "web"))
import viewer_test  # noqa: E402  (the test's server and Chromium driver)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gab", required=True)
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--work", default=os.path.join(HERE, "..", "build", "web-bench"))
    args = parser.parse_args()
    work = os.path.abspath(args.work)
    site = os.path.join(work, "site")
    os.makedirs(site, exist_ok=True)
    subprocess.run(["bash", os.path.join(HERE, "..", "scripts", "build-web.sh"), site], check=True)
    name = "bench.gab"
    path = os.path.join(site, name)
    stats = json.loads(subprocess.run([args.gab, "compress", "-i", args.mesh, "-o", path, "--json"],
                                      stdout=subprocess.PIPE, check=True).stdout)
    native, web = [], []
    browser = viewer_test.Browser(viewer_test.find_chromium(), work)
    try:
        with viewer_test.Server(site) as server:
            url = "http://127.0.0.1:%d/index.html?file=%s" % (server.port, name)
            browser.load(url)  # a first load warms the JIT and the caches
            for _ in range(args.runs):
                out = subprocess.run([args.gab, "decompress", "-i", path, "-o", os.path.join(work, "decoded.off"),
                                      "--threads", "1", "--json"], stdout=subprocess.PIPE, check=True).stdout
                native.append(json.loads(out)["decode_s"])
                title, levels = browser.load(url)
                if not title.startswith("gab: done"):
                    sys.exit("web_vs_native: the page says %r" % title)
                web.append(float(levels[-1]["decodeMs"]) / 1e3)
    finally:
        browser.close()
    n, w = statistics.median(native), statistics.median(web)
    print("%s: n=%d, %d bytes, %d chunks; native %.3f s (%s), wasm %.3f s (%s); wasm / native %.2fx" %
          (os.path.basename(args.mesh), stats["n"], stats["bytes"], stats["chunks"], n,
           ", ".join("%.3f" % x for x in native), w, ", ".join("%.3f" % x for x in web), w / n))


if __name__ == "__main__":
    main()
