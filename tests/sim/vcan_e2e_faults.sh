#!/bin/sh
# vcan_e2e_faults.sh TREAD TIR: node and rig as two processes on vcan0 (classic, then FD), with faults
# injected while the loop runs: a flood of random extended-ID frames (cangen; the node's kernel filters
# drop them), an error frame (CAN_ERR_FLAG, the canerrsim technique), malformed frames on the node's
# input IDs (wrong length, bad CRC), and the link set down and up. Passes when the node survives and
# rejects and counts the bad frames, and every answer the rig checked equals the reference model.
tread=$1
tir=$2
status=0
fail() { echo "vcan_e2e_faults: FAIL: $*"; status=1; }
for layout in "" "--fd"; do
  echo "=== layout ${layout:-classic} ==="
  "$tread" node --can vcan0 $layout --tir "$tir" --period-us 2000 --duration-s 5 >/tmp/node.txt 2>&1 &
  node_pid=$!
  sleep 0.5
  "$tread" rig --can vcan0 $layout --tir "$tir" --period-us 2000 --duration-s 3.5 >/tmp/rig.txt 2>&1 &
  rig_pid=$!
  sleep 0.7
  cangen vcan0 -e -g 0.1 -n 3000 &
  gen_pid=$!
  cansend vcan0 20000040#0000000000000000         # error frame: bus-off class
  if [ -z "$layout" ]; then
    cansend vcan0 100#0011                        # WheelSlip_0 with a wrong length
    cansend vcan0 100#FF01000000000000            # WheelSlip_0 with a bad CRC
  else
    cansend vcan0 0A0##1001122334455667788        # RigInputsFD with a wrong length (8, not 64)
    cansend vcan0 0A0##1FF01000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000
  fi
  sleep 0.3
  ip link set vcan0 down
  sleep 0.2
  ip link set vcan0 up
  wait $gen_pid
  wait $rig_pid || fail "rig exited with an error"
  wait $node_pid || fail "node exited with an error"
  cat /tmp/node.txt /tmp/rig.txt
  grep -q "bad CRC [1-9]" /tmp/node.txt || fail "node did not count the bad CRC"
  grep -q "bad length [1-9]" /tmp/node.txt || fail "node did not count the wrong length"
  grep -q "error frames [1-9]" /tmp/node.txt || fail "node did not see the error frame"
  # After the link gap each output message's counter jumps: its first frame is rejected, the next
  # resynchronises (E2E); nothing else may be rejected.
  max_resync=13; [ -n "$layout" ] && max_resync=3
  awk -v max=$max_resync '/^node frames/ { if ($5 + 0 > max) exit 1 }' /tmp/rig.txt || fail "rig rejected more node frames than the link gap explains"
  grep -Eq "node frames +[1-9][0-9]* accepted" /tmp/rig.txt || fail "rig accepted no node frames"
  grep -Eq "answers checked +[1-9][0-9]{2,}" /tmp/rig.txt || fail "too few answers checked"
  awk '/^max \|dF\|/ { if ($3 + 0 > 0.6) exit 1 }' /tmp/rig.txt || fail "answers differ from the reference"
  grep -Eq "foreign frames" /tmp/rig.txt || fail "no rig report"
done
exit $status
