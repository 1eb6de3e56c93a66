#!/usr/bin/env bash
# Timing benchmark of the node (not pass/fail: these machines are shared and noisy). In one run, on
# the same machine and the same CPU:
#   1. cyclictest: SCHED_FIFO 80, mlockall, 1 kHz, pinned to the last CPU: the machine's own wake-up
#      latency, the yardstick for everything below;
#   2. the node as it runs on a rig (`tread demo`, real clock): its own thread on that CPU,
#      SCHED_FIFO 80, mlockall with a prefaulted stack and heap, no I/O on its thread; the rig and
#      its answer checker on another thread, on another CPU at SCHED_FIFO 70, over the lock-free
#      in-process link; 4 tyres + 2 wheelsets (one with wheel-rail forces), the "sweep" scenario.
#      Periodic mode: the node's wake latency, cycle time and overruns on its own deadlines;
#   3. the same in sync mode: the node sleeps until the rig's cycle frame and answers it;
#      CAN-in -> CAN-out latency (the rig's cycle frame to the node's last answer frame);
#   4. the cycle's compute time from Google Benchmark.
# Then the figures against the goals of issue 17 (node wake p99 <= 1.2 x cyclictest p99; no overrun
# when cyclictest stays below the period; CAN-in -> CAN-out p99 <= cyclictest p99 + 30 us).
# Usage: scripts/bench-timing.sh [SECONDS]   (default 10 s each)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-10}
cpu=$(($(nproc) - 1))
cmake --preset host >/dev/null
cmake --build --preset host --target tread node_cycle_bench >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "== cyclictest: SCHED_FIFO 80, mlockall, 1 kHz, CPU $cpu, ${seconds} s =="
if ! cyclictest -m -p 80 -i 1000 -a "$cpu" -t 1 -l $((seconds * 1000)) -q -h 20000 \
  >"$work/hist" 2>&1; then
  echo "cyclictest failed (needs root for SCHED_FIFO):"
  cat "$work/hist"
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
  }' "$work/hist" | tee "$work/cyclictest"

demo() {
  build/host/sim/tread demo --scenario sweep --sweep-duration-s "$seconds" --rt-priority 80 --mlock \
    --cpu "$cpu" --no-plot --out "$work/demo" "$@" 2>/dev/null
}
echo
echo "== tread node, periodic: own thread on CPU $cpu, SCHED_FIFO 80, mlockall; rig on another CPU" \
  "at 70; 4 tyres + 2 wheelsets, ${seconds} s =="
demo --mode periodic | grep -E "^(cycles|overruns|wake latency|cycle time|deadline|late inputs|rig frames|scheduler|mlockall|affinity|stack|rig thread)|refused" |
  tee "$work/periodic"
echo
echo "== tread node, sync: woken by the rig's cycle frame, ${seconds} s =="
demo --mode sync | grep -E "^(cycles|cycle time|CAN-in|rig frames)|refused" | tee "$work/sync"

echo
echo "== against the goals (issue 17, part 1) =="
/usr/bin/python3 - "$work" <<'EOF'
import re, sys, pathlib
d = pathlib.Path(sys.argv[1])
def fig(text, label):
    m = re.search(label + r".*?p50 (\d+) us, p99 (\d+) us, max ([\d.]+) us", text)
    return tuple(float(x) for x in m.groups()) if m else None
cyc = fig((d / "cyclictest").read_text(), "cyclictest wake latency")
per = (d / "periodic").read_text()
syn = (d / "sync").read_text()
wake = fig(per, "wake latency")
can = fig(syn, "CAN-in -> CAN-out")
over = re.search(r"^overruns\s+(\d+)", per, re.M)
if not (cyc and wake and can and over):
    print("figures missing (see above)")
    sys.exit(0)
ratio = wake[1] / max(cyc[1], 1)
print(f"node wake p99 {wake[1]:.0f} us vs cyclictest p99 {cyc[1]:.0f} us: x{ratio:.2f} (goal <= 1.2)")
print(f"overruns {over.group(1)} (goal 0 when cyclictest's max {cyc[2]:.0f} us stays below the period of 1000 us)")
print(f"CAN-in -> CAN-out p99 {can[1]:.0f} us = cyclictest p99 + {can[1] - cyc[1]:.0f} us (goal <= + 30 us)")
EOF

echo
echo "== cycle compute time (Google Benchmark, median of 5) =="
build/host/tests/loop/node_cycle_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true 2>/dev/null |
  grep -E "median"
