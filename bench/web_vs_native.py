#!/usr/bin/env python3
"""The viewer's WebAssembly decoder against the native one on the same file
(issue 20: "within 3x the native decoder's time on the same machine"; issue
33: the first shape 0.5 s after the first chunk, the page answering input).

    python3 bench/web_vs_native.py --gab build/apps/gab --mesh ../shared/meshes/igea.off [--reorder] [--runs 5]

Builds the page (scripts/build-web.sh) into build/web-bench/site, compresses
the mesh (default options, or --reorder), then `runs` times, alternating:
  * decodes the file natively with one thread (`gab decompress --threads 1`,
    decode_s) and in headless Chromium, in the page's Web Worker (the page's
    own timing of its last level, data-decode-ms; and from the last byte's
    arrival to the whole mesh drawn, data-shown-ms - data-arrived-ms);
  * serves it one frame at a time (viewer_test.py's throttled stream) and
    takes the first level's delay from its chunk's arrival to its shape
    drawn, with the native decode of that level (`--anchors K`);
  * the longest the page's thread went without a timer callback on the
    throttled stream, decoding in the worker and on the page (&worker=0).
Prints the medians (and every run), and the first load's figures (the
module compiled afresh, as on a first visit; it warms the caches). Needs
emscripten and chromium (apt-get install emscripten chromium)."""
import argparse
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(HERE, "..", "tests", "web"))
import viewer_test  # noqa: E402  (the test's server and Chromium driver)


def native_decode_s(gab, path, work, anchors=None):
    command = [gab, "decompress", "-i", path, "-o", os.path.join(work, "decoded.off"), "--threads", "1", "--json"]
    if anchors is not None:
        command += ["--anchors", str(anchors)]
    return json.loads(subprocess.run(command, stdout=subprocess.PIPE, check=True).stdout)["decode_s"]


def summary(values, unit="%.3f"):
    return (unit + " (" + ", ".join(unit for _ in values) + ")") % ((statistics.median(values),) + tuple(values))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gab", required=True)
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--reorder", action="store_true", help="compress with --reorder")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--work", default=os.path.join(HERE, "..", "build", "web-bench"))
    args = parser.parse_args()
    work = os.path.abspath(args.work)
    site = os.path.join(work, "site")
    os.makedirs(site, exist_ok=True)
    subprocess.run(["bash", os.path.join(HERE, "..", "scripts", "build-web.sh"), site], check=True)
    name = "bench.gab"
    path = os.path.join(site, name)
    stats = json.loads(subprocess.run([args.gab, "compress", "-i", args.mesh, "-o", path, "--json"] +
                                      (["--reorder"] if args.reorder else []),
                                      stdout=subprocess.PIPE, check=True).stdout)
    native, web, web_shown = [], [], []
    first_native, first_shown, first_decode = [], [], []
    gap_worker, gap_page = [], []
    first_anchors = None
    browser = viewer_test.Browser(viewer_test.find_chromium(), work)
    try:
        with viewer_test.Server(site) as server:
            url = "http://127.0.0.1:%d/index.html?file=" % server.port
            blank = "http://127.0.0.1:%d/blank" % server.port
            # A first load, throttled, in a fresh browser: the module compiled
            # afresh (a first visit); it warms the JIT and the caches.
            title, levels = browser.load(url + "slow/" + name)
            cold = [(int(level["shownMs"]) - int(level["arrivedMs"])) / 1e3 for level in levels]
            cold_decode = [float(level["decodeMs"]) / 1e3 for level in levels]
            handle = browser.watch()
            for _ in range(args.runs):
                native.append(native_decode_s(args.gab, path, work))
                browser.blank(blank)  # each load starts clear of the last one's teardown
                title, levels = browser.load(url + name)
                if not title.startswith("gab: done"):
                    sys.exit("web_vs_native: the page says %r" % title)
                web.append(float(levels[-1]["decodeMs"]) / 1e3)
                web_shown.append((int(levels[-1]["shownMs"]) - int(levels[-1]["arrivedMs"])) / 1e3)

                browser.blank(blank)
                title, levels = browser.load(url + "slow/" + name)
                gap_worker.append(browser.watched("slow/" + name)["maxGap"])
                first_anchors = int(levels[0]["anchors"])
                first_shown.append((int(levels[0]["shownMs"]) - int(levels[0]["arrivedMs"])) / 1e3)
                first_decode.append(float(levels[0]["decodeMs"]) / 1e3)
                first_native.append(native_decode_s(args.gab, path, work, first_anchors))

                browser.blank(blank)
                browser.load(url + "slow/" + name + "&worker=0")
                gap_page.append(browser.watched("slow/" + name)["maxGap"])
            browser.unwatch(handle)
    finally:
        browser.close()
    n, w = statistics.median(native), statistics.median(web)
    print("%s: n=%d, %d bytes, %d chunks; native %s, wasm in the worker %s; wasm / native %.2fx; "
          "whole mesh drawn %s s after its last byte" %
          (os.path.basename(args.mesh), stats["n"], stats["bytes"], stats["chunks"], summary(native), summary(web),
           w / n, summary(web_shown)))
    print("throttled stream: the first level (%d anchors) drawn %s s after its chunk arrived; "
          "its decode %s s in the worker, %s s natively" %
          (first_anchors, summary(first_shown), summary(first_decode), summary(first_native)))
    print("first load (the module compiled afresh), throttled: levels drawn %s s after their chunks arrived, "
          "decoded in %s s" % (", ".join("%.3f" % x for x in cold), ", ".join("%.3f" % x for x in cold_decode)))
    print("throttled stream: the page's thread unanswered at most %s ms decoding in the worker, "
          "%s ms on the page (worker=0)" % (summary(gap_worker, "%.0f"), summary(gap_page, "%.0f")))


if __name__ == "__main__":
    main()
