#!/usr/bin/env bash
# Timing benchmark of the node (not pass/fail: these machines are shared and noisy). In one run, on
# the same machine: cyclictest's wake-up latency (SCHED_FIFO 80, 1 kHz), then the node's wake-up
# latency and cycle time in the same conditions (the HIL demo: 4 tyres + 2 wheelsets, rig on the
# in-process bus, real clock), then the cycle compute time from Google Benchmark.
# Usage: scripts/bench-timing.sh [SECONDS]   (default 10 s each)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-10}
cmake --preset host >/dev/null
cmake --build --preset host --target tread node_cycle_bench >/dev/null

hist=$(mktemp)
trap 'rm -f "$hist"' EXIT
echo "== cyclictest: SCHED_FIFO 80, mlockall, 1 kHz, ${seconds} s =="
if ! cyclictest -m -p 80 -i 1000 -l $((seconds * 1000)) -q -h 20000 >"$hist" 2>&1; then
  echo "cyclictest failed (needs root for SCHED_FIFO):"
  cat "$hist"
fi
awk '
  /^[0-9]+ +[0-9]+/ { us = $1 + 0; n = $2 + 0; count[us] = n; total += n; if (us > maxus && n > 0) maxus = us }
  /# Max Latencies/ { max = $4 + 0 }
  END {
    if (total == 0) { print "no histogram"; exit }
    split("0.5 0.99", qs, " ")
    for (k = 1; k <= 2; k++) {
      target = qs[k] * total; seen = 0
      for (us = 0; us <= maxus; us++) { seen += count[us]; if (seen >= target) { p[k] = us; break } }
    }
    printf "cyclictest wake latency  p50 %d us, p99 %d us, max %d us  (%d samples)\n", p[1], p[2], max, total
  }' "$hist"

echo
echo "== tread node: SCHED_FIFO 80, mlockall, 1 kHz, 4 tyres + 2 wheelsets, ${seconds} s =="
build/host/sim/tread demo --scenario sweep --sweep-duration-s "$seconds" --rt-priority 80 --mlock --no-plot --out build/bench-demo |
  grep -E "wake latency|cycle time|overruns|cycles|scheduler|mlockall|refused"

echo
echo "== cycle compute time (Google Benchmark, median of 5) =="
build/host/tests/loop/node_cycle_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true 2>/dev/null |
  grep -E "median"
