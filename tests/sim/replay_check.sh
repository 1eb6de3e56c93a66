#!/usr/bin/env bash
# replay_check.sh TREAD TIR OUTDIR [--fd]: records the HIL demo (simulated clock) and replays its log
# (and replays it with --relaxation: different answers, reproducible).
set -euo pipefail
tread=$1 tir=$2 out=$3
shift 3
mkdir -p "$out"
# The float node also serves the wheel-rail forces of wheelset 0 (as the demo's does), so their
# frames are in the log and must replay bit for bit; the fixed-point node has no force path.
forces=1
for arg in "$@"; do
  if [[ $arg == --fixed ]]; then forces=0; fi
done
"$tread" demo --clock sim --scenario sweep --sweep-duration-s 1 --tir "$tir" --wheelsets 2 \
  --wheelset-forces "$forces" --wheelset-profile wheel=S1002,rail=60E1,cant=1:40 --no-plot --out "$out" --log "$out/run.log" "$@" \
  | tee "$out/demo.txt"
grep -q "frames rejected   0 " "$out/demo.txt"
"$tread" node --tir "$tir" --wheelsets 2 --wheelset-forces "$forces" \
  --wheelset-profile wheel=S1002,rail=60E1,cant=1:40 \
  --replay "$out/run.log" --clock sim --tx-log "$out/replayed_tx.log" "$@" | tee "$out/replay.txt"
grep -q "transmitted stream identical to the log, bit for bit" "$out/replay.txt"
# A changed frame in the log must be caught: flip one data digit of the first node output.
awk 'BEGIN{d=0} !d && / 0F0#/ {sub(/#../, "#00"); d=1} {print}' "$out/run.log" >"$out/tampered.log"
if "$tread" node --tir "$tir" --wheelsets 2 --wheelset-forces "$forces" \
  --wheelset-profile wheel=S1002,rail=60E1,cant=1:40 \
  --replay "$out/tampered.log" --clock sim "$@" >"$out/tampered.txt" 2>&1; then
  echo "replay_check: a tampered log replayed as identical" >&2
  exit 1
fi
grep -q "replay differs from the log" "$out/tampered.txt"
# With --relaxation the node's answers lag the recorded slips, so they differ from the log; two
# replays with relaxation transmit the same stream, bit for bit.
for run in a b; do
  if "$tread" node --tir "$tir" --wheelsets 2 --wheelset-forces "$forces" \
  --wheelset-profile wheel=S1002,rail=60E1,cant=1:40 \
    --replay "$out/run.log" --clock sim --relaxation --tx-log "$out/relaxed_$run.log" "$@" \
    >"$out/relaxed_$run.txt" 2>&1; then
    echo "replay_check: relaxation changed no answer" >&2
    exit 1
  fi
  grep -q "replay differs from the log" "$out/relaxed_$run.txt"
done
cmp "$out/relaxed_a.log" "$out/relaxed_b.log"
echo "replay_check: OK"
