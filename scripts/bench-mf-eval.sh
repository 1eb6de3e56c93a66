#!/usr/bin/env bash
# Throughput benchmark of `tread mf eval` (not pass/fail: these machines are shared and noisy).
# Makes a CSV of ROWS deterministic random operating points inside the ranges of
# data/tyres/MagicFormula61_Parameters.tir (FZMIN…FZMAX, KPUMIN…KPUMAX, ALPMIN…ALPMAX,
# CAMMIN…CAMMAX, PRESMIN…PRESMAX, Vx from VXLOW to 3 × LONGVL; 6 significant digits, as a rig
# writes), then runs `tread mf eval` RUNS times with all columns and RUNS times with
# `--columns Fx_N,Fy_N,Mz_Nm`, and prints the median wall time and rows/s of each, the median CPU
# time per row (user + system, all threads) and the peak RSS. Then the same with twice the rows,
# once each, to show that memory does not grow with the row count.
# Usage: scripts/bench-mf-eval.sh [ROWS] [RUNS] [ARGS...]   (default 1000000 rows, 5 runs; ARGS
#        are passed to every run, e.g. --float or --batch)
#        TREAD=path/to/tread scripts/bench-mf-eval.sh   (another build, e.g. an older one)
set -euo pipefail
# Debian's python3 (python3-numpy from scripts/install-deps.sh), whatever python3 is first on PATH.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
rows=${1:-1000000}
runs=${2:-5}
shift $(($# < 2 ? $# : 2))
extra=("$@")
tir=data/tyres/MagicFormula61_Parameters.tir
if [[ -z ${TREAD:-} ]]; then
  cmake --preset host >/dev/null
  cmake --build --preset host --target tread >/dev/null
  TREAD=build/host/sim/tread
fi
dir=build/bench-mf-eval
mkdir -p "$dir"

# make_input ROWS FILE: the operating points (numpy, seed 2026).
make_input() {
  /usr/bin/python3 - "$tir" "$1" "$2" <<'EOF'
import re, sys
import numpy as np
tir, rows, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
keys = {}
for line in open(tir):
    m = re.match(r"\s*([A-Z_0-9]+)\s*=\s*([-+0-9.eEdD]+)", line)
    if m:
        keys.setdefault(m.group(1), float(m.group(2).replace("d", "e").replace("D", "e")))
rng = np.random.default_rng(2026)
cols = [
    ("Fz_N", rng.uniform(keys["FZMIN"], keys["FZMAX"], rows)),
    ("kappa", rng.uniform(keys["KPUMIN"], keys["KPUMAX"], rows)),
    ("alpha_rad", rng.uniform(keys["ALPMIN"], keys["ALPMAX"], rows)),
    ("gamma_rad", rng.uniform(keys["CAMMIN"], keys["CAMMAX"], rows)),
    ("Vx_mps", rng.uniform(keys["VXLOW"], 3 * keys["LONGVL"], rows)),
    ("P_Pa", rng.uniform(keys["PRESMIN"], keys["PRESMAX"], rows)),
]
with open(path, "w") as f:
    f.write(",".join(name for name, _ in cols) + "\n")
    np.savetxt(f, np.column_stack([v for _, v in cols]), fmt="%.6g", delimiter=",")
EOF
}

# run_once INPUT [ARGS...]: prints "wall_s peak_rss_kib cpu_s" of one `tread mf eval` (cpu: user +
# system, all threads: the part of the figure that another load on the machine does not change).
run_once() {
  local input=$1
  shift
  local stats=$dir/time.txt
  rm -f "$dir/out.csv"  # not the previous run's file to unlink at the rename
  if [[ -x /usr/bin/time ]]; then
    /usr/bin/time -f "%e %M %U %S" -o "$stats" "$TREAD" mf eval --tir "$tir" --input "$input" \
      --output "$dir/out.csv" "$@" 2>/dev/null
    awk '{ print $1, $2, $3 + $4 }' "$stats"
  else
    /usr/bin/python3 - "$TREAD" "$tir" "$input" "$dir/out.csv" "$@" <<'EOF'
import resource, subprocess, sys, time
tread, tir, inp, out, *extra = sys.argv[1:]
t0 = time.monotonic()
subprocess.run([tread, "mf", "eval", "--tir", tir, "--input", inp, "--output", out, *extra],
               check=True, stderr=subprocess.DEVNULL)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{time.monotonic() - t0:.2f} {usage.ru_maxrss} {usage.ru_utime + usage.ru_stime:.2f}")
EOF
  fi
}

# bench LABEL ROWS RUNS INPUT [ARGS...]: median wall time, rows/s and the largest peak RSS.
bench() {
  local label=$1 n=$2 k=$3 input=$4
  shift 4
  local results=()
  for ((i = 0; i < k; i++)); do results+=("$(run_once "$input" "$@")"); done
  printf '%s\n' "${results[@]}" | /usr/bin/python3 -c '
import statistics, sys
label, n = sys.argv[1], int(sys.argv[2])
runs = [tuple(map(float, line.split())) for line in sys.stdin if line.strip()]
t = statistics.median(r[0] for r in runs)
cpu = statistics.median(r[2] for r in runs)
rss = max(r[1] for r in runs) / 1024
times = " ".join(f"{r[0]:.2f}" for r in runs)
print(f"{label:<28} {n:>8} rows  median {t:5.2f} s {n / t:>10,.0f} rows/s  "
      f"CPU {cpu / n * 1e6:4.2f} us/row  peak RSS {rss:5.1f} MiB  (runs: {times} s)")
' "$label" "$n"
  rm -f "$dir/out.csv"
}

echo "== tread mf eval ${extra[*]}: $("$TREAD" --version 2>/dev/null | head -1), $(nproc) cores, $tir =="
input=$dir/in_${rows}.csv
[[ -f $input ]] || make_input "$rows" "$input"
bench "all columns" "$rows" "$runs" "$input" --columns all "${extra[@]}"
bench "--columns Fx_N,Fy_N,Mz_Nm" "$rows" "$runs" "$input" --columns Fx_N,Fy_N,Mz_Nm "${extra[@]}"
bench "default columns" "$rows" 1 "$input" "${extra[@]}"

echo "== memory with twice the rows =="
input2=$dir/in_$((2 * rows)).csv
[[ -f $input2 ]] || make_input $((2 * rows)) "$input2"
bench "all columns" $((2 * rows)) 1 "$input2" --columns all "${extra[@]}"
bench "--columns Fx_N,Fy_N,Mz_Nm" $((2 * rows)) 1 "$input2" --columns Fx_N,Fy_N,Mz_Nm "${extra[@]}"
