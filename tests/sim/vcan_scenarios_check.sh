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
status=0
TREAD_OUT_DIR=$out "$src/scripts/vm/run-vcan-test.sh" --workdir "$out" \
  --file "$tread:$tread" --file "$tir:$tir" -- \
  "$src/tests/sim/vcan_scenarios.sh" "$tread" "$tir" "$scenarios" || status=1
profile=wheel=S1002,rail=60E1,cant=1:40
for layout in classic fd; do
  flag=""; [[ $layout == fd ]] && flag="--fd"
  # The same scenarios in process (stub bus, simulated clock): the traces must be equal, value for
  # value (lockstep makes the two-process run independent of timing).
  "$tread" demo --clock sim $flag --tir "$tir" --wheelsets 2 --wheelset-forces 0 --wheelset-profile "$profile" \
    --scenario "$scenarios" --no-plot --out "$out/inproc_$layout" >"$out/inproc_$layout.txt"
  for csv in "$out/inproc_$layout"/*.csv; do
    name=$(basename "$csv")
    if cmp -s "$csv" "$out/rig_$layout/$name"; then
      echo "vcan_scenarios_check: $layout $name: two-process trace == in-process trace ($(wc -l <"$csv") rows)"
    else
      echo "vcan_scenarios_check: FAIL: $layout $name: the two-process trace differs from the in-process one"
      status=1
    fi
  done
  traces=()
  IFS=, read -ra names <<<"$scenarios"
  for n in "${names[@]}"; do traces+=("$out/rig_$layout/$n.csv"); done
  /usr/bin/python3 "$src/tests/sim/decode_capture.py" "$src/src/proto/tread_$layout.dbc" \
    "$out/capture_$layout.log" "${traces[@]}" || status=1
done
exit $status
