#!/usr/bin/env bash
# Label slurm: a single-node Slurm cluster on localhost (scripts/slurm-local.sh) runs
#  1. `record --shard` of 4 frames of the default scene as an sbatch --array of 2 tasks, and
#  2. `regress --shard` of the suite (budget checks included) as an sbatch --array of 2 tasks, merged;
#  3. `bench chart --quick --shard` (the default scene at 48², 8 spp references) as an sbatch
#     --array of 2 tasks, merged;
# each must be byte-identical to a single-process run (the chart: its scores, and every file when
# the merge is given the single run's times). Exit 77 (skipped) when slurm cannot run.
# Usage: slurm_check.sh PROXYGI SOURCE_DIR WORK_DIR
set -uo pipefail
proxygi=$1 source=$2 work=$(realpath -m "$3")
rm -rf "$work" && mkdir -p "$work"
started=$("$source/scripts/slurm-local.sh" start "$work/cluster")
code=$?
[ $code -eq 0 ] || exit $code
eval "$started"
trap '"$source/scripts/slurm-local.sh" stop "$work/cluster"' EXIT
suite=$source/tests/regress
frames=(--frames 0:3 --width 64 --height 64)

sbatch --wait --array=0-1 --output="$work/record_%a.log" "$source/scripts/slurm/record-array.sbatch" \
  "$proxygi" default "$work/record_sharded" "${frames[@]}" > /dev/null || { echo "FAIL: record array"; cat "$work"/record_*.log; exit 1; }
sbatch --wait --array=0-1 --output="$work/regress_%a.log" "$source/scripts/slurm/regress-array.sbatch" \
  "$proxygi" "$work/regress" "$suite" > /dev/null || { echo "FAIL: regress array"; cat "$work"/regress_*.log; exit 1; }
"$proxygi" regress --merge "$work"/regress/shard_* --report "$work/regress/merged" || { echo "FAIL: merge"; exit 1; }
chart=(--quick --size 48 --frames 1 --reference-spp 8 --scenes default --cache "$work/chart/cache")
sbatch --wait --array=0-1 --output="$work/chart_%a.log" "$source/scripts/slurm/chart-array.sbatch" \
  "$proxygi" "$work/chart" "${chart[@]}" > /dev/null || { echo "FAIL: chart array"; cat "$work"/chart_*.log; exit 1; }

"$proxygi" record default -o "$work/record_single" --no-mp4 "${frames[@]}" 2> /dev/null || { echo "FAIL: single record"; exit 1; }
"$proxygi" regress "$suite" --report "$work/regress_single" > /dev/null 2>&1 || { echo "FAIL: single regress"; exit 1; }
"$proxygi" bench chart --quick --size 48 --frames 1 --reference-spp 8 --scenes default --cache "$work/chart_single_cache" \
  --out "$work/chart_single" > /dev/null 2>&1 || { echo "FAIL: single chart"; exit 1; }
"$proxygi" bench chart --merge "$work"/chart/shard_* --out "$work/chart/merged" > /dev/null || { echo "FAIL: chart merge"; exit 1; }
"$proxygi" bench chart --merge "$work"/chart/shard_* --out "$work/chart/replayed" \
  --timings-from "$work/chart_single/bench-chart-timings.json" > /dev/null || { echo "FAIL: chart merge with times"; exit 1; }

fail=0
diff -r "$work/record_single" "$work/record_sharded" || { echo "FAIL: sharded record differs"; fail=1; }
[ "$(ls "$work/record_single"/frame_*.png | wc -l)" -eq 4 ] || { echo "FAIL: expected 4 frames"; fail=1; }
for f in results.json junit.xml report.html; do
  cmp "$work/regress_single/$f" "$work/regress/merged/$f" || { echo "FAIL: merged $f differs"; fail=1; }
done
cmp "$work/chart_single/bench-chart-scores.json" "$work/chart/merged/bench-chart-scores.json" || { echo "FAIL: chart scores differ"; fail=1; }
for f in bench-chart-scores.json bench-chart-timings.json bench-chart.csv bench-chart.md bench-chart.png; do
  cmp "$work/chart_single/$f" "$work/chart/replayed/$f" || { echo "FAIL: merged chart $f differs"; fail=1; }
done
[ $fail -eq 0 ] && echo "slurm: record, regress and bench chart arrays byte-identical to single runs"
exit $fail
