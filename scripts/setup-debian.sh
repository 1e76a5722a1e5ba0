#!/usr/bin/env bash
# Installs every Debian bookworm package AeroNC needs to build, run and test.
# Idempotent: packages already present are skipped by apt.
set -euo pipefail
PKGS=(
  build-essential cmake ninja-build pkg-config
  freecad-python3 freecad
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev libocct-visualization-dev libtbb-dev
  pybind11-dev python3-dev libeigen3-dev libpolyclipping-dev libnlopt-cxx-dev
  libsqlite3-dev sqlite3 libgtest-dev googletest nlohmann-json3-dev
  qtbase5-dev python3-pyside2.qtcore python3-pyside2.qtgui python3-pyside2.qtwidgets
  xvfb xauth python3-pytest python3-numpy python3-matplotlib
  linuxcnc-uspace
  clang libclang-rt-14-dev
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PKGS[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
