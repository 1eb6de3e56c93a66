#!/usr/bin/env bash
# The soak of issue 16: node + rig over vcan0 in the VM for SECONDS (default 600) with faults injected
# every minute (link down/up, error frames, garbage bursts, a stalled rig, a stalled node, a killed and
# restarted rig); checks and prints the summary (tests/sim/vcan_soak.sh says what is checked).
# A benchmark-like run, not a CI step. Writes build/host/soak/soak_summary.txt and soak_node.txt.
# Usage: scripts/soak.sh [SECONDS]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-600}
if ((seconds < 120)); then
  echo "soak: at least 120 s (a baseline, one round of faults, a tail)" >&2
  exit 2
fi
cmake --preset host >/dev/null && cmake --build --preset host --target tread >/dev/null
tread=$(pwd)/build/host/sim/tread
tir=$(pwd)/data/tyres/MagicFormula61_Parameters.tir
out=build/host/soak
rm -rf "$out"
mkdir -p "$out"
TREAD_VM_TIMEOUT_S=$((seconds + 300)) scripts/vm/run-vcan-test.sh --file "$tread:$tread" \
  --file "$tir:$tir" --workdir "$out" -- tests/sim/vcan_soak.sh "$tread" "$tir" "$seconds"
