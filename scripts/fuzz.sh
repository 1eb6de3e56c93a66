#!/usr/bin/env bash
# Coverage-guided fuzzing of every input parser (tests/fuzz): builds the `fuzz` preset (clang,
# libFuzzer, AddressSanitizer + UBSan) and runs each target for SECONDS (default 600) on a working
# copy of its seed corpus, two at a time (one per core), then prints a table:
#   | target | seconds | executions | exec/s | coverage (edges) | features | corpus (new) | findings |
# Findings (their inputs) are copied into tests/fuzz/regressions/<target>/, which the unit tests
# replay in every build: commit them with the fix. A benchmark run, not a CI step (CI runs each
# target for 30 s: ctest --preset fuzz).
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-600}
shift || true
targets=("$@")
if ((${#targets[@]} == 0)); then
  targets=(tir measurement profile candump_replay can_frames cli_values)
fi
cmake --preset fuzz >/dev/null && cmake --build --preset fuzz || exit 1
work=build/fuzz/fuzz-run
mkdir -p "$work"
declare -A dicts=([tir]=tir [measurement]=measurement [profile]=profile [candump_replay]=candump
  [can_frames]="" [cli_values]=cli_values)
run_one() {
  local t=$1 dict=""
  if [[ -n ${dicts[$t]:-} ]]; then dict=tests/fuzz/dict/${dicts[$t]}.dict; fi
  ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1 \
    UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    tests/fuzz/run_fuzzer.sh "build/fuzz/tests/fuzz/fuzz_$t" "$t" "$seconds" "$work" \
    "tests/fuzz/corpus/$t" "$dict" "tests/fuzz/regressions/$t" >"$work/$t.summary" 2>&1
}
running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if ((running >= 2)); then
    wait -n
    running=$((running - 1))
  fi
done
wait
status=0
echo "| target | seconds | executions | exec/s | coverage (edges) | features | corpus (new) | findings |"
echo "|---|---|---|---|---|---|---|---|"
for t in "${targets[@]}"; do
  line=$(grep -E "^fuzz $t:" "$work/$t.summary" | head -1)
  if [[ -z $line ]]; then
    echo "| $t | failed to run: see $work/$t.summary | | | | | | |"
    status=1
    continue
  fi
  # fuzz NAME: S s, E execs (R/s), cov C, ft F, corpus N (+A), findings K
  sed -E 's/^fuzz ([^:]+): ([0-9]+) s, ([0-9]+) execs \(([0-9]+)\/s\), cov ([0-9?]+), ft ([0-9?]+), corpus ([0-9]+) \(\+([0-9]+)\), findings ([0-9]+)$/| \1 | \2 | \3 | \4 | \5 | \6 | \7 (+\8) | \9 |/' <<<"$line"
  if grep -q FAILED "$work/$t.summary"; then status=1; fi
done
exit "$status"
