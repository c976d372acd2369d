#!/usr/bin/env bash
# Process CPU time per frame (user + sys of every thread, lavapipe's included) of two proxygi
# binaries, interleaved, for comparisons on a machine whose wall times other jobs inflate.
# Usage: scripts/cpu-time-ab.sh BEFORE_BINARY AFTER_BINARY [OUT_DIR]
# Environment: FRAMES (default 26), RUNS (default 2).
# Per binary and scene, `record` of 2 and of FRAMES frames at 512² (PNG only); per frame =
# (cpu(FRAMES) − cpu(2)) / (FRAMES − 2), so start-up, loading and the first frames cancel.
# Scenes: the default scene with receivers at 1/1 and at 1/4, the crowd at 1/4. Writes
# OUT_DIR/log (one line per binary, scene and run) and prints ms per frame and the ratios.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
before="$1"; after="$2"; out="${3:-cpu-time-ab-out}"
frames="${FRAMES:-26}"; runs="${RUNS:-2}"
mkdir -p "$out"
sed 's/"receiver_scale": 4/"receiver_scale": 1/' "$root/assets/scenes/default.json" > "$out/default_k1.json"
cp "$root/assets/scenes/default.json" "$out/default_k4.json"
cp "$root/assets/scenes/crowd.json" "$out/crowd_k4.json"
: > "$out/log"
for run in $(seq 1 "$runs"); do
  for scene in default_k1 default_k4 crowd_k4; do
    for variant in before after; do
      binary="$before"; [ "$variant" = after ] && binary="$after"
      for n in 2 "$frames"; do
        /usr/bin/time -f "%U %S %e" -o "$out/time-$n" "$binary" record "$out/$scene.json" -o "$out/frames-$variant-$scene" \
          --frames "0:$((n - 1))" --overwrite --no-mp4 -q
      done
      echo "$variant $scene $run $(cat "$out/time-2") $(cat "$out/time-$frames") $(uptime | sed 's/.*average: //')" >> "$out/log"
    done
  done
done
awk -v n="$frames" '{ cpu = ($7 + $8 - $4 - $5) / (n - 2) * 1000; key = $2 " run " $3; v[key, $1] = cpu; keys[key] = 1 }
  END { for (k in keys) printf "%-18s CPU ms/frame before %7.1f after %7.1f ratio %.2f\n", k, v[k, "before"], v[k, "after"],
        v[k, "before"] / v[k, "after"] }' "$out/log" | sort
