#!/usr/bin/env bash
# Installs every package tread needs, from Debian's archive. Idempotent: safe to run again.
# Usage: sudo scripts/install-deps.sh   (as root: plain bash scripts/install-deps.sh)
set -euo pipefail

packages=(
  # build
  cmake ninja-build g++ make pkg-config git
  # libraries
  libgtest-dev libgmock-dev libbenchmark-dev libeigen3-dev libceres-dev libgpiod-dev libcli11-dev
  libfast-float-dev  # `tread mf eval` reads numbers with fast_float (header-only)
  libdragonbox-dev   # ... and writes them with Dragonbox's shortest digits (header-only part)
  gnuplot-nox nlohmann-json3-dev  # plots: gnuplot directly (Debian's libsciplot-dev is the Motif widget, not C++ sciplot)
  # CAN, real-time tools and the independent DBC parser
  can-utils rt-tests gpiod python3-canmatrix canmatrix-utils python3-numpy
  stress-ng  # the CPU hog beside the vcan tests (issue 16's runs under load: scripts/vcan-repeat.sh)
  # cross compilers and emulators
  g++-aarch64-linux-gnu g++-arm-linux-gnueabihf gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib
  libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-user-static qemu-system-x86
  qemu-system-arm  # the Cortex-M firmware image on the emulated MPS2 boards (ctest -L target)
  # the vcan VM harness: initramfs tools (the kernel itself is fetched by scripts/fetch-vm-kernel.sh)
  busybox-static cpio xz-utils zstd kmod
  # style
  clang-format clang-tidy
  # coverage-guided fuzzing: clang with libFuzzer and the sanitizers (preset fuzz, scripts/fuzz.sh)
  clang libclang-rt-14-dev
)

export DEBIAN_FRONTEND=noninteractive
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages already installed"
else
  echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The vcan VM harness needs Debian's kernel image (unpacked, not installed).
"$(dirname "${BASH_SOURCE[0]}")/vm/fetch-kernel.sh"
