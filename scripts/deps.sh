#!/usr/bin/env bash
# Installs the Debian packages trilho needs to build, test and run (sudo when not root).
# Sourced by scripts/run and scripts/test; does nothing when everything is already there.
set -euo pipefail
TRILHO_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev qt6-serialport-dev qt6-serialbus-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  qt6-translations-l10n
  libqcustomplot-dev libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev libgl1-mesa-dev
  xvfb xauth
  help2man desktop-file-utils file
  clang-14 libfuzzer-14-dev
  socat
  mbpoll python3-pymodbus libmodbus-dev
)
missing=()
for p in "${TRILHO_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "trilho: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
