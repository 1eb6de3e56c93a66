#!/usr/bin/env bash
# Instructions and memory of the firmware images on their emulated boards, as a table.
# Each image replays tests/data/target/sweep_rig.log (4 MF wheels + 2 contact-table wheelsets,
# 250 cycles) under qemu-system-arm with -icount shift=0, where every instruction advances the
# emulated clock by 1 ns, and reads SysTick (25 MHz on MPS2: 1 tick = 40 instructions; the image
# measures the ratio itself with a loop of 200 000 instructions). So the counts are deterministic,
# and resolve to 1 tick: ±40 instructions for one node cycle; the per-call figures are means over
# 256 MF evaluations, 1024 contact lookups and 208 frame encodings. Instructions, not cycles: a
# Cortex-M4 at 168 MHz needs 1–3 cycles for most (more for flash wait states and divisions).
# Flash = text + data; RAM = data + bss + the stack's high-water mark (painted and measured in the
# run). Figures, not checks: nothing here fails on a budget.
# Usage: scripts/target-timing.sh [BUILD_DIR MACHINE]...
#        (default: build/cortex-m4f mps2-an386, and build/cortex-m3 mps2-an385 if built)
set -euo pipefail
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$src"
args=("$@")
if ((${#args[@]} == 0)); then
  args=(build/cortex-m4f mps2-an386)
  if [[ -f build/cortex-m3/firmware/tread_firmware.elf ]]; then args+=(build/cortex-m3 mps2-an385); fi
fi
if ((${#args[@]} % 2)); then
  echo "usage: $0 [BUILD_DIR MACHINE]..." >&2
  exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

printf '| image | board | node cycle (4 MF + 2 contact) | MF evaluation | contact lookup | encode frame | receive frame | flash | RAM (static + stack) |\n'
printf '|---|---|---|---|---|---|---|---|---|\n'
for ((i = 0; i < ${#args[@]}; i += 2)); do
  build=${args[i]} machine=${args[i + 1]}
  elf=$build/firmware/tread_firmware.elf
  if [[ ! -f $elf ]]; then
    echo "target-timing: $elf not built (cmake --workflow --preset $(basename "$build"))" >&2
    exit 1
  fi
  out=$tmp/$(basename "$build").txt
  if ! scripts/qemu-semihost.sh "$machine" "$elf" -- --replay tests/data/target/sweep_rig.log \
    --tx-log "$tmp/tx.log" --timing >"$out" 2>&1; then
    cat "$out" >&2
    echo "target-timing: $elf failed on $machine" >&2
    exit 1
  fi
  read -r text data bss < <(arm-none-eabi-size --format=berkeley "$elf" | awk 'NR == 2 {print $1, $2, $3}')
  awk -v image="$(basename "$build")" -v board="$machine" -v text="$text" -v data="$data" -v bss="$bss" '
    /^timing calibration_2x100000_instructions:/ { ipt = 200000 / $5 }
    /^timing node_cycle_full:/ { n = $3; cmin = $7; cmean = $9 / 100; cmax = $11 }
    /^timing receive_frame:/ { rmean = $9 / 100 }
    /^timing mf_evaluate:/ { mf = $5 / $3 }
    /^timing contact_lookup:/ { lut = $5 / $3 }
    /^timing encode_frame:/ { enc = $5 / $3 }
    /^memory stack_peak_bytes:/ { stack = $3 }
    END {
      ipt = int(ipt + 0.5)
      printf "| %s | %s | %d instr (min %d, max %d; %d cycles) | %.0f instr | %.0f instr | %.0f instr | %.0f instr | %.1f KiB (text %d + data %d) | %.1f KiB (%d + %d + stack %d) |\n",
        image, board, cmean * ipt, cmin * ipt, cmax * ipt, n, mf * ipt, lut * ipt, enc * ipt,
        rmean * ipt, (text + data) / 1024, text, data, (data + bss + stack) / 1024, data, bss, stack
    }' "$out"
done
echo
echo "Budgets (issue 14, informational): node cycle ≤ 15 000 instructions on the M4F (≤ 40 000"
echo "fixed-point without FPU); flash ≤ 128 KiB, RAM ≤ 16 KiB per image. 1 SysTick tick = 40"
echo "instructions under -icount shift=0 (measured per run); node-cycle figures resolve to ±40."
