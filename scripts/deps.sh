#!/usr/bin/env bash
# Installs the Debian packages edyn needs to build, test, benchmark and run its demo, when any
# is missing. Idempotent, and silent when everything is already there.
set -euo pipefail

packages=(
  g++ cmake make ninja-build pkg-config
  libtbb-dev
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  libcli11-dev
  libbullet-dev gnuplot-nox
  libenet-dev
  libtinyobjloader-dev
  clang libclang-rt-14-dev
  doxygen
  libglfw3-dev libimgui-dev libstb-dev libgl-dev xvfb xauth libgl1-mesa-dri
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "deps.sh: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "deps.sh: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
