#!/usr/bin/env bash
# The viewer's figures of README "Viewer" (issue 13): what the UI and the present cost, measured
# in one process (`view --measure-blocks`: blocks of 12 frames cycle through the window with the
# UI, the window without it, an offscreen image of the same size and format, and readback as
# `bench frame` times it, so every ratio compares neighbouring blocks under the same machine
# state; separate processes a minute apart differed by ±20 % on this 2-core machine), at 512²
# and 1280×720, playing and paused; `bench frame` at 512² for reference; fps at 1280×720 with and
# without the adaptive resolution; time from `proxygi view MODEL.glb` to the first frame, and to
# proxies when the rig is fitted, for the shared characters (copied to OUT_DIR/models first: the
# viewer caches rigs next to a model).
# Needs xvfb-run. Usage: scripts/viewer-measure.sh [OUT_DIR]   (default: viewer-measure-out/)
# Environment: PROXYGI (default build/release/apps/proxygi), SHARED (default ../shared), REPS (2:
# block runs per size and playback), FRAMES (2400 at 512², a third of it at 1280×720), ONLY_UI=1
# (the UI + present comparison alone), NO_CACHE=1 (the UI rasterized onto every frame instead of
# the cached overlay: --no-ui-cache).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=$(realpath "${PROXYGI:-$ROOT/build/release/apps/proxygi}")
SHARED=$(realpath "${SHARED:-$ROOT/../shared}")
OUT=${1:-viewer-measure-out}
REPS=${REPS:-2}
FRAMES=${FRAMES:-2400}
mkdir -p "$OUT" && cd "$OUT"
load() { cut -d' ' -f1 /proc/loadavg; }
# blocks.json: each ending's mean ms, and the paired ratios of neighbouring blocks (median and
# quartiles): window with UI / offscreen is the UI + present cost, window without UI / offscreen
# the present alone, window / window without UI the UI alone, window / readback against `bench frame`'s loop.
report() { /usr/bin/python3 -c "
import json, statistics as st, sys
s = json.load(open(sys.argv[1]))['measure_blocks_ms']
kinds = ['window', 'window_no_ui', 'offscreen', 'readback']
n = min(len(s[k]) for k in kinds)
print('  ms per frame: ' + '  '.join('%s %.2f' % (k, st.mean(s[k][:n])) for k in kinds) + '  (%d blocks of %d frames each)' % (n, s['block_frames']))
for a, b, what in [('window', 'offscreen', 'UI + present'), ('window_no_ui', 'offscreen', 'present alone'),
                   ('window', 'window_no_ui', 'UI alone'), ('window', 'readback', 'window with UI vs bench frame loop')]:
    r = [s[a][i] / s[b][i] for i in range(n)]
    q = st.quantiles(r, n=4)
    print('  %-36s median %+6.1f %%  quartiles %+.1f .. %+.1f %%  (means %+.1f %%)' % (what, 100 * (st.median(r) - 1), 100 * (q[0] - 1), 100 * (q[2] - 1),
          100 * (st.mean(s[a][:n]) / st.mean(s[b][:n]) - 1)))" "$1"; }
ui_flags=""; [[ -n "${NO_CACHE:-}" ]] && ui_flags="--no-ui-cache"
for size in 512x512 1280x720; do
  w=${size%x*}; h=${size#*x}
  frames=$FRAMES; [[ "$size" == 1280x720 ]] && frames=$((FRAMES / 3))
  for playback in playing paused; do
    play=""; [[ "$playback" == playing ]] && play="--play"
    for rep in $(seq "$REPS"); do
      echo "== $size $playback rep $rep $(date +%T) load $(load)"
      xvfb-run -a "$B" view default $play $ui_flags --max-frames "$frames" --width "$w" --height "$h" --no-adaptive \
        --measure-blocks 12 --state-out "blocks_${size}_${playback}_${rep}.json" >/dev/null 2>&1
      report "blocks_${size}_${playback}_${rep}.json"
    done
  done
done
echo "bench frame $(date +%T) load $(load): $("$B" bench frame --size 512 --frames 30 --only default 2>&1 | grep -E '^default +image +compute 1/4')"
[[ -n "${ONLY_UI:-}" ]] && exit 0  # ONLY_UI=1: the UI + present comparison alone
# One line per run: fps and mean frame time, from the state file's FIELD: frame_ms_steady (every
# frame after the warm-up) or frame_ms (the last 128 frames: where the adaptive resolution settled).
fps() { /usr/bin/python3 -c "
import json, sys
s = json.load(open(sys.argv[1]))
ms = s[sys.argv[2]]['mean']
print('fps %.2f frame_ms %.1f internal %s frames %d (%s)' % (1000 / ms, ms, s['internal'], s['frames'], sys.argv[2]))" "$1" "$2"; }
echo "== 1280x720 $(date +%T) load $(load)"
xvfb-run -a "$B" view default --play --max-frames 40 --no-adaptive --state-out fixed.json >/dev/null 2>&1
echo -n "adaptive off: "; fps fixed.json frame_ms_steady
xvfb-run -a "$B" view default --play --max-frames 200 --state-out adaptive.json >/dev/null 2>&1
echo -n "adaptive on:  "; fps adaptive.json frame_ms
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
