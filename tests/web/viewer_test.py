#!/usr/bin/env python3
"""The progressive viewer end to end: build it (scripts/build-web.sh), serve
it on 127.0.0.1 and load it in headless Chromium (software WebGL).

Checks, each by the title the page sets (web/viewer.js) and its level list:
  * a real mesh's file ends at "gab: done n=<n> anchors=<anchors>", the
    numbers of `gab compress --json`; a screenshot stays in WORK/viewer.png;
  * served one frame at a time (a throttled stream), the first level is
    shown before the whole file has arrived, and later levels refine it;
  * the levels were decoded in the Web Worker (the body's data-decoder);
    with ?worker=0 the page decodes them itself, with the same result;
  * ?level=0 stops at the coarsest level;
  * the first view looks along the decoded surface's axis of least spread
    (the viewer's principal axes against the test's own), +Y up; ?up=z
    turns +Z up;
  * a file with a corrupted chunk, one with a corrupted header and a
    missing file end at "gab: error: ..." with the decoder's (or HTTP's) message;
  * a larger mesh (bunny00 subdivided once: 150,818 vertices, --reorder;
    or --large-mesh) on the throttled stream: the page's thread keeps
    answering while its levels decode (a timer callback at most
    MAX_GAP_MS late, in the best of GAP_LOADS loads, from the file's
    request to the final title; decoding on the page's thread misses that
    by the decode's whole length), and the panel said "decoding level L… T s"
    meanwhile. The log gives the first shape's delay after the first
    chunk's arrival and the whole mesh's decode against the native one.

Exit 0 on success, 1 on a failure, 77 (ctest: skipped) when emscripten or
Chromium is missing, unless GAB_WEB_TEST_REQUIRED=1 (CI): then 1.

  viewer_test.py --gab build/apps/gab --source . --work build/web-test [--mesh MESH] [--large-mesh MESH]
"""

import argparse
import base64
import fcntl
import functools
import http.server
import json
import os
import re
import select
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time

SKIP = 77
FRAME_DELAY_S = 0.15  # the throttled stream's pause between frames
MAX_GAP_MS = 100      # the longest the page's thread may go unanswered while a file decodes
GAP_LOADS = 3         # loads of the larger file; the best one counts (the machine may be busy)

# Injected before the page's own scripts: when the page's thread ran a timer
# callback (a gap is a stretch without one; the timer asks every 5 ms) and
# what the progress line said, until the title is final.
WATCH = """(() => {
  const watch = window.gabWatch = { gaps: [], progress: [] };
  let last = performance.now();
  function tick() {
    const now = performance.now();
    if (now - last > 16) watch.gaps.push([last, now]);
    last = now;
    const line = document.getElementById('progress');
    const text = line ? line.textContent : '';
    if (text && watch.progress[watch.progress.length - 1] !== text) watch.progress.push(text);
    if (!/^gab: (done|error)/.test(document.title)) setTimeout(tick, 5);
  }
  setTimeout(tick, 5);
})();"""

# The longest gap after the page asked for the file (Resource Timing's
# startTime: what came before, such as WebGL's start, is not the decoder's),
# and the progress lines seen.
WATCHED = """(() => {
  const file = performance.getEntriesByType('resource').find((e) => e.name.endsWith(%s));
  const from = file ? file.startTime : 0;
  const gaps = window.gabWatch.gaps.filter(([a, b]) => b > from).map(([a, b]) => b - Math.max(a, from));
  return JSON.stringify({ maxGap: Math.max(0, ...gaps), progress: window.gabWatch.progress,
                          decoder: document.body.dataset.decoder || '' });
})()"""


def log(message):
    print(message, flush=True)


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def header_bytes(data):
    """The header's size (docs/format.md 2.1): 14 fixed bytes, the varints n
    and faces, 40 bytes of f64, the varints anchors, chunks and sections,
    and the CRC-32."""
    at = 14
    for count in range(5):
        while data[at] & 0x80:
            at += 1
        at += 1
        if count == 1:
            at += 40
    return at + 4


