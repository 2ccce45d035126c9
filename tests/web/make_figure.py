#!/usr/bin/env python3
"""The picture of the viewer in docs/viewer.md: one .gab file shown at several levels
side by side (the paper's Figure 6, live), each panel the page itself with
?file=NAME&level=L&compact=1, screenshotted by headless Chromium.

  make_figure.py SITE NAME.gab LEVEL... -o docs/viewer-levels.png

SITE is a folder made by scripts/build-web.sh that holds NAME.gab.
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
    parser.add_argument("file")
    parser.add_argument("levels", nargs="+", type=int)
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    frames = "".join('<iframe src="index.html?file=%s&level=%d&compact=1"></iframe>' % (args.file, level)
                     for level in args.levels)
    with open(os.path.join(args.site, "figure.html"), "w") as f:
        f.write(FIGURE % (PANEL, PANEL, frames))
    work = os.path.dirname(os.path.abspath(args.site))
    browser = viewer_test.Browser(viewer_test.find_chromium(), work)
    try:
        browser.call("Emulation.setDeviceMetricsOverride",
                     {"width": PANEL * len(args.levels), "height": PANEL, "deviceScaleFactor": 1, "mobile": False})
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
