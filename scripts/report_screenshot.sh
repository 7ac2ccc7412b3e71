#!/bin/sh
# the README's picture of `mcrash report`: the top of the restraint concept's page that
# `make demo` writes (out/report/iso413_concept.html), 1280 x 1250 px, in headless Chromium,
# into docs/img/report.png. Usage: scripts/report_screenshot.sh [PAGE.html [OUT.png]]
set -eu
HTML=${1:-out/report/iso413_concept.html}
PNG=${2:-docs/img/report.png}
[ -f "$HTML" ] || { echo "$HTML: no such page (run make demo first)" >&2; exit 2; }
CH=$(command -v chromium || command -v chromium-browser || true)
[ -n "$CH" ] || { echo "chromium not found (apt-get install chromium)" >&2; exit 2; }
abs="$(cd "$(dirname "$HTML")" && pwd)/$(basename "$HTML")"
out="$(cd "$(dirname "$PNG")" && pwd)/$(basename "$PNG")"
prof=$(mktemp -d)
"$CH" --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run \
    --user-data-dir="$prof" --window-size=1280,1250 --virtual-time-budget=5000 \
    --screenshot="$out" "file://$abs" >/dev/null 2>&1
rm -rf "$prof"
echo "$PNG: $(wc -c <"$PNG") bytes"
