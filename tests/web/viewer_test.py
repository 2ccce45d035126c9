#!/usr/bin/env python3
"""The progressive viewer end to end: build it (scripts/build-web.sh), serve
it on 127.0.0.1 and load it in headless Chromium (software WebGL).

Checks, each by the title the page sets (web/viewer.js) and its level list:
  * a real mesh's file ends at "gab: done n=<n> anchors=<anchors>", the
    numbers of `gab compress --json`; a screenshot stays in WORK/viewer.png;
  * served one frame at a time (a throttled stream), the first level is
    shown before the whole file has arrived, and later levels refine it;
  * ?level=0 stops at the coarsest level;
  * a file with a corrupted chunk, one with a corrupted header and a
    missing file end at "gab: error: ..." with the decoder's (or HTTP's) message.

Exit 0 on success, 1 on a failure, 77 (ctest: skipped) when emscripten or
Chromium is missing.

  viewer_test.py --gab build/apps/gab --source . --work build/web-test [--mesh MESH]
"""

import argparse
import functools
import html
import http.server
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time

SKIP = 77
HEADER_BYTES = 72  # codec/include/gab/codec/gab_format.h
FRAME_DELAY_S = 0.15  # the throttled stream's pause between frames


def log(message):
    print(message, flush=True)


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def frame_ends(data):
    """Byte offsets after the header and after each frame (u32 length, u32
    CRC-32, payload); the file must not be geometry-only (no unframed hash)."""
    ends = [HEADER_BYTES]
    at = HEADER_BYTES
    while at + 8 <= len(data):
        (length,) = struct.unpack_from("<I", data, at)
        at += 8 + length
        ends.append(min(at, len(data)))
    return ends


class Handler(http.server.SimpleHTTPRequestHandler):
    """Serves the site; /slow/NAME sends NAME one frame at a time."""

    def log_message(self, fmt, *args):  # keep ctest's output to the checks
        pass

    def do_GET(self):
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
    def __init__(self, chromium, work):
        self.chromium = chromium
        self.work = work

    def run(self, url, extra, timeout_s=120):
        profile = tempfile.mkdtemp(prefix="gab-chromium-", dir=self.work)
        args = [self.chromium, "--headless=new", "--no-sandbox", "--disable-gpu-sandbox",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
                "--disable-quic", "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--disable-extensions",
                "--disable-dev-shm-usage", "--user-data-dir=" + profile,
                "--virtual-time-budget=60000", "--window-size=960,720"] + extra + [url]
        try:
            done = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  timeout=timeout_s, check=False)
        except subprocess.TimeoutExpired:
            raise AssertionError("chromium took more than %d s on %s" % (timeout_s, url))
        finally:
            shutil.rmtree(profile, ignore_errors=True)
        if done.returncode != 0:
            raise AssertionError("chromium failed (%d) on %s:\n%s" %
                                 (done.returncode, url, done.stderr.decode(errors="replace")[-2000:]))
        return done.stdout.decode(errors="replace")

    def dom(self, url):
        return self.run(url, ["--dump-dom"])

    def screenshot(self, url, path):
        self.run(url, ["--screenshot=" + path, "--hide-scrollbars"])
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            raise AssertionError("no screenshot written to " + path)


def title_of(dom):
    m = re.search(r"<title>(.*?)</title>", dom, re.S)
    return html.unescape(m.group(1)).strip() if m else ""


def levels_of(dom):
    """The level list's items: dicts of their data- attributes."""
    items = []
    for m in re.finditer(r'<li class="level"([^>]*)>', dom):
        items.append({k: html.unescape(v) for k, v in re.findall(r'data-([a-z-]+)="([^"]*)"', m.group(1))})
    return items


def corrupt_copy(data, offset):
    out = bytearray(data)
    out[offset] ^= 0x5A
    return bytes(out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gab", required=True, help="the gab binary")
    parser.add_argument("--source", required=True, help="the repository's root")
    parser.add_argument("--work", required=True, help="a folder for the site, files and screenshot")
    parser.add_argument("--mesh", help="the mesh to compress (default: data/meshes/camel.off)")
    args = parser.parse_args()

    chromium = find_chromium()
    missing = [tool for tool, path in (("emcc", shutil.which("emcc")), ("chromium", chromium)) if not path]
    if missing:
        log("SKIPPED: %s not installed (apt-get install emscripten chromium)" % " and ".join(missing))
        return SKIP
    mesh = args.mesh or os.path.join(args.source, "data", "meshes", "camel.off")
    if not os.path.isfile(mesh):
        log("SKIPPED: no mesh at %s (scripts/setup-and-run.sh unpacks it)" % mesh)
        return SKIP

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

    browser = Browser(chromium, work)
    failures = []

    def check(what, condition, detail):
        log(("ok   " if condition else "FAIL ") + what + ("" if condition else ": " + detail))
        if not condition:
            failures.append(what)

    with Server(site) as server:
        base = "http://127.0.0.1:%d/index.html?file=" % server.port

        t = time.monotonic()
        dom = browser.dom(base + "mesh.gab")
        title = title_of(dom)
        levels = levels_of(dom)
        log("whole file: %.1f s in chromium" % (time.monotonic() - t))
        expected = "gab: done n=%d anchors=%d" % (n, anchors)
        check("title after the whole file", title == expected, "%r, expected %r" % (title, expected))
        if levels:
            log("browser decode of the whole file: %s ms (native: %.1f ms)" %
                (levels[-1].get("decode-ms"), 1e3 * decode["decode_s"]))

        dom = browser.dom(base + "slow/mesh.gab")
        title = title_of(dom)
        levels = levels_of(dom)
        check("throttled stream: title", title == expected, "%r" % title)
        first_bytes = int(levels[0]["bytes"]) if levels else len(data)
        check("throttled stream: the first level before the whole file",
              len(levels) >= 2 and first_bytes < len(data),
              "%d levels shown, the first at %d of %d bytes" % (len(levels), first_bytes, len(data)))
        log("throttled stream: %d levels shown at %s bytes of %d" %
            (len(levels), ", ".join(level["bytes"] for level in levels), len(data)))

        dom = browser.dom(base + "mesh.gab&level=0")
        title = title_of(dom)
        levels = levels_of(dom)
        level0 = levels[-1]["anchors"] if levels else "?"
        check("level=0 stops at the coarsest level",
              title == "gab: done n=%d anchors=%s" % (n, level0) and int(level0) < anchors and len(levels) == 1,
              "%r, %d levels" % (title, len(levels)))

        for name, pattern in (("bad-chunk.gab", r"^gab: error: chunk \d+ is corrupt \(checksum mismatch\)$"),
                              ("bad-header.gab", r"^gab: error: bad \.gab header: checksum mismatch"),
                              ("missing.gab", r"^gab: error: HTTP 404")):
            title = title_of(browser.dom(base + name))
            check(name + ": " + title, re.search(pattern, title) is not None, "expected /%s/" % pattern)

        shot = os.path.join(work, "viewer.png")
        browser.screenshot(base + "mesh.gab", shot)
        log("screenshot: %s (%d bytes)" % (shot, os.path.getsize(shot)))

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
