#!/usr/bin/env bash
# Installs every Debian package the build and the run need. Skips apt when all are present.
set -euo pipefail
pkgs=(
  build-essential cmake pkg-config git
  libmujoco-dev libqhull-dev
  libeigen3-dev nlohmann-json3-dev libcli11-dev libabsl-dev
  libompl-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  libgtest-dev libgmock-dev
  libegl-dev libegl-mesa0 libgl1-mesa-dri libgl-dev
  libpng-dev ffmpeg
  libcpp-httplib-dev
  libtorch-dev libopenblas0-openmp
  libopenmpi-dev openmpi-bin
  clang libfuzzer-14-dev libclang-rt-14-dev
  pybind11-dev python3-dev python3-numpy python3-torch python3-matplotlib
  blender libjs-three chromium
)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then exit 0; fi
echo "installing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
