#!/usr/bin/env bash
# Installs what a fresh Debian (bookworm) machine lacks to build BulletShockPropagation, its
# demos and tests: all from Debian's registry. Installs only what is missing. Extra package names
# given as arguments are installed too (demos/charts.sh adds python3-matplotlib).
set -euo pipefail
packages=(cmake g++ make pkg-config libbullet-dev libgtest-dev libeigen3-dev libbenchmark-dev "$@")
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
