#!/usr/bin/env bash
# Installs what a fresh Debian (bookworm) machine lacks to build BulletShockPropagation, its
# demos and tests: all from Debian's registry. Installs only what is missing. Extra package names
# given as arguments are installed too (demos/charts.sh adds python3-matplotlib). With --demo
# first, only what bsp_demo needs: Bullet, a compiler, CMake and pkg-config (demos/run.sh).
# The viewer (demos/viewer) and its headless tests need GLFW, Dear ImGui, libpng, EGL and Mesa's
# software renderer (llvmpipe, no GPU or display needed) and the DejaVu label font.
set -euo pipefail
packages=(cmake g++ make pkg-config libbullet-dev)
if [ "${1:-}" = --demo ]; then
  shift
else
  # dpkg-dev: dpkg-shlibdeps, for the .deb's versioned dependencies (tests/consumer).
  packages+=(dpkg-dev libgtest-dev libeigen3-dev libbenchmark-dev
    libglfw3-dev libimgui-dev libpng-dev libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri fonts-dejavu-core)
fi
packages+=("$@")
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
