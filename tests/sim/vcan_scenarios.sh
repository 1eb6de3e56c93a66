#!/bin/sh
# vcan_scenarios.sh TREAD TIR SCENARIOS: node and rig as two processes on vcan0 (classic, then FD). The
# node runs in sync mode; the rig runs its scenarios in lockstep with it (vehicle braking, kinematic
# hunting of two wheelsets) while candump captures the traffic into OUT/capture_<layout>.log (decoded
# afterwards with the DBC by an independent parser, tests/sim/decode_capture.py). OUT is
# $TREAD_OUT_DIR, default /work/out (the VM harness copies it back with --workdir), where
# tests/sim/vcan_scenarios_check.sh compares the traces with an in-process run. Then the same
# scenarios run in process (tread demo --clock sim). Passes when nothing was rejected, lost or late,
# neither the node's nor the rig's kernel receive queue overflowed (SO_RXQ_OVFL), and every trace of
# the two-process run equals the in-process one, value for value.
tread=$1
tir=$2
scenarios=${3:-braking,hunting}
out=${TREAD_OUT_DIR:-/work/out}
profile=wheel=S1002,rail=60E1,cant=1:40
status=0
fail() { echo "vcan_scenarios: FAIL: $*"; status=1; }
mkdir -p "$out"
for layout in classic fd; do
  flag=""; [ $layout = fd ] && flag="--fd"
  echo "=== $layout: node (sync) + rig over vcan0, scenarios $scenarios ==="
  # candump with an 8 MiB receive buffer (as root: SO_RCVBUFFORCE) and -d: should its queue still
  # overflow, the drops are written into the capture (DROPCOUNT lines) and counted as the capture's,
  # not the node's (tests/sim/decode_capture.py).
  candump -d -r 8388608 -L vcan0 >"$out/capture_$layout.log" &
  dump_pid=$!
  "$tread" node --can vcan0 $flag --tir "$tir" --wheelsets 2 --wheelset-profile "$profile" \
    --mode sync --timeout-ms 2000 >"$out/node_$layout.txt" 2>&1 &
  node_pid=$!
  sleep 0.5
  "$tread" rig --can vcan0 $flag --tir "$tir" --wheelsets 2 --wheelset-profile "$profile" \
    --scenario "$scenarios" --answer-timeout-ms 3000 --out "$out/rig_$layout" >"$out/rig_$layout.txt" 2>&1 ||
    fail "rig exited with an error ($layout)"
  kill -TERM $node_pid; wait $node_pid || fail "node exited with an error ($layout)"
  # Let candump (sharing the VM's one CPU) write out what it has queued before stopping it.
  lines=-1
  while [ "$lines" != "$(wc -l <"$out/capture_$layout.log")" ]; do
    lines=$(wc -l <"$out/capture_$layout.log"); sleep 0.5
  done
  kill -TERM $dump_pid; wait $dump_pid 2>/dev/null
  cat "$out/node_$layout.txt" "$out/rig_$layout.txt"
  grep -q "frames rejected   0 " "$out/node_$layout.txt" || fail "node rejected frames ($layout)"
  grep -q "frames lost       0 " "$out/node_$layout.txt" || fail "node lost frames ($layout)"
  grep -q "^rx queue overflow 0 " "$out/node_$layout.txt" || fail "the node's receive queue overflowed ($layout)"
  grep -q "^rx queue overflow    0 " "$out/rig_$layout.txt" || fail "the rig's receive queue overflowed ($layout)"
  grep -Eq "^rig cycles +[0-9]+ \(late answers 0," "$out/rig_$layout.txt" || fail "late answers ($layout)"
  grep -Eq "^node frames +[1-9][0-9]* accepted, 0 rejected" "$out/rig_$layout.txt" || fail "rig rejected node frames ($layout)"
done
exit $status
