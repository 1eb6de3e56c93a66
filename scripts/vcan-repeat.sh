#!/usr/bin/env bash
# Runs the SocketCAN tests (ctest -L vcan: natively or in the VM) N times in a row and prints one row
# per run: result, seconds, and what the tests measured (the flood per protocol frame from the fault
# test's calibration, the lockstep pace set from it, the flood reached, the node's lost frames and
# receive-queue overflows, candump's drops in the scenario capture).
# --load: with a CPU hog beside it (stress-ng, one worker at 100 %: the other core of a 2-core machine
# busy the whole time). Issue 16's reliability runs; logs in build/host/vcan-repeat/.
# Usage: scripts/vcan-repeat.sh [--load] [N]
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
load=0
if [[ ${1:-} == --load ]]; then load=1; shift; fi
runs=${1:-10}
cmake --preset host >/dev/null && cmake --build --preset host || exit 1
logs=build/host/vcan-repeat/$([[ $load == 1 ]] && echo load || echo quiet)
rm -rf "$logs"
mkdir -p "$logs"
hog=""
if ((load)); then
  command -v stress-ng >/dev/null || { echo "vcan-repeat: stress-ng not found: run scripts/install-deps.sh" >&2; exit 1; }
  stress-ng --cpu 1 --cpu-load 100 --quiet &
  hog=$!
  trap 'kill $hog 2>/dev/null; wait $hog 2>/dev/null' EXIT
fi
echo "vcan tests, $runs runs$([[ $load == 1 ]] && echo ", under stress-ng --cpu 1") on $(nproc) cores, $(git rev-parse --short HEAD)"
echo "| run | result | s | flood calibration classic / FD | pace classic / FD (us) | flood reached classic / FD | node lost / overflowed classic / FD | capture drops classic / FD |"
echo "|---|---|---|---|---|---|---|---|"
failed=0
for ((k = 1; k <= runs; k++)); do
  log=$logs/run$k.log
  start=$(date +%s)
  if ctest --test-dir build/host -L vcan -V >"$log" 2>&1; then result=pass; else result=FAIL; failed=$((failed + 1)); fi
  secs=$(($(date +%s) - start))
  cal=$(grep -oE "calibration: [0-9.]+x" "$log" | awk '{ printf "%s%s", sep, $2; sep = " / " }')
  pace=$(grep -oE "lockstep paced at [0-9]+" "$log" | awk '{ printf "%s%s", sep, $4; sep = " / " }')
  lost=$(grep -oE "node: frames lost [0-9]+, receive-queue overflows [0-9]+" "$log" |
    awk '{ printf "%s%s / %s", sep, $4, $7; sep = "; " }' | tr -d ,)
  flood=$(grep -oE "flood: [0-9]+ frames on vcan0 besides the protocol's [0-9]+: [0-9.]+x" "$log" |
    awk '{ printf "%s%s", sep, $NF; sep = " / " }')
  drops=$(grep -oE "capture drops [0-9]+" "$log" | awk '{ printf "%s%s", sep, $3; sep = " / " }')
  echo "| $k | $result | $secs | $cal | $pace | $flood | $lost | $drops |"
  if [[ $result == FAIL ]]; then grep -E "FAIL|Failed|\*\*\*" "$log" | head -5 | sed 's/^/    /'; fi
done
echo "$((runs - failed)) of $runs passed"
((failed == 0))
