#!/usr/bin/env bash
# Performance figures of issue 17 in one run (a benchmark, not pass/fail: these machines are shared
# and noisy, so every ratio is taken against tread's own scalar double path measured in the same
# run).
#   1. The Magic Formula with all outputs (forces, moments, Rl, Re, contact patch, relaxation),
#      MF 6.1 and MF 6.2 (data/tyres/MagicFormula6{1,2}_Parameters.tir, the same tyre), useMode 111,
#      1024 random operating points: ns per evaluation (per wheel for the lanes and the batch), × the
#      double path,
#      and MF 6.2 / MF 6.1 in every path (CPU-time medians of 40 repetitions, interleaved in random
#      order), and that ratio measured in pairs (BM_Ratio_*; the one the issue's ≤ 1.3 is read from).
#   2. With --timing SECONDS: scripts/bench-timing.sh SECONDS RUNS (cyclictest alone, then RUNS
#      times the node with a cyclictest beside it and a control pair; --timing-runs, default 3).
#   3. With --cli: scripts/bench-mf-eval.sh (`tread mf eval` on 1 M rows), when present.
#   4. With --issue-baseline: scripts/bench-issue-baseline.sh (four lanes and the batch against the
#      double path of the day the issue was filed, commit 75b2c3b, and through it against the
#      issue's peer; builds that commit's mf_bench once).
# A peer (e.g. MFeval exported to C++) is not part of the project; where one is measured elsewhere,
# its figure against the double path carries over through the ratio column.
# Usage: scripts/bench-perf.sh [--timing SECONDS [--timing-runs N]] [--cli] [--issue-baseline]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
timing=""
timing_runs=3
cli=0
baseline=0
while (($#)); do
  case $1 in
    --timing) timing=${2:?--timing needs SECONDS}; shift 2 ;;
    --timing-runs) timing_runs=${2:?--timing-runs needs N}; shift 2 ;;
    --cli) cli=1; shift ;;
    --issue-baseline) baseline=1; shift ;;
    *) echo "usage: $0 [--timing SECONDS [--timing-runs N]] [--cli] [--issue-baseline]" >&2; exit 2 ;;
  esac
done
cmake --preset host >/dev/null
cmake --build --preset host --target mf_bench >/dev/null

json=$(mktemp)
pairs=$(mktemp)
trap 'rm -f "$json" "$pairs"' EXIT
echo "== Magic Formula, all outputs (mf_bench, CPU medians of 40 interleaved repetitions) on $(nproc) cores of" \
  "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%F) =="
# The repetitions of the eight benchmarks run interleaved in random order, so that a burst of load
# on this shared machine falls on MF 6.1 and MF 6.2 alike instead of on whichever ran during it
# (run one after the other, the four lanes' ratio moved from 1.17 to 1.36 between two runs).
build/host/tests/mf/mf_bench --benchmark_filter='Mf6[12]_(Double|Float|FloatFour|FloatBatch)_Combined_Extras$' \
  --benchmark_repetitions=40 --benchmark_min_time=0.05 --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true --benchmark_format=json >"$json" 2>/dev/null
# MF 6.2 / MF 6.1 measured in pairs (BM_Ratio_*: a block of MF 6.1 evaluations, then the same in
# MF 6.2, the median of the pairs' ratios), the median of 3 repetitions: the issue's ratio.
build/host/tests/mf/mf_bench --benchmark_filter='Ratio_(Double|Float|FloatFour|FloatBatch)$' \
  --benchmark_repetitions=3 --benchmark_min_time=0.5 --benchmark_report_aggregates_only=true \
  --benchmark_format=json >"$pairs" 2>/dev/null
PYTHONPATH=scripts /usr/bin/python3 - "$json" "$pairs" <<'EOF'
import json, sys
from mf_bench_per_wheel import ns_per_wheel
runs = json.load(open(sys.argv[1]))["benchmarks"]
ns = {}
for r in runs:
    if r.get("aggregate_name") != "median":
        continue
    ns[r["run_name"].removeprefix("BM_")] = ns_per_wheel(r)
paired = {}
for r in json.load(open(sys.argv[2]))["benchmarks"]:
    if r.get("aggregate_name") == "median":
        paired[r["run_name"].removeprefix("BM_Ratio_")] = r["mf62_over_mf61"]
paths = [("tread double", "Double"), ("tread float", "Float"), ("tread four lanes, per wheel", "FloatFour"),
         ("tread batch (evaluate_batch: 16 lanes with AVX-512, else 8), per wheel", "FloatBatch")]
print("| path | MF 6.1 ns/eval | × double | MF 6.2 ns/eval | × double | MF 6.2 / MF 6.1 | the same, paired |")
print("|---|---|---|---|---|---|---|")
base61 = ns["Mf61_Double_Combined_Extras"]
base62 = ns["Mf62_Double_Combined_Extras"]
for label, key in paths:
    a = ns[f"Mf61_{key}_Combined_Extras"]
    b = ns[f"Mf62_{key}_Combined_Extras"]
    print(f"| {label} | {a:.0f} | {base61 / a:.2f} | {b:.0f} | {base62 / b:.2f} | {b / a:.2f} | {paired[key]:.3f} |")
EOF

if [[ -n $timing ]]; then
  echo
  bash scripts/bench-timing.sh "$timing" "$timing_runs"
fi
if ((cli)); then
  echo
  if [[ -x scripts/bench-mf-eval.sh || -f scripts/bench-mf-eval.sh ]]; then
    bash scripts/bench-mf-eval.sh
  else
    echo "(scripts/bench-mf-eval.sh not present)"
  fi
fi
if ((baseline)); then
  echo
  bash scripts/bench-issue-baseline.sh
fi
