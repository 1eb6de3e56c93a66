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
exit $status
