#!/usr/bin/env bash
# Runs a test that needs SocketCAN: natively when this kernel has CAN and vcan0 (creating vcan0 when
# it can), otherwise inside the throwaway VM (scripts/vm/run-in-vm.sh). Never skips: when neither
# works, it fails loudly.
# Usage: scripts/vm/run-vcan-test.sh [run-in-vm options] -- PROGRAM [ARGS...]
# TREAD_VCAN_MODE=auto|native|vm forces a path (default auto).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mode=${TREAD_VCAN_MODE:-auto}

native_can() {
  python3 -c 'import socket; socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW).close()' \
    2>/dev/null || return 1
  if ! ip link show vcan0 >/dev/null 2>&1; then
    ip link add dev vcan0 type vcan 2>/dev/null && ip link set vcan0 mtu 72 && ip link set vcan0 up ||
      return 1
  fi
  if ! ip link show vcan1 >/dev/null 2>&1; then
    ip link add dev vcan1 type vcan 2>/dev/null && ip link set vcan1 up || return 1
  fi
}

if [[ $mode == native || ($mode == auto && $(native_can && echo yes) == yes) ]]; then
  # Options for the VM are not needed natively (the program reads and writes host paths directly;
  # a --workdir is where it writes its results: TREAD_OUT_DIR tells it).
  while (($#)) && [[ $1 != -- ]]; do
    [[ $1 == --workdir ]] && export TREAD_OUT_DIR=$2
    shift
  done
  [[ ${1:-} == -- ]] && shift
  echo "run-vcan-test: native SocketCAN" >&2
  exec "$@"
fi
echo "run-vcan-test: host kernel has no usable CAN; running in the VM" >&2
exec "$here/run-in-vm.sh" "$@"
