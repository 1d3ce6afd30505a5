#!/usr/bin/env bash
# Installs the Debian packages trilho needs to build, test and run (sudo when not root).
# Run by scripts/run and scripts/test; installs nothing when everything is already there, then
# checks that every tool and Python module the tests use answers (scripts/check-tools), so a
# missing package is one line here rather than a traceback inside a test.
# Usage: scripts/deps.sh [--no-check]   (--no-check: install only; scripts/run, which runs no test)
set -euo pipefail
TRILHO_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  # The boards' own firmware (firmware/, issue 32): avr-gcc and avr-libc cross-compile it in the
  # normal build (binutils-avr, avr-objcopy and avr-size, comes with gcc-avr); libsimavr runs it
  # cycle for cycle against the plants in the tests (hal/firmware_sim), simavr is the same
  # simulator as a command, for looking at an image by hand.
  gcc-avr avr-libc simavr libsimavr-dev
  qt6-base-dev qt6-serialport-dev qt6-serialbus-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  qt6-translations-l10n
  libqcustomplot-dev libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev libgl1-mesa-dev
  xvfb xauth
  help2man desktop-file-utils file
  # clang-14's sanitizer and fuzzer runtimes (libclang_rt.*) are in libclang-rt-14-dev, which
  # clang-14 only recommends; libfuzzer-14-dev alone does not link -fsanitize=fuzzer.
  clang-14 libfuzzer-14-dev libclang-rt-14-dev
  socat
  mbpoll python3-pymodbus libmodbus-dev
  # pymodbus.client imports serial_asyncio (Debian 12's pymodbus 3.0 lists it only as a
  # Recommends, and we install without recommends).
  python3-serial-asyncio
  # The widget tests measure the screens with named font files (tests/support/test_fonts.h,
  # issue 35): DejaVu Sans and Sans Mono (the oblique faces, which the forms' italic captions
  # use, are in fonts-dejavu-extra), and Noto Sans Mono, the monospace fontconfig picks once
  # fonts-noto-mono is on a desktop (it moved the rail's readout by 11 px at 1024x768).
  fonts-dejavu-core fonts-dejavu-extra fonts-noto-mono
  # and the other sets a Debian 12 desktop may bring, which the layout test runs with each
  # (layoutHoldsWithEachFontSet): Noto Sans (fontconfig's "Sans Serif" once installed, KDE's
  # font), Liberation (GNOME, LibreOffice) and URW base35 (Ghostscript, ImageMagick).
  fonts-noto-core fonts-liberation2 fonts-urw-base35
)
check=1
[ "${1:-}" = "--no-check" ] && check=0
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
[ $check -eq 0 ] || bash "$(dirname "${BASH_SOURCE[0]}")/check-tools" --quiet