def frame_ends(data):
    """Byte offsets after the header and after each frame (u32 length, u32
    CRC-32, payload); the file must not be geometry-only (no unframed hash)."""
    ends = [header_bytes(data)]
    at = ends[0]
    while at + 8 <= len(data):
        (length,) = struct.unpack_from("<I", data, at)
        at += 8 + length
        ends.append(min(at, len(data)))
    return ends


class Handler(http.server.SimpleHTTPRequestHandler):
    """Serves the site; /slow/NAME sends NAME one frame at a time; /blank is
    an empty page."""

    def log_message(self, fmt, *args):  # keep ctest's output to the checks
        pass

    def do_GET(self):
        if self.path == "/blank":
            body = b"<!DOCTYPE html><title>blank</title>"
            self.send_response(200)
            self.send_header("Content-Type", "text/html")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)
            return None
        if not self.path.startswith("/slow/"):
            return super().do_GET()
        name = os.path.basename(self.path.split("?")[0])
        path = os.path.join(self.directory, name)
        if not os.path.isfile(path):
            return self.send_error(404)
        with open(path, "rb") as f:
            data = f.read()
        self.send_response(200)
        self.send_header("Content-Type", "application/octet-stream")
        self.send_header("Content-Length", str(len(data)))
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        start = 0
        try:
            for end in frame_ends(data):
                self.wfile.write(data[start:end])
                self.wfile.flush()
                start = end
                time.sleep(FRAME_DELAY_S)
            self.wfile.write(data[start:])
        except (BrokenPipeError, ConnectionResetError):
            pass


class Server:
    """http.server on 127.0.0.1, a free port, in a thread of this process
    (so it cannot outlive the test)."""

    def __init__(self, directory):
        handler = functools.partial(Handler, directory=directory)
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.httpd.daemon_threads = True
        self.port = self.httpd.server_address[1]
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.httpd.shutdown()
        self.httpd.server_close()


