#!/usr/bin/env bash
# The README's first command: install dependencies, build (release), and record the built-in
# default scene (the mannequin walking with soft shadows and bounce light) to out/: PNG frames
# and out/video.mp4. Rerunning resumes: frames already in out/ are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
build/release/apps/proxygi record default -o out --mp4
