#!/usr/bin/env bash
# Timing benchmark of the node (not pass/fail: these machines are shared and noisy). On the same
# machine and the same CPU:
#   1. cyclictest alone: SCHED_FIFO 80, mlockall, 1 kHz, pinned to the last CPU: the machine's own
#      wake-up latency when nothing else runs there;
#   2. the node as it runs on a rig (`tread demo`, real clock): its own thread on that CPU,
#      SCHED_FIFO 80, mlockall with a prefaulted stack and heap, no I/O on its thread; the rig and
#      its answer checker on another thread, on another CPU at SCHED_FIFO 70, over the lock-free
#      in-process link; 4 tyres + 2 wheelsets (one with wheel-rail forces), the "sweep" scenario.
#      Periodic mode: the node's wake latency, cycle time and overruns on its own deadlines;
#   3. the same in sync mode: the node sleeps until the rig's cycle frame and answers it;
#      CAN-in -> CAN-out latency (the rig's cycle frame to the node's last answer frame);
#   4. the cycle's compute time from Google Benchmark.
# During 2 and 3 a second cyclictest runs on the node's CPU at the same time (started a second
# before the node's run and stopped after it ends), one priority above the node, at 1 kHz half a
# period away from the node's deadlines: the demo puts those at whole milliseconds of
# CLOCK_MONOTONIC + 250 us, cyclictest wakes at whole seconds + 750 us + k ms (--secaligned 750).
# Neither delays the other, and neither shares the kernel's tick (on whole milliseconds; HZ 250:
# every 4 ms). This is the machine's latency in the seconds the node ran: a VM's stalls come and
# go, and a yardstick measured in other seconds (1) can miss the stall the node met, or meet one
# the node did not.
# The goals of issue 17 (node wake p99 <= 1.2 x cyclictest p99; no overrun when cyclictest stays
# below the period; CAN-in -> CAN-out p99 <= cyclictest p99 + 30 us) are judged against the
# concurrent cyclictest.
#   5. The yardstick's own spread (control): two cyclictests in the same seconds, one at the
#      node's phase and priority (80, a quarter period), one where the cyclictest beside the node
#      runs (81, three quarters). On a VM the p99 of one 1 kHz run swings with the host's noise:
#      two such identical yardsticks differed by x0.5 to x2.2 in 20 s runs on this kind of machine.
#      A node's ratio from one run is read against that spread; 2, 3 and 5 are repeated RUNS times
#      in turn, and the summary gives medians.
# Usage: scripts/bench-timing.sh [SECONDS] [RUNS]   (default 10 s each, 3 runs)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-10}
runs=${2:-3}
if ! [[ $seconds =~ ^[1-9][0-9]*$ && $runs =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 [SECONDS] [RUNS] (whole numbers >= 1)" >&2
  exit 2
fi
cpu=$(($(nproc) - 1))
cmake --preset host >/dev/null
cmake --build --preset host --target tread node_cycle_bench >/dev/null

work=$(mktemp -d)
beside_pid=""
control_pid=""
# A cyclictest left beside the node (a failed demo, an interrupted run) would run on at SCHED_FIFO.
trap '[[ -z $beside_pid ]] || kill -INT "$beside_pid" 2>/dev/null || true
[[ -z $control_pid ]] || kill -INT "$control_pid" 2>/dev/null || true
rm -rf "$work"' EXIT
# cyclictest's histogram (-h) -> "p50 .. us, p99 .. us, max .. us (n samples)".
summarize() {
  awk -v label="$2" '
  /^[0-9]+ +[0-9]+/ { us = $1 + 0; n = $2 + 0; count[us] = n; total += n; if (us > maxus && n > 0) maxus = us }
  /# Max Latencies/ { max = $4 + 0 }
  END {
    if (total == 0) { print label " no histogram"; exit }
    split("0.5 0.99", qs, " ")
    for (k = 1; k <= 2; k++) {
      target = qs[k] * total; seen = 0
      for (us = 0; us <= maxus; us++) { seen += count[us]; if (seen >= target) { p[k] = us; break } }
    }
    printf "%s  p50 %d us, p99 %d us, max %d us  (%d samples)\n", label, p[1], p[2], max, total
  }' "$1"
}
echo "== cyclictest alone: SCHED_FIFO 80, mlockall, 1 kHz, CPU $cpu, ${seconds} s =="
if ! cyclictest -m -p 80 -i 1000 -a "$cpu" -t 1 -l $((seconds * 1000)) -q -h 20000 \
  >"$work/hist" 2>&1; then
  echo "cyclictest failed (needs root for SCHED_FIFO):"
  cat "$work/hist"
fi
summarize "$work/hist" "cyclictest wake latency" | tee "$work/cyclictest"

# cyclictest beside the node: same CPU, priority 81, 1 kHz half a period after the node's
# deadlines, until stopped (SIGINT: it prints its histogram and exits). Its first wake-up is at the
# next whole second but one at most.
beside_start() {
  cyclictest -m -p 81 -i 1000 --secaligned 750 -a "$cpu" -t 1 -q -h 20000 >"$work/beside_$1" 2>&1 &
  beside_pid=$!
  sleep 1
}
beside_stop() {
  kill -INT "$beside_pid" 2>/dev/null || true
  wait "$beside_pid" 2>/dev/null || true
  beside_pid=""
  summarize "$work/beside_$1" "cyclictest beside the node" | tee "$work/cyclictest_$1"
}

demo() {
  build/host/sim/tread demo --scenario sweep --sweep-duration-s "$seconds" --rt-priority 80 --mlock \
    --cpu "$cpu" --no-plot --out "$work/demo" "$@" 2>/dev/null
}
for ((r = 1; r <= runs; r++)); do
  echo
  echo "== run $r of $runs: tread node, periodic: own thread on CPU $cpu, SCHED_FIFO 80, mlockall;" \
    "rig on another CPU at 70; 4 tyres + 2 wheelsets, ${seconds} s =="
  beside_start "periodic_$r"
  demo --mode periodic | grep -E "^(cycles|overruns|wake latency|cycle time|deadline|late inputs|rig frames|scheduler|mlockall|affinity|stack|rig thread)|refused" |
    tee "$work/periodic_$r" || echo "run $r: the periodic demo failed or printed nothing"
  beside_stop "periodic_$r"
  echo
  echo "== run $r of $runs: tread node, sync: woken by the rig's cycle frame, ${seconds} s =="
  beside_start "sync_$r"
  demo --mode sync | grep -E "^(cycles|cycle time|CAN-in|rig frames)|refused" | tee "$work/sync_$r" ||
    echo "run $r: the sync demo failed or printed nothing"
  beside_stop "sync_$r"
  echo
  echo "== run $r of $runs: control, two cyclictests in the same seconds: at the node's phase and" \
    "priority (80), and at the phase of the one beside it (81), ${seconds} s =="
  cyclictest -m -p 81 -i 1000 --secaligned 750 -a "$cpu" -t 1 -l $((seconds * 1000)) -q -h 20000 \
    >"$work/control_beside_$r" 2>&1 &
  control_pid=$!
  cyclictest -m -p 80 -i 1000 --secaligned 250 -a "$cpu" -t 1 -l $((seconds * 1000)) -q -h 20000 \
    >"$work/control_node_$r" 2>&1 || true
  wait "$control_pid" || true
  control_pid=""
  summarize "$work/control_node_$r" "cyclictest at the node's phase" | tee "$work/control_node_sum_$r"
  summarize "$work/control_beside_$r" "cyclictest at the other phase" | tee "$work/control_beside_sum_$r"
done

echo
echo "== against the goals (issue 17, part 1) =="
/usr/bin/python3 - "$work" "$runs" <<'EOF'
import re, statistics, sys, pathlib
d = pathlib.Path(sys.argv[1])
runs = int(sys.argv[2])
def fig(path, label):
    p = d / path
    if not p.exists():
        return None
    m = re.search(label + r".*?p50 (\d+) us, p99 (\d+) us, max ([\d.]+) us", p.read_text())
    return tuple(float(x) for x in m.groups()) if m else None
alone = fig("cyclictest", "cyclictest wake latency")
if alone:
    print(f"cyclictest alone p99 {alone[1]:.0f} us, max {alone[2]:.0f} us")
wake_ratios, control_ratios = [], []
for r in range(1, runs + 1):
    cyc = fig(f"cyclictest_periodic_{r}", "cyclictest beside the node")
    cyc_sync = fig(f"cyclictest_sync_{r}", "cyclictest beside the node")
    wake = fig(f"periodic_{r}", "wake latency")
    can = fig(f"sync_{r}", "CAN-in -> CAN-out")
    c_node = fig(f"control_node_sum_{r}", "cyclictest at the node's phase")
    c_other = fig(f"control_beside_sum_{r}", "cyclictest at the other phase")
    control = None
    if c_node and c_other:
        control = c_node[1] / max(c_other[1], 1)
        control_ratios.append(control)
    periodic = d / f"periodic_{r}"
    over = re.search(r"^overruns\s+(\d+)", periodic.read_text(), re.M) if periodic.exists() else None
    if not (cyc and cyc_sync and wake and can and over):
        print(f"run {r}: figures missing (see above)")
        continue
    ratio = wake[1] / max(cyc[1], 1)
    wake_ratios.append(ratio)
    applies = "the goal of 0 applies" if cyc[2] < 1000 else "above the period: the goal does not apply"
    print(f"run {r}: node wake p99 {wake[1]:.0f} us vs cyclictest beside {cyc[1]:.0f} us: x{ratio:.2f}; "
          f"overruns {over.group(1)} (cyclictest beside max {cyc[2]:.0f} us, {applies}); "
          f"CAN-in -> CAN-out p99 {can[1]:.0f} us = cyclictest beside {cyc_sync[1]:.0f} us "
          f"{can[1] - cyc_sync[1]:+.0f} us (goal <= +30)", end="")
    if control is not None:
        print(f"; control p99 {c_node[1]:.0f} vs {c_other[1]:.0f} us: x{control:.2f}")
    else:
        print("; control: figures missing")
if wake_ratios:
    print(f"node wake p99 / cyclictest beside p99: median x{statistics.median(wake_ratios):.2f} over "
          f"{len(wake_ratios)} runs (x{min(wake_ratios):.2f} to x{max(wake_ratios):.2f}; goal <= 1.2)")
if control_ratios:
    print(f"control, two identical cyclictests at those phases: median x{statistics.median(control_ratios):.2f} "
          f"(x{min(control_ratios):.2f} to x{max(control_ratios):.2f}): the yardstick's own spread")
EOF

echo
echo "== cycle compute time (Google Benchmark, median of 5) =="
build/host/tests/loop/node_cycle_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true 2>/dev/null |
  grep -E "median"
