#!/usr/bin/env bash
# Runs a bare-metal image under qemu-system-arm with semihosting: the words after -- become the
# image's command line (SYS_GET_CMDLINE), its files are the host's, and qemu exits with the image's
# exit status (SYS_EXIT_EXTENDED). -icount shift=0 makes the emulated clock count instructions
# (1 ns each), so the run and its SysTick readings are deterministic.
# Usage: scripts/qemu-semihost.sh MACHINE IMAGE.elf [-- ARG...]     (e.g. mps2-an386)
# Environment: QEMU_SYSTEM_ARM (default qemu-system-arm), TREAD_QEMU_TIMEOUT_S (default 300).
set -euo pipefail
if (($# < 2)); then
  echo "usage: $0 MACHINE IMAGE.elf [-- ARG...]" >&2
  exit 2
fi
machine=$1 image=$2
shift 2
if (($#)) && [[ $1 == -- ]]; then shift; fi
config="enable=on,target=native,arg=$(basename "$image")"
for word in "$@"; do
  if [[ $word == *" "* ]]; then
    echo "qemu-semihost: '$word': the semihosting command line splits at spaces" >&2
    exit 2
  fi
  config+=",arg=${word//,/,,}"  # a comma inside an option value is written twice
done
exec timeout "${TREAD_QEMU_TIMEOUT_S:-300}" "${QEMU_SYSTEM_ARM:-qemu-system-arm}" \
  -M "$machine" -nographic -monitor none -serial none -icount shift=0 \
  -semihosting-config "$config" -kernel "$image"