class Browser:
    """Headless Chromium driven through the DevTools protocol over a pipe
    (--remote-debugging-pipe: JSON messages ending in NUL on fds 3 and 4),
    so the page runs on the real clock: a virtual-time budget would stop
    the page's clock while it decodes, and move on without waiting for a
    slow stream."""

    def __init__(self, chromium, work):
        self.profile = tempfile.mkdtemp(prefix="gab-chromium-", dir=work)
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()

        def child_fds():  # the protocol's fds 3 (commands) and 4 (answers)
            a = fcntl.fcntl(to_chrome_r, fcntl.F_DUPFD, 10)
            b = fcntl.fcntl(from_chrome_w, fcntl.F_DUPFD, 10)
            os.dup2(a, 3)
            os.dup2(b, 4)

        args = [chromium, "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--disable-extensions", "--disable-dev-shm-usage", "--hide-scrollbars",
                "--user-data-dir=" + self.profile, "--window-size=960,720",
                "--remote-debugging-pipe", "about:blank"]
        self.log = open(os.path.join(work, "chromium.log"), "wb")
        self.process = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=self.log, stderr=self.log,
                                        preexec_fn=child_fds, pass_fds=(3, 4))
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        self.session = None
        targets = self.call("Target.getTargets", timeout_s=60)["targetInfos"]
        page = next(t for t in targets if t["type"] == "page")
        self.session = self.call("Target.attachToTarget", {"targetId": page["targetId"], "flatten": True},
                                 browser=True)["sessionId"]
        self.call("Page.enable")

    def close(self):
        try:
            self.call("Browser.close", browser=True, timeout_s=10)
        except (AssertionError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        for fd in (self.to_chrome, self.from_chrome):
            try:
                os.close(fd)
            except OSError:
                pass
        self.log.close()
        shutil.rmtree(self.profile, ignore_errors=True)

    def call(self, method, params=None, browser=False, timeout_s=30):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if self.session and not browser:
            message["sessionId"] = self.session
        os.write(self.to_chrome, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout_s
        while True:
            while b"\0" not in self.buffer:
                left = deadline - time.monotonic()
                ready = select.select([self.from_chrome], [], [], max(0.0, left))[0] if left > 0 else []
                if not ready:
                    raise AssertionError("chromium did not answer %s within %d s" % (method, timeout_s))
                data = os.read(self.from_chrome, 1 << 20)
                if not data:
                    raise AssertionError("chromium closed its pipe (see chromium.log)")
                self.buffer += data
            raw, self.buffer = self.buffer.split(b"\0", 1)
            answer = json.loads(raw)
            if answer.get("id") != self.next_id:
                continue  # an event, or an earlier command's late answer
            if "error" in answer:
                raise AssertionError("%s: %s" % (method, answer["error"]))
            return answer.get("result", {})

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True})
        return result.get("result", {}).get("value")

    def load(self, url, timeout_s=120):
        """Opens url and waits for the page's final title; returns it and the
        levels shown (the data- attributes of the level list's items)."""
        self.call("Page.navigate", {"url": url})
        deadline = time.monotonic() + timeout_s
        title = ""
        while time.monotonic() < deadline:
            try:
                title = self.evaluate("location.href === %s ? document.title : ''" % json.dumps(url)) or ""
            except AssertionError:  # the old document went away under the call
                title = ""
            if title.startswith("gab: done") or title.startswith("gab: error"):
                break
            time.sleep(0.05)
        else:
            raise AssertionError("%s: no final title within %d s (last: %r)" % (url, timeout_s, title))
        levels = self.evaluate("JSON.stringify([...document.querySelectorAll('li.level')]"
                               ".map((li) => Object.assign({}, li.dataset)))")
        return title, json.loads(levels or "[]")

    def blank(self, url):
        """Leaves the page for url (the server's /blank: the same site, so
        the same renderer process and its compiled WebAssembly) and waits
        there, so that the next page does not share its thread with this
        one's teardown (dropping a WebGL context waits for the GPU process:
        0.4 s at times)."""
        self.call("Page.navigate", {"url": url})
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            try:
                if self.evaluate("location.href") == url:
                    break
            except AssertionError:  # the old document went away under the call
                pass
            time.sleep(0.05)
        time.sleep(0.2)
        self.evaluate("0")  # answered once the thread is free

    def watch(self):
        """Runs WATCH in every page loaded from now on; returns the handle for unwatch."""
        return self.call("Page.addScriptToEvaluateOnNewDocument", {"source": WATCH})["identifier"]

    def unwatch(self, handle):
        self.call("Page.removeScriptToEvaluateOnNewDocument", {"identifier": handle})

    def watched(self, file_name):
        """What WATCH saw of the page just loaded, which fetched file_name."""
        return json.loads(self.evaluate(WATCHED % json.dumps(file_name)))

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", {"format": "png"})["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))


def read_off(path):
    """Vertices and triangles of an OFF file as gab writes it."""
    with open(path) as f:
        words = f.read().split()
    at = 1 if words[0] == "OFF" else 0
    n, t = int(words[at]), int(words[at + 1])
    at += 3
    vertices = [tuple(float(w) for w in words[at + 3 * i:at + 3 * i + 3]) for i in range(n)]
    at += 3 * n
    triangles = []
    for _ in range(t):
        count = int(words[at])
        triangles.append(tuple(int(w) for w in words[at + 1:at + 1 + count][:3]))
        at += 1 + count
    return vertices, triangles


