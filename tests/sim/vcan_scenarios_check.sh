#!/usr/bin/env bash
# vcan_scenarios_check.sh SOURCE_DIR TREAD TIR OUT: runs tests/sim/vcan_scenarios.sh over real
# SocketCAN (in the VM harness when the host has no CAN), brings the candump captures and the rig's
# traces back to OUT, and decodes each capture with the DBC by the independent parser
# (tests/sim/decode_capture.py, python3-canmatrix), checking it against the traces.
set -euo pipefail
src=$1 tread=$2 tir=$3 out=$4
scenarios=braking,hunting
rm -rf "$out"
mkdir -p "$out"
TREAD_OUT_DIR=$out "$src/scripts/vm/run-vcan-test.sh" --workdir "$out" \
  --file "$tread:$tread" --file "$tir:$tir" -- \
  "$src/tests/sim/vcan_scenarios.sh" "$tread" "$tir" "$scenarios"
status=0
for layout in classic fd; do
  traces=()
  IFS=, read -ra names <<<"$scenarios"
  for n in "${names[@]}"; do traces+=("$out/rig_$layout/$n.csv"); done
  /usr/bin/python3 "$src/tests/sim/decode_capture.py" "$src/src/proto/tread_$layout.dbc" \
    "$out/capture_$layout.log" "${traces[@]}" || status=1
done
exit $status
