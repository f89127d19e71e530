#!/usr/bin/env bash
# The browser test of outputs/html_report.h: a sample report (html_report_sample) opened
# in headless chromium renders, every figure and table has a size, no image fails, no console
# errors (scripts/check_html_report.py); in a wide window its table spans the window, in a
# narrow one the page does not scroll sideways. Exit 77 (skipped) when chromium is not installed.
# Usage: html_report_browser_test.sh PATH/TO/html_report_sample REPO_ROOT
set -euo pipefail
sample="$1"; root="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$sample" "$tmp/report.html"
python3 "$root/scripts/check_html_report.py" "$tmp/report.html" --min-figures 4 --min-tables 1 \
  --window-size 1400,1800 --full-width 0.9
python3 "$root/scripts/check_html_report.py" "$tmp/report.html" --window-size 700,1200
# The checker must see a fault: the same report with an image that cannot load is refused.
sed 's|<h1>|<img src="missing.png" alt="x"><h1>|' "$tmp/report.html" > "$tmp/broken.html"
if python3 "$root/scripts/check_html_report.py" "$tmp/broken.html" 2>/dev/null; then
  echo "FAIL: the checker passed a report with a missing image" >&2
  exit 1
fi
echo "OK: a report with a missing image is refused"
# ... and a report squeezed into a narrow fixed column is refused by --full-width.
sed 's|</style>|body{max-width:600px}</style>|' "$tmp/report.html" > "$tmp/narrow.html"
if python3 "$root/scripts/check_html_report.py" "$tmp/narrow.html" --full-width 0.9 2>/dev/null; then
  echo "FAIL: the checker passed a report in a 600 px column" >&2
  exit 1
fi
echo "OK: a report in a 600 px column is refused"
