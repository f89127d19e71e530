#!/usr/bin/env python3
"""Checks an HTML report in a real headless browser (Debian's chromium).

    python3 scripts/check_html_report.py REPORT.html [--min-figures N] [--min-tables N]
                                         [--window-size W,H] [--full-width F]

The report is copied alone into a temporary directory (so anything it does not carry inline fails
to load: the report must be self-contained) with a small checking script put first in its <head>.
Chromium loads it with no network, and the script records, after the load event:
  * every JavaScript error and console.error/console.warn call (the reports have no scripts, so
    any is a fault), and every resource that failed to load (img, link, script, ...);
  * every <img>: loaded with a non-zero natural size; every inline <svg> and <table>: laid out with
    a non-zero size; the page has an <h1> and is taller than zero;
  * the page is no wider than the window (a wide table scrolls in its own box, the page does not
    scroll sideways), and with --full-width F the widest table spans at least F of the window's
    width (a report uses the screen, not a narrow column). --window-size sets the window
    (default 1400,1800).
Chromium's own log is also searched for CONSOLE messages. Exit 0 when all hold, 1 with the list of
failures, 77 (ctest's "skipped") when chromium is not installed.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

CHECKER = r"""<script>
(function () {
  var problems = [];
  window.addEventListener('error', function (e) {
    var t = e.target;
    if (t && t !== window && (t.src || t.href)) problems.push('resource failed: ' + (t.src || t.href));
    else problems.push('script error: ' + e.message);
  }, true);
  var wrap = function (kind) {
    var orig = console[kind];
    console[kind] = function () {
      problems.push('console.' + kind + ': ' + Array.prototype.join.call(arguments, ' '));
      orig.apply(console, arguments);
    };
  };
  wrap('error'); wrap('warn');
  window.addEventListener('load', function () {
    var imgs = document.images, svgs = document.querySelectorAll('svg'),
        tables = document.querySelectorAll('table');
    for (var i = 0; i < imgs.length; ++i)
      if (!imgs[i].complete || imgs[i].naturalWidth === 0) problems.push('image not loaded: ' + imgs[i].src);
    var size = function (el) { var r = el.getBoundingClientRect(); return r.width > 0 && r.height > 0; };
    for (var j = 0; j < svgs.length; ++j)
      if (!size(svgs[j])) problems.push('svg ' + (j + 1) + ' has no size');
    for (var k = 0; k < tables.length; ++k)
      if (!size(tables[k])) problems.push('table ' + (k + 1) + ' has no size');
    if (!document.querySelector('h1')) problems.push('no <h1>');
    if (document.body.scrollHeight <= 0) problems.push('page has no height');
    var viewport = document.documentElement.clientWidth,
        page = document.documentElement.scrollWidth, widest = 0;
    if (page > viewport + 1)
      problems.push('page is ' + page + ' px wide in a ' + viewport + ' px window (scrolls sideways)');
    for (var t = 0; t < tables.length; ++t)
      widest = Math.max(widest, tables[t].getBoundingClientRect().width);
    var result = {problems: problems, images: imgs.length, svgs: svgs.length, tables: tables.length,
                  figures: document.querySelectorAll('figure').length,
                  height_px: document.body.scrollHeight, viewport_px: viewport,
                  widest_table_px: Math.round(widest)};
    document.documentElement.setAttribute('data-demcal-check', JSON.stringify(result));
  });
})();
</script>"""


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("report")
    parser.add_argument("--min-figures", type=int, default=0)
    parser.add_argument("--min-tables", type=int, default=0)
    parser.add_argument("--window-size", default="1400,1800")
    parser.add_argument("--full-width", type=float, default=0)
    args = parser.parse_args()
    chromium = find_chromium()
    if chromium is None:
        print("SKIP: chromium not installed (scripts/install_deps.sh installs it)", file=sys.stderr)
        return 77
    with open(args.report, encoding="utf-8") as f:
        html = f.read()
    head = re.search(r"<head[^>]*>", html)
    if head is None:
        print(f"FAIL: {args.report}: no <head>", file=sys.stderr)
        return 1
    html = html[: head.end()] + CHECKER + html[head.end():]
    with tempfile.TemporaryDirectory() as tmp:
        page = os.path.join(tmp, "report.html")
        with open(page, "w", encoding="utf-8") as f:
            f.write(html)
        cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
               "--window-size=" + args.window_size,
               "--user-data-dir=" + os.path.join(tmp, "profile"), "--enable-logging=stderr",
               "--v=0", "--virtual-time-budget=3000", "--dump-dom", "file://" + page]
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    failures = []
    if run.returncode != 0:
        failures.append(f"chromium exited with {run.returncode}")
    match = re.search(r"data-demcal-check=\"([^\"]*)\"", run.stdout)
    if match is None:
        failures.append("the checking script did not run (page not loaded?)")
        result = {}
    else:
        text = match.group(1).replace("&quot;", '"').replace("&amp;", "&")
        text = text.replace("&lt;", "<").replace("&gt;", ">")
        result = json.loads(text)
        failures += result["problems"]
    failures += [line for line in run.stderr.splitlines() if ":CONSOLE" in line]
    if result and result["figures"] < args.min_figures:
        failures.append(f"{result['figures']} figures, expected at least {args.min_figures}")
    if result and result["tables"] < args.min_tables:
        failures.append(f"{result['tables']} tables, expected at least {args.min_tables}")
    if result and result["widest_table_px"] < args.full_width * result["viewport_px"]:
        failures.append(f"widest table {result['widest_table_px']} px in a "
                        f"{result['viewport_px']} px window: less than {args.full_width:g} of it")
    if failures:
        print(f"FAIL: {args.report}:", file=sys.stderr)
        for f in failures:
            print("  " + f, file=sys.stderr)
        return 1
    print(f"OK: {args.report}: {result['figures']} figures, {result['svgs']} svg, "
          f"{result['tables']} tables, {result['images']} images, "
          f"{result['height_px']} px tall in a {result['viewport_px']} px window, "
          f"widest table {result['widest_table_px']} px, no console errors")
    return 0


if __name__ == "__main__":
    sys.exit(main())
