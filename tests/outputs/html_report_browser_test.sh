#!/usr/bin/env bash
# The browser test of outputs/html_report.h: a sample report (html_report_sample) opened
# in headless chromium renders, every figure and table has a size, no image fails, no console
# errors (scripts/check_html_report.py). Exit 77 (skipped) when chromium is not installed.
# Usage: html_report_browser_test.sh PATH/TO/html_report_sample REPO_ROOT
set -euo pipefail
sample="$1"; root="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$sample" "$tmp/report.html"
python3 "$root/scripts/check_html_report.py" "$tmp/report.html" --min-figures 2 --min-tables 1
# The checker must see a fault: the same report with an image that cannot load is refused.
sed 's|<h1>|<img src="missing.png" alt="x"><h1>|' "$tmp/report.html" > "$tmp/broken.html"
if python3 "$root/scripts/check_html_report.py" "$tmp/broken.html" 2>/dev/null; then
  echo "FAIL: the checker passed a report with a missing image" >&2
  exit 1
fi
echo "OK: a report with a missing image is refused"
