#!/bin/sh
# vcan_demo_check.sh TREAD TIR: the HIL demo over real SocketCAN on vcan0, classic and FD layouts.
# Passes when every frame crossed: nothing rejected, lost or refused, on either side.
tread=$1
tir=$2
status=0
for layout in "" "--fd"; do
  out=$("$tread" demo --can vcan0 $layout --tir "$tir" --wheelsets 0 --scenario sweep --sweep-duration-s 0.5 --no-plot --out /tmp/demo 2>&1)
  rc=$?
  echo "$out"
  if [ $rc -ne 0 ]; then echo "vcan_demo_check: tread demo $layout exited $rc"; status=1; fi
  echo "$out" | grep -q "frames rejected   0 " || { echo "vcan_demo_check: node rejected frames ($layout)"; status=1; }
  echo "$out" | grep -q "frames lost       0 " || { echo "vcan_demo_check: frames lost ($layout)"; status=1; }
  echo "$out" | grep -q "send refused 0)" || { echo "vcan_demo_check: sends refused ($layout)"; status=1; }
  echo "$out" | grep -Eq "rig frames +[1-9][0-9]* accepted, 0 rejected" || { echo "vcan_demo_check: rig side ($layout)"; status=1; }
done
# Sync mode over SocketCAN: the node sleeps in ppoll until the rig's cycle frame; every cycle is
# answered, and CAN-in -> CAN-out (kernel receive timestamps, CLOCK_REALTIME, put on the rig's
# CLOCK_MONOTONIC) is a real, positive latency below the 20 ms histogram: a wrong clock conversion
# would be off by decades.
out=$("$tread" demo --can vcan0 --mode sync --timeout-ms 60000 --tir "$tir" --wheelsets 0 --scenario sweep --sweep-duration-s 0.5 --no-plot --out /tmp/demo 2>&1)
rc=$?
echo "$out"
if [ $rc -ne 0 ]; then echo "vcan_demo_check: tread demo --mode sync exited $rc"; status=1; fi
echo "$out" | grep -q "cycles without a complete answer 0$" || { echo "vcan_demo_check: sync: unanswered cycles"; status=1; }
lat=$(echo "$out" | sed -n 's/^CAN-in -> CAN-out p50 \([0-9]*\) us, p99 \([0-9]*\) us.*/\1 \2/p')
set -- $lat
if [ -z "$lat" ] || [ "$1" -le 0 ] || [ "$2" -ge 20000 ]; then
  echo "vcan_demo_check: sync: CAN-in -> CAN-out not a plausible latency ('$lat')"; status=1
fi
exit $status
