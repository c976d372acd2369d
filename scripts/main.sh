#!/usr/bin/env bash
# The README's first command: install dependencies, build (release), run the main job on the
# built-in default. Until the recorder lands, the main job lists the Vulkan devices.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
mkdir -p out
build/release/apps/proxygi devices
