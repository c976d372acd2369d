#!/usr/bin/env bash
# Builds proxygi and runs `bench frame` and `bench chart --quick` on a real GPU's Vulkan device,
# writing JSON, within about 8 minutes on a CUDA-class machine (16 cores). Usage:
#   scripts/gpu-bench.sh [OUT_DIR]        (default: gpu-bench-out/)
# Environment:
#   PROXYGI_DEVICE   device name substring or index for --device (default: the first discrete
#                    GPU, i.e. the context's own choice, which prefers a real GPU over lavapipe)
#   BUILD_DIR        build folder (default: build/gpu-bench)
#   JOBS             parallel build jobs (default: nproc)
#   TIME_LIMIT_S     per-step time limit (default 240 s build, 180 s per benchmark)
# Writes OUT_DIR/devices.txt, OUT_DIR/bench-frame.json (512² and 1024²), OUT_DIR/bench-chart/ (the
# quick chart's CSV/MD/PNG) and OUT_DIR/bench-chart.json, and OUT_DIR/summary.txt with the device
# name and the frame rates against the GPU goals (default scene at 1024² with 1/4 receivers
# ≥ 1000 fps; crowd ≥ 500 fps). Fails (exit 1) when no non-CPU Vulkan device is found, so a
# lavapipe run is never reported as GPU figures.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/gpu-bench-out}"
build="${BUILD_DIR:-$root/build/gpu-bench}"
jobs="${JOBS:-$(nproc)}"
build_limit="${TIME_LIMIT_S:-240}"
bench_limit="${TIME_LIMIT_S:-180}"
mkdir -p "$out"
start=$(date +%s)
step() { echo "gpu-bench: [$(( $(date +%s) - start )) s] $*" >&2; }

step "configure + build ($jobs jobs) in $build"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPROXYGI_BUILD_TESTS=OFF "${launcher[@]}" >"$out/configure.log"
timeout "$build_limit" cmake --build "$build" --target proxygi -j "$jobs" >"$out/build.log"
proxygi="$build/apps/proxygi"

device_args=()
[ -n "${PROXYGI_DEVICE:-}" ] && device_args=(--device "$PROXYGI_DEVICE")

step "devices"
"$proxygi" devices >"$out/devices.txt" 2>&1 || true
cat "$out/devices.txt" >&2
# The chosen device must not be a CPU driver (llvmpipe/lavapipe/SwiftShader).
probe="$("$proxygi" bench frame --only crowd --frames 1 --size 64 --json "${device_args[@]}" 2>/dev/null)"
device="$(python3 -c 'import json,sys; print(json.load(sys.stdin)["device"])' <<<"$probe")"
case "$device" in
  *llvmpipe*|*lavapipe*|*SwiftShader*)
    echo "gpu-bench: the Vulkan device is '$device', a CPU driver; no GPU figures written" >&2
    exit 1 ;;
esac
step "device: $device"

for size in 512 1024; do
  step "bench frame --size $size"
  timeout "$bench_limit" "$proxygi" bench frame --json --frames 30 --size "$size" "${device_args[@]}" \
    >"$out/bench-frame-$size.json"
done
python3 - "$out" <<'EOF' >"$out/bench-frame.json"
import json, sys
out = sys.argv[1]
print(json.dumps({str(s): json.load(open(f"{out}/bench-frame-{s}.json")) for s in (512, 1024)}, indent=2))
EOF

step "bench chart --quick"
timeout "$bench_limit" "$proxygi" bench chart --quick --json --out "$out/bench-chart" --cache "$out/chart-cache" \
  "${device_args[@]}" >"$out/bench-chart.json" 2>"$out/bench-chart.log" || {
  echo "gpu-bench: bench chart failed or ran out of time (see $out/bench-chart.log)" >&2; }

python3 - "$out" "$device" <<'EOF' | tee "$out/summary.txt"
import json, sys
out, device = sys.argv[1], sys.argv[2]
frame = json.load(open(f"{out}/bench-frame-1024.json"))
def fps(scene, k, splat="compute"):
    for r in frame["results"]:
        if r["scene"] == scene and r["method"] == "image" and r["receiver_scale"] == k and r["splat"] == splat:
            return r["fps"]
    return float("nan")
d, c = fps("default", 4), fps("crowd", 4)
print(f"device: {device}")
print(f"default scene 1024^2, 1/4 receivers: {d:.0f} fps (goal >= 1000: {'met' if d >= 1000 else 'not met'})")
print(f"crowd (20 characters) 1024^2, 1/4:  {c:.0f} fps (goal >= 500: {'met' if c >= 500 else 'not met'})")
EOF
step "done; JSON in $out"