def thinnest_axis(vertices, triangles):
    """The unit eigenvector of the smallest eigenvalue of the surface's
    covariance (each triangle by its area at its centroid: an oracle
    independent of the viewer's exact second moments and Jacobi rotations),
    by power iteration on trace(C) I - C."""
    area, mean, cov = 0.0, [0.0] * 3, [[0.0] * 3 for _ in range(3)]
    cents = []
    for a, b, c in triangles:
        p, q, r = vertices[a], vertices[b], vertices[c]
        u = [q[k] - p[k] for k in range(3)]
        v = [r[k] - p[k] for k in range(3)]
        w = 0.5 * sum(x * x for x in (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                       u[0] * v[1] - u[1] * v[0])) ** 0.5
        g = [(p[k] + q[k] + r[k]) / 3 for k in range(3)]
        cents.append((w, g))
        area += w
        for k in range(3):
            mean[k] += w * g[k]
    mean = [m / area for m in mean]
    for w, g in cents:
        d = [g[k] - mean[k] for k in range(3)]
        for i in range(3):
            for j in range(3):
                cov[i][j] += w * d[i] * d[j] / area
    trace = cov[0][0] + cov[1][1] + cov[2][2]
    x = [0.3, 0.5, 0.8]
    for _ in range(500):
        y = [trace * x[i] - sum(cov[i][j] * x[j] for j in range(3)) for i in range(3)]
        norm = sum(v * v for v in y) ** 0.5
        x = [v / norm for v in y]
    return x


def corrupt_copy(data, offset):
    out = bytearray(data)
    out[offset] ^= 0x5A
    return bytes(out)


