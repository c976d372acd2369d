#!/usr/bin/env bash
# The README's second command: install dependencies, build (release, tests on), run every test.
# GPU tests run on whatever Vulkan device is chosen (lavapipe on CI) with the validation layer on.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
ctest --preset release --timeout 900 "$@"
