#!/usr/bin/env python3
"""Pictures of the viewer for the docs: one .gab file shown at several levels
side by side (docs/viewer.md: the paper's Figure 6, live), each panel the
page itself with ?file=NAME&level=L&compact=1, or panels of the page's own
parameters (docs/tuning-codec.md: decoded shapes close up, flat shaded),
screenshotted by headless Chromium.

  make_figure.py SITE NAME.gab LEVEL... -o docs/viewer-levels.png
  make_figure.py SITE --panel 'file=A.gab&flat=1&zoom=0.5' --panel ... -o OUT.png

SITE is a folder made by scripts/build-web.sh that holds the files.
"""

import argparse
import json
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viewer_test  # noqa: E402  (Browser, Server, find_chromium)

PANEL = 420

FIGURE = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>gab: loading</title>
<style>body { margin: 0; display: flex; background: #f4f4f2; }
iframe { width: %dpx; height: %dpx; border: 0; }</style></head>
<body>%s
<script>
// Done when every panel is (their titles say so).
const timer = setInterval(() => {
  const titles = [...document.querySelectorAll('iframe')].map((f) => f.contentDocument ? f.contentDocument.title : '');
  const error = titles.find((t) => t.startsWith('gab: error'));
  if (error) document.title = error;
  else if (titles.every((t) => t.startsWith('gab: done'))) document.title = 'gab: done ' + titles.length;
  if (document.title !== 'gab: loading') clearInterval(timer);
}, 50);
</script></body></html>
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("site")
    parser.add_argument("file", nargs="?")
    parser.add_argument("levels", nargs="*", type=int)
    parser.add_argument("--panel", action="append", default=[], help="a panel's query string (compact=1 added)")
    parser.add_argument("--size", type=int, default=PANEL, help="a panel's width and height in pixels")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    queries = args.panel + ["file=%s&level=%d" % (args.file, level) for level in args.levels]
    if not queries or (args.levels and not args.file):
        parser.error("give NAME.gab and levels, or --panel queries")
    frames = "".join('<iframe src="index.html?%s&compact=1"></iframe>' % query for query in queries)
    with open(os.path.join(args.site, "figure.html"), "w") as f:
        f.write(FIGURE % (args.size, args.size, frames))
    work = os.path.dirname(os.path.abspath(args.site))
    browser = viewer_test.Browser(viewer_test.find_chromium(), work)
    try:
        browser.call("Emulation.setDeviceMetricsOverride",
                     {"width": args.size * len(queries), "height": args.size, "deviceScaleFactor": 1, "mobile": False})
        with viewer_test.Server(args.site) as server:
            title, _ = browser.load("http://127.0.0.1:%d/figure.html" % server.port)
            print(title)
            if not title.startswith("gab: done"):
                return 1
            browser.screenshot(args.output)
    finally:
        browser.close()
    print("%s: %d bytes" % (args.output, os.path.getsize(args.output)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
