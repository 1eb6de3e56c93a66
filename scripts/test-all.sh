#!/usr/bin/env bash
# Every test, from a fresh clone: installs the Debian packages, then builds and tests every preset —
# host (unit, golden, vcan through the VM harness), asan, fuzz (every libFuzzer target for 30 s on
# its corpus, clang + ASan/UBSan), aarch64 and armhf (under qemu-user),
# cortex-m4f and cortex-m3 (the firmware images, run under qemu-system-arm) — runs the main job
# (scripts/demo.sh) and checks formatting. Exits non-zero if anything fails.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh || { echo "test-all: dependency installation failed" >&2; exit 1; }

failed_steps=()
total_passed=0
total_failed=0
log_dir=build/logs
mkdir -p "$log_dir"

run_workflow() {
  local preset=$1 log="$log_dir/$1.log" began
  began=$(date +%s)
  echo "=== workflow: $preset ==="
  cmake --workflow --preset "$preset" 2>&1 | tee "$log" | grep -E --line-buffered \
    '(tests passed|Test +#|FAILED|Error|error:|image size|text\s+data|tread_firmware\.elf)' | grep -v 'Passed'
  local rc=${PIPESTATUS[0]}
  local summary failed=0
  summary=$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1)
  if [[ -n $summary ]]; then
    local total
    failed=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$summary")
    total=$(sed -E 's/.* failed out of ([0-9]+).*/\1/' <<<"$summary")
    total_failed=$((total_failed + failed))
    total_passed=$((total_passed + total - failed))
  fi
  if [[ $rc != 0 ]]; then
    failed_steps+=("$preset")
    # A step that failed before or besides its tests (configure, build, a cross link) counts once.
    if [[ -z $summary || $failed == 0 ]]; then total_failed=$((total_failed + 1)); fi
  fi
  echo "    ($preset: $(($(date +%s) - began)) s)"
}

start=$(date +%s)
for preset in host asan fuzz aarch64 armhf cortex-m4f cortex-m3; do
  run_workflow "$preset"
done

echo "=== main job: bash scripts/demo.sh (simulated clock) ==="
# demo_step NAME OUT "PATTERN" "PLOTS" [tread demo arguments]: runs scripts/demo.sh on the simulated
# clock into OUT, requires every plot of PLOTS (names in OUT), prints the summary lines matching
# PATTERN; counts a pass or a failure.
demo_step() {
  local name=$1 out=$2 pattern=$3 plots=$4 ok=1 plot
  shift 4
  bash scripts/demo.sh --clock sim --out "$out" "$@" >"$log_dir/$name.log" 2>&1 || ok=0
  for plot in $plots; do
    [[ -s $out/$plot ]] || ok=0
  done
  if ((ok)); then
    grep -E "$pattern" "$log_dir/$name.log"
    total_passed=$((total_passed + 1))
  else
    tail -20 "$log_dir/$name.log"
    failed_steps+=("$name")
    total_failed=$((total_failed + 1))
  fi
}
# The README's first command, as a new user runs it (here on the simulated clock: the same scenarios
# and results; the real clock only adds timing figures). It must finish and draw every plot.
demo_step demo build/demo-check \
  "mean_deceleration|ay_steady|wavelength vs Klingel|critical_speed|low_speed_wavelength" \
  "braking.png hunting.png dynamic-hunting.png"
# The curving scenario (on request): outer wheel Y/Q against Nadal.
demo_step demo-curving build/demo-curving "outer_y_over_q|min_nadal_margin|equilibrium" \
  "curving.png" --scenario curving

echo "=== installed package: bash scripts/check-install.sh (host, cortex-m4f) ==="
# cmake --install of the host and Cortex-M4F builds, and examples/consumer built against each
# (find_package(tread)); the host consumer runs.
if bash scripts/check-install.sh host cortex-m4f >"$log_dir/check-install.log" 2>&1; then
  grep -E "^(headers|bare-metal image|consumer|check-install):" "$log_dir/check-install.log"
  total_passed=$((total_passed + 1))
else
  tail -20 "$log_dir/check-install.log"
  failed_steps+=("check-install")
  total_failed=$((total_failed + 1))
fi

echo "=== format check ==="
if cmake --build --preset host --target format-check; then
  total_passed=$((total_passed + 1))
else
  failed_steps+=("format-check")
  total_failed=$((total_failed + 1))
fi

echo "=== summary ($(($(date +%s) - start)) s) ==="
echo "test-all: $total_passed passed, $total_failed failed" >"$log_dir/summary.txt"
if ((${#failed_steps[@]})); then
  echo "test-all: FAILED steps: ${failed_steps[*]} (logs in $log_dir)"
  cat "$log_dir/summary.txt"
  exit 1
fi
cat "$log_dir/summary.txt"