def check_responsive(browser, base, blank, large, native, check):
    """The larger file on the throttled stream, GAP_LOADS times in the Web
    Worker and once on the page's thread (for the log): the page's thread
    answers throughout, and the panel shows the decode's progress."""
    expected = "gab: done n=%d anchors=%d" % (large["n"], large["anchors"])
    handle = browser.watch()
    try:
        runs = []
        for _ in range(GAP_LOADS):
            browser.blank(blank)
            title, levels = browser.load(base + "slow/large.gab")
            runs.append((title, levels, browser.watched("slow/large.gab")))
        browser.blank(blank)
        title, levels = browser.load(base + "slow/large.gab&worker=0")
        page = browser.watched("slow/large.gab")
    finally:
        browser.unwatch(handle)
    check("larger file, throttled: " + ", ".join(sorted(set(run[0] for run in runs))),
          all(run[0] == expected and run[2]["decoder"] == "worker" for run in runs),
          "expected %r from the worker each time" % expected)
    gaps = [run[2]["maxGap"] for run in runs]
    check("larger file: the page's thread answers while it decodes (longest gap %s ms; at most %d in the best load)" %
          (", ".join("%.0f" % gap for gap in gaps), MAX_GAP_MS), min(gaps) <= MAX_GAP_MS,
          "every load left the page's thread unanswered longer")
    progress = [line for run in runs for line in run[2]["progress"]]
    shown = [line for line in progress if re.match(r"^decoding level \d+… \d+\.\d s$", line)]
    check("larger file: the panel showed the decode's progress (%s)" % (shown[-1] if shown else "nothing"),
          len(shown) > 0, "no 'decoding level L… T s' line among %r" % progress[:10])
    log("larger file decoded on the page's thread (worker=0): longest gap %.0f ms, %s" %
        (page["maxGap"], title))
    for title, levels, _ in runs:
        if title != expected or not levels:
            continue
        first, last = levels[0], levels[-1]
        log("larger file: first shape (level %s) %d ms after its chunk arrived (decode %s ms); "
            "whole mesh decoded in %s ms, %.1fx native's %.0f ms, shown %d ms after its last byte" %
            (first["level"], int(first["shownMs"]) - int(first["arrivedMs"]), first["decodeMs"],
             last["decodeMs"], float(last["decodeMs"]) / (1e3 * native["decode_s"]), 1e3 * native["decode_s"],
             int(last["shownMs"]) - int(last["arrivedMs"])))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gab", required=True, help="the gab binary")
    parser.add_argument("--source", required=True, help="the repository's root")
    parser.add_argument("--work", required=True, help="a folder for the site, files and screenshot")
    parser.add_argument("--mesh", help="the mesh to compress (default: data/meshes/camel.off)")
    parser.add_argument("--large-mesh", help="the larger mesh for the responsiveness check "
                        "(default: data/meshes/bunny00.off subdivided once)")
    args = parser.parse_args()

    chromium = find_chromium()
    missing = [tool for tool, path in (("emcc", shutil.which("emcc")), ("chromium", chromium)) if not path]
    required = os.environ.get("GAB_WEB_TEST_REQUIRED") == "1"
    if missing:
        log("%s: %s not installed (apt-get install emscripten chromium)" %
            ("FAIL" if required else "SKIPPED", " and ".join(missing)))
        return 1 if required else SKIP
    mesh = args.mesh or os.path.join(args.source, "data", "meshes", "camel.off")
    if not os.path.isfile(mesh):
        log("%s: no mesh at %s (scripts/setup-and-run.sh unpacks it)" % ("FAIL" if required else "SKIPPED", mesh))
        return 1 if required else SKIP

    work = os.path.abspath(args.work)
    site = os.path.join(work, "site")
    os.makedirs(site, exist_ok=True)

    t = time.monotonic()
    subprocess.run(["bash", os.path.join(args.source, "scripts", "build-web.sh"), site], check=True)
    log("build-web: %.1f s" % (time.monotonic() - t))

    gab_file = os.path.join(site, "mesh.gab")
    out = subprocess.run([args.gab, "compress", "-i", mesh, "-o", gab_file, "--json"],
                         stdout=subprocess.PIPE, check=True).stdout
    stats = json.loads(out)
    n, anchors = stats["n"], stats["anchors"]
    decode = json.loads(subprocess.run([args.gab, "decompress", "-i", gab_file, "-o",
                                        os.path.join(work, "decoded.off"), "--json", "--threads", "1"],
                                       stdout=subprocess.PIPE, check=True).stdout)
    with open(gab_file, "rb") as f:
        data = f.read()
    ends = frame_ends(data)
    log("%s: n=%d anchors=%d, %d bytes, %d frames after the header; native decode %.1f ms" %
        (os.path.basename(mesh), n, anchors, len(data), len(ends) - 1, 1e3 * decode["decode_s"]))
    # The last chunk's payload ends the file: flip its last byte. The header's
    # byte 20 is inside its weight (covered by its CRC).
    with open(os.path.join(site, "bad-chunk.gab"), "wb") as f:
        f.write(corrupt_copy(data, len(data) - 1))
    with open(os.path.join(site, "bad-header.gab"), "wb") as f:
        f.write(corrupt_copy(data, 20))

    large_mesh = args.large_mesh
    if not large_mesh:
        large_mesh = os.path.join(work, "bunny00-x4.off")
        subprocess.run([args.gab, "subdivide", os.path.join(args.source, "data", "meshes", "bunny00.off"),
                        "-o", large_mesh, "--levels", "1"], stdout=subprocess.DEVNULL, check=True)
    large_file = os.path.join(site, "large.gab")
    large = json.loads(subprocess.run([args.gab, "compress", "-i", large_mesh, "-o", large_file, "--reorder",
                                       "--json"], stdout=subprocess.PIPE, check=True).stdout)
    large_decode = json.loads(subprocess.run([args.gab, "decompress", "-i", large_file, "-o",
                                              os.path.join(work, "large-decoded.off"), "--json", "--threads", "1"],
                                             stdout=subprocess.PIPE, check=True).stdout)
    log("%s (the larger mesh): n=%d anchors=%d, %d bytes, %d chunks; native decode %.1f ms" %
        (os.path.basename(large_mesh), large["n"], large["anchors"], large["bytes"], large["chunks"],
         1e3 * large_decode["decode_s"]))

    failures = []

    def check(what, condition, detail):
        log(("ok   " if condition else "FAIL ") + what + ("" if condition else ": " + detail))
        if not condition:
            failures.append(what)

    browser = Browser(chromium, work)
    try:
        with Server(site) as server:
            base = "http://127.0.0.1:%d/index.html?file=" % server.port
            expected = "gab: done n=%d anchors=%d" % (n, anchors)

            t = time.monotonic()
            title, levels = browser.load(base + "mesh.gab")
            log("whole file: shown in %.2f s" % (time.monotonic() - t))
            check("whole file: " + title, title == expected, "expected %r" % expected)
            if levels:
                log("browser decode of the whole file: %s ms (native, one thread: %.1f ms)" %
                    (levels[-1]["decodeMs"], 1e3 * decode["decode_s"]))
            decoder = browser.evaluate("document.body.dataset.decoder || ''")
            check("whole file: decoded in the Web Worker (data-decoder=%s)" % decoder, decoder == "worker",
                  "expected data-decoder=worker")
            view = json.loads(browser.evaluate("document.getElementById('view').dataset.view || '{}'") or "{}")
            axis = thinnest_axis(*read_off(os.path.join(work, "decoded.off")))
            to_camera = view.get("toCamera", [0, 0, 0])
            along = abs(sum(a * b for a, b in zip(axis, to_camera)))
            check("first view: along the axis of least spread, +Y up (%s; the oracle's axis %s)" %
                  (view, [round(a, 3) for a in axis]), along > 0.98 and view.get("up") == "y",
                  "|cos| = %.3f between the view and the axis" % along)
            shot = os.path.join(work, "viewer.png")
            browser.screenshot(shot)
            log("screenshot: %s (%d bytes)" % (shot, os.path.getsize(shot)))

            title, levels = browser.load(base + "slow/mesh.gab")
            check("throttled stream: " + title, title == expected, "expected %r" % expected)
            first_bytes = int(levels[0]["bytes"]) if levels else len(data)
            check("throttled stream: the first level before the whole file",
                  len(levels) >= 2 and first_bytes < len(data),
                  "%d levels shown, the first at %d of %d bytes" % (len(levels), first_bytes, len(data)))
            log("throttled stream: %d levels shown, at %s of %d bytes, decoded in %s ms" %
                (len(levels), ", ".join(level["bytes"] for level in levels), len(data),
                 ", ".join(level["decodeMs"] for level in levels)))

            title, _ = browser.load(base + "mesh.gab&up=z")
            view = json.loads(browser.evaluate("document.getElementById('view').dataset.view || '{}'") or "{}")
            to_camera = view.get("toCamera", [0, 0, 1])
            check("up=z: +Z up, the view across it (%s)" % view,
                  view.get("up") == "z" and abs(to_camera[2]) < 0.5, "expected up z and a view across Z")
            shot_up = os.path.join(work, "viewer-up-z.png")
            browser.screenshot(shot_up)

            title, levels = browser.load(base + "mesh.gab&worker=0")
            decoder = browser.evaluate("document.body.dataset.decoder || ''")
            check("worker=0: %s, decoded by the page (data-decoder=%s)" % (title, decoder),
                  title == expected and decoder == "page", "expected %r and data-decoder=page" % expected)

            title, levels = browser.load(base + "mesh.gab&level=0")
            level0 = levels[-1]["anchors"] if levels else "?"
            check("level=0: " + title,
                  title == "gab: done n=%d anchors=%s" % (n, level0) and int(level0) < anchors and len(levels) == 1,
                  "%d levels shown, expected 1 of fewer than %d anchors" % (len(levels), anchors))

            for name, pattern in (("bad-chunk.gab", r"^gab: error: chunk \d+ is corrupt \(checksum mismatch\)$"),
                                  ("bad-header.gab", r"^gab: error: bad \.gab header: checksum mismatch"),
                                  ("missing.gab", r"^gab: error: HTTP 404")):
                title, _ = browser.load(base + name)
                check(name + ": " + title, re.search(pattern, title) is not None, "expected /%s/" % pattern)

            check_responsive(browser, base, "http://127.0.0.1:%d/blank" % server.port, large, large_decode, check)
    finally:
        browser.close()

    if failures:
        log("%d check(s) failed" % len(failures))
        return 1
    log("all checks passed")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (AssertionError, subprocess.CalledProcessError) as e:
        log("FAIL " + str(e))
        sys.exit(1)
