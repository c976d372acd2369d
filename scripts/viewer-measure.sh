#!/usr/bin/env bash
# The viewer's figures of README "Viewer" (issue 13): the UI + present cost against the offscreen
# viewer and against `bench frame` (the issue's baseline) at 512², REPS interleaved repetitions so each ratio comes from runs
# seconds apart, then the median and every value of each ratio per build; fps at 1280×720 with and without the adaptive resolution; time from
# `proxygi view MODEL.glb` to the first frame, and to proxies when the rig is fitted, for the
# shared characters (copied to OUT_DIR/models first: the viewer caches rigs next to a model).
# Needs xvfb-run. Usage: scripts/viewer-measure.sh [OUT_DIR]   (default: viewer-measure-out/)
# Environment: PROXYGI (default build/release/apps/proxygi), SHARED (default ../shared), REPS (3),
# BEFORE (another build, run interleaved with this one), ONLY_UI=1 (the 512² comparison alone),
# NO_CACHE=1 (also this build with --no-ui-cache: the UI rasterized onto every frame), FRAMES
# (frames per viewer run, default 150: several seconds, so a run weighs the HUD's once-a-second
# and five-second work as a person's session does).
# Frame times are the state file's steady mean (frame_ms_steady: every frame after the first
# run::kWarmupFrames, as `bench frame` times frames after as many warm-up frames); a build
# without it gives frame_ms, the mean of its last 128 frames.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=$(realpath "${PROXYGI:-$ROOT/build/release/apps/proxygi}")
SHARED=$(realpath "${SHARED:-$ROOT/../shared}")
OUT=${1:-viewer-measure-out}
mkdir -p "$OUT" && cd "$OUT"
# One line per run: fps, mean frame time, then where the frames' wall time went (the state file's
# frame_parts_ms: acquire, render = CPU prepare + submit + ring waits, ui_build, ui_submit,
# present; on lavapipe the device's work shows as waiting in ui_submit offscreen and in present
# in a window, where the software swapchain waits for the frame before copying it to X).
FRAMES=${FRAMES:-150}
STEADY="def steady(s): return s.get('frame_ms_steady', s['frame_ms'])['mean']"
fps() { /usr/bin/python3 -c "
import json, sys
$STEADY
s = json.load(open(sys.argv[1]))
parts = ' '.join('%s %.2f' % (k, v) for k, v in s.get('frame_parts_ms', {}).items() if v >= 0.005)
print('fps %.2f frame_ms %.1f internal %s frames %d | %s' % (1000 / steady(s), steady(s), s['internal'], s['frames'], parts))" "$1"; }
# ratio TAG w_ui.json w_noui.json off.json: prints the repetition's ratios and appends them to ratios.txt.
ratio() { /usr/bin/python3 -c "
import json, sys
$STEADY
ms = [steady(json.load(open(f))) for f in sys.argv[2:]]
print('UI + present %+.1f %% (window with UI %.1f ms / offscreen without %.1f ms); present alone %+.1f %%' % (100 * (ms[0] / ms[2] - 1), ms[0], ms[2], 100 * (ms[1] / ms[2] - 1)))
open('ratios.txt', 'a').write('%s vs_offscreen %.4f\n%s present_alone %.4f\n' % (sys.argv[1], ms[0] / ms[2], sys.argv[1], ms[1] / ms[2]))" "$@"; }
load() { cut -d' ' -f1 /proc/loadavg; }
bench() { echo "bench frame $(date +%T) load $(load): $("$B" bench frame --size 512 --frames 8 --only default 2>&1 | grep -E '^default +image +compute 1/4')"; }
bench
# BEFORE=other/proxygi: each configuration also runs that build, right before this one.
# NO_CACHE=1: this build with --no-ui-cache too ("nocache:" marks it).
BINS=("$B"); [[ -n "${BEFORE:-}" ]] && BINS=("$(realpath "$BEFORE")" "$B")
[[ -n "${NO_CACHE:-}" ]] && BINS+=("nocache:$B")
REPS=${REPS:-3}
rm -f ratios.txt
for rep in $(seq "$REPS"); do
  echo "== rep $rep $(date +%T) load $(load)"
  for entry in "${BINS[@]}"; do
    bin=${entry#nocache:}; ui_flags=""
    tag=$([[ "$bin" == "$B" ]] && echo "" || echo " (BEFORE)")
    [[ "$entry" == nocache:* ]] && ui_flags="--no-ui-cache" && tag=" (--no-ui-cache)"
    xvfb-run -a "$bin" view default --play --max-frames $FRAMES --width 512 --height 512 --no-adaptive $ui_flags --state-out w_ui.json >/dev/null 2>&1
    echo -n "window, UI$tag:         "; fps w_ui.json
    xvfb-run -a "$bin" view default --play --max-frames $FRAMES --width 512 --height 512 --no-adaptive --no-ui --state-out w_noui.json >/dev/null 2>&1
    echo -n "window, no UI$tag:      "; fps w_noui.json
    "$bin" view default --offscreen --play --max-frames $FRAMES --width 512 --height 512 --no-adaptive --no-ui --state-out off.json >/dev/null 2>&1
    echo -n "offscreen, no UI$tag:   "; fps off.json
    echo -n "rep $rep$tag: "; ratio "${tag:- (this build)}" w_ui.json w_noui.json off.json
    # The issue's own baseline: `bench frame`'s pipelined loop, same size and setting, same minute.
    bench_ms=$("$bin" bench frame --size 512 --frames 30 --only default 2>&1 | awk '/^default +image +compute 1\/4/ {print $8}')
    /usr/bin/python3 -c "
import json, sys
$STEADY
ui = steady(json.load(open('w_ui.json')))
print('rep $rep$tag: window with UI %.1f ms / bench frame %.1f ms: %+.1f %%' % (ui, float(sys.argv[1]), 100 * (ui / float(sys.argv[1]) - 1)))
open('ratios.txt', 'a').write('%s vs_bench_frame %.4f\n' % (sys.argv[2], ui / float(sys.argv[1])))" "$bench_ms" "${tag:- (this build)}"
  done
done
# Median and every value of each ratio (window with UI / offscreen viewer without, window
# without UI / offscreen, window with UI / bench frame), per build.
/usr/bin/python3 -c "
import collections, statistics
values = collections.defaultdict(list)
for line in open('ratios.txt'):
    *tag, kind, value = line.split()
    values[(' '.join(tag), kind)].append(float(value))
for (tag, kind), v in sorted(values.items()):
    print('%-20s %-15s median %+.1f %%  all: %s  (%d of %d <= +10 %%)' % (tag, kind, 100 * (statistics.median(v) - 1),
          ' '.join('%+.1f' % (100 * (x - 1)) for x in v), sum(x <= 1.10 for x in v), len(v)))"
[[ -n "${ONLY_UI:-}" ]] && exit 0  # ONLY_UI=1: the 512² comparison alone
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
