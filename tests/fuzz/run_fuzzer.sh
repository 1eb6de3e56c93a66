#!/usr/bin/env bash
# Runs one libFuzzer target for SECONDS on a working copy of its seed corpus (the repository's copy
# is never written), with its dictionary, and prints one summary line:
#   fuzz NAME: SECONDS s, EXECS execs (RATE/s), cov C, ft F, corpus N (+NEW), findings K
# A finding (crash, sanitizer report, broken invariant, timeout, out-of-memory) fails the run; its
# input is left in WORKDIR/NAME/findings and copied to KEEP_DIR when that is given.
# Usage: run_fuzzer.sh BINARY NAME SECONDS WORKDIR SEED_CORPUS [DICT] [KEEP_DIR]
set -uo pipefail
bin=$1 name=$2 seconds=$3 work=$4 seeds=$5 dict=${6:-} keep=${7:-}
dir=$work/$name
rm -rf "$dir"
mkdir -p "$dir/corpus" "$dir/findings"
cp -r "$seeds"/. "$dir/corpus/" 2>/dev/null || true
rm -f "$dir/corpus/.gitkeep"
args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
  -artifact_prefix="$dir/findings/" -max_len=65536)
if [[ -n $dict ]]; then args+=(-dict="$dict"); fi
log=$dir/fuzz.log
"$bin" "${args[@]}" "$dir/corpus" >"$log" 2>&1
rc=$?
final_stat() { grep -E "^stat::$1:" "$log" | tail -1 | awk '{print $2}'; }
execs=$(final_stat number_of_executed_units)
rate=$(final_stat average_exec_per_sec)
added=$(final_stat new_units_added)
last=$(grep -E '^#[0-9]+' "$log" | tail -1)
cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
units=$(find "$dir/corpus" -type f | wc -l)
# libFuzzer also writes slow-unit-* (a unit over -report_slow_units, 10 s): on a shared VM a stall
# of the machine does that (a 4-byte CAN input "took" 12 s and replays in 0.1 s). A real hang is a
# timeout-* artifact (-timeout=10) and a nonzero exit; a slow unit alone is reported, not failed.
slow=$(find "$dir/findings" -type f -name 'slow-unit-*' | wc -l)
findings=$(find "$dir/findings" -type f ! -name 'slow-unit-*' | wc -l)
if ((slow > 0)); then echo "fuzz $name: $slow slow unit(s) kept in $dir/findings (not a failure)"; fi
echo "fuzz $name: $seconds s, ${execs:-0} execs (${rate:-0}/s), cov ${cov:-?}, ft ${ft:-?}, corpus $units (+${added:-0}), findings $findings"
if ((findings > 0)) || ((rc != 0)); then
  grep -E "ERROR|invariant|SUMMARY|runtime error" "$log" | head -20
  if [[ -n $keep ]]; then
    mkdir -p "$keep"
    cp "$dir/findings"/* "$keep/" 2>/dev/null || true
    echo "fuzz $name: findings copied to $keep"
  fi
  echo "fuzz $name: FAILED (log: $log)"
  exit 1
fi
