#!/usr/bin/env bash
# The viewer's figures of README "Viewer" (issue 13): the UI + present cost against the offscreen
# viewer and `bench frame` at 512², three interleaved repetitions so each ratio comes from runs
# seconds apart; fps at 1280×720 with and without the adaptive resolution; time from
# `proxygi view MODEL.glb` to the first frame, and to proxies when the rig is fitted, for the
# shared characters (copied to OUT_DIR/models first: the viewer caches rigs next to a model).
# Needs xvfb-run. Usage: scripts/viewer-measure.sh [OUT_DIR]   (default: viewer-measure-out/)
# Environment: PROXYGI (default build/release/apps/proxygi), SHARED (default ../shared).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=$(realpath "${PROXYGI:-$ROOT/build/release/apps/proxygi}")
SHARED=$(realpath "${SHARED:-$ROOT/../shared}")
OUT=${1:-viewer-measure-out}
mkdir -p "$OUT" && cd "$OUT"
fps() { /usr/bin/python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print('fps %.2f frame_ms %.1f internal %s frames %d' % (s['fps_mean'], s['frame_ms']['mean'], s['internal'], s['frames']))" "$1"; }
load() { cut -d' ' -f1 /proc/loadavg; }
bench() { echo "bench frame $(date +%T) load $(load): $("$B" bench frame --size 512 --frames 8 --only default 2>&1 | grep -E '^default +image +compute 1/4')"; }
bench
for rep in 1 2 3; do
  echo "== rep $rep $(date +%T) load $(load)"
  xvfb-run -a "$B" view default --play --max-frames 60 --width 512 --height 512 --no-adaptive --state-out w_ui.json >/dev/null 2>&1
  echo -n "window, UI:         "; fps w_ui.json
  xvfb-run -a "$B" view default --play --max-frames 60 --width 512 --height 512 --no-adaptive --no-ui --state-out w_noui.json >/dev/null 2>&1
  echo -n "window, no UI:      "; fps w_noui.json
  "$B" view default --offscreen --play --max-frames 60 --width 512 --height 512 --no-adaptive --no-ui --state-out off.json >/dev/null 2>&1
  echo -n "offscreen, no UI:   "; fps off.json
done
bench
echo "== 1280x720 $(date +%T) load $(load)"
xvfb-run -a "$B" view default --play --max-frames 40 --no-adaptive --state-out fixed.json >/dev/null 2>&1
echo -n "adaptive off: "; fps fixed.json
xvfb-run -a "$B" view default --play --max-frames 200 --state-out adaptive.json >/dev/null 2>&1
echo -n "adaptive on:  "; fps adaptive.json
echo "== first frame $(date +%T) load $(load)"
rm -rf models && mkdir models
for m in CesiumMan Fox RiggedSimple; do
  cp "$SHARED/assets/gltf/$m.glb" models/
  for run in fresh cached; do
    echo -n "$m ($run rig): "
    xvfb-run -a "$B" view "models/$m.glb" --max-frames 40 2>&1 | grep -E "first frame|proxies of" | tr '\n' ' '
    echo
  done
done
