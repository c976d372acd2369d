#!/usr/bin/env bash
# Loads a regression report.html in headless Chromium (Debian's `chromium`) and checks that it
# logs no console message or script error and that every image decoded. The report comes from
# a run of walk.json against a copy of its goldens with one golden swapped, so it holds a
# failure with golden, new, difference and FLIP images. Exit 77 (CTest: skipped) without chromium.
# Usage: browser_check.sh PROXYGI SOURCE_DIR WORK_DIR
set -uo pipefail
proxygi=$1 source=$2 work=$3
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium not installed: skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
cp -r "$source/tests/regress/goldens" "$work/goldens"
g="$work/goldens/walk/llvmpipe/ground"
[ -d "$g" ] && cp "$g/frame_00060.png" "$g/frame_00030.png"
"$proxygi" regress "$source/tests/regress/walk.json" --goldens "$work/goldens" --filter 'walk/ground' --filter 'walk/frame' \
  --filter 'walk/tracks' --report "$work/report" > "$work/regress.out" 2>&1
code=$?
[ -f "$work/report/report.html" ] || { echo "no report.html (regress exit $code)"; cat "$work/regress.out"; exit 1; }
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0 --virtual-time-budget=5000 \
  --dump-dom "file://$work/report/report.html" > "$work/dom.html" 2> "$work/chromium.err"
rc=$?
if [ $rc -ne 0 ]; then
  if grep -qiE "Missing X server|cannot open display|sandbox" "$work/chromium.err"; then echo "chromium cannot run here: skipped"; exit 77; fi
  echo "chromium exit $rc"; tail -20 "$work/chromium.err"; exit 1
fi
body=$(grep -o '<body[^>]*>' "$work/dom.html" | head -1)
echo "body: $body"
fail=0
grep -q 'data-images-ok="true"' <<< "$body" || { echo "FAIL: images did not all render"; fail=1; }
grep -q 'data-errors=' <<< "$body" && { echo "FAIL: script errors: $body"; fail=1; }
if grep -E ':CONSOLE\(|Uncaught' "$work/chromium.err"; then echo "FAIL: console messages"; fail=1; fi
images=$(sed -n 's/.*data-images="\([0-9]*\)".*/\1/p' <<< "$body")
[ "${images:-0}" -ge 4 ] || { echo "FAIL: expected at least 4 images, got ${images:-0}"; fail=1; }
grep -q 'class="check fail failure"' "$work/dom.html" || { echo "FAIL: the swapped golden did not fail"; fail=1; }
grep -q -- '--bless walk/ground' "$work/dom.html" || { echo "FAIL: no bless command in the report"; fail=1; }
exit $fail
