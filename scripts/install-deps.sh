#!/usr/bin/env bash
# Installs every Debian 12 package proxygi builds, tests or runs with. Idempotent: apt-get skips
# what is already there. Needs root (or sudo); downloads nothing outside Debian's archive.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git clang libclang-rt-14-dev
  # libraries
  libtinygltf-dev libglm-dev libopenmesh-dev libstb-dev nlohmann-json3-dev libcli11-dev
  libeigen3-dev libembree-dev libtinyexr-dev libglfw3-dev libimgui-dev libpng-dev
  # Vulkan: loader, headers, lavapipe (Mesa CPU driver), shader compiler, validation layer
  libvulkan-dev mesa-vulkan-drivers glslang-tools spirv-tools vulkan-validationlayers vulkan-tools
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # the viewer's window tests: an X server of their own, real input events
  xvfb xauth xdotool
  # video output and charts (matplotlib is called as /usr/bin/python3)
  ffmpeg python3-numpy python3-matplotlib
  # regression reports in a real browser (label browser), a local Slurm cluster (label slurm)
  chromium slurm-wlm munge
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
