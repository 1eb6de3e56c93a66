#!/usr/bin/env bash
# The wide-lane code (evaluate_four's AVX2 clone and its AVX-512 evaluate_four_v4, the batch's
# evaluate_eight_v3 and evaluate_sixteen_v4)
# must call nothing of tread's own out of line but redo_lanes: any other function is compiled for
# the baseline target, and a wide clone calling it passes its 8- or 16-lane vectors by the
# baseline's ABI (GCC's -Wpsabi note): slow at best (an out-of-line atan_lanes made the 8-lane batch
# a third slower), a crash where the two disagree (kya_load_arg, 62838d2). GCC's flatten does not
# always inline everything (its IPA clones, its limits), so this checks the linked binary.
# Usage: wide_clone_calls.sh BINARY. Allowed: library calls through the PLT (libm, libc) and
# redo_lanes (pointers and ints only).
set -euo pipefail
binary=$1
listing=$(objdump -d --no-show-raw-insn -C "$binary")
report=$(awk '
  /^[0-9a-f]+ <.*>:$/ {
    wide = ($0 ~ /\[clone \.arch_x86_64_v[34]\]/ || $0 ~ /evaluate_sixteen_v4|evaluate_eight_v3|evaluate_four_v4/) && $0 ~ /tread::mf::/
    if (wide) { clones++; name = $0 }
    next
  }
  wide && /\tcall / {
    target = $0; sub(/.*\tcall +[0-9a-f]+ /, "", target)
    if (target ~ /@plt>$/ || target ~ /redo_lanes</) next
    bad++
    if (!((name, target) in seen)) { seen[name, target] = 1; print "  " name "\n    calls " target }
  }
  END { printf "wide functions: %d, disallowed calls: %d\n", clones, bad }
' <<<"$listing")
echo "$report"
summary=$(tail -n 1 <<<"$report")
clones=$(sed -E 's/wide functions: ([0-9]+),.*/\1/' <<<"$summary")
bad=$(sed -E 's/.*disallowed calls: ([0-9]+)/\1/' <<<"$summary")
if ((clones < 4)); then
  echo "FAIL: expected evaluate_four's AVX2 clone, evaluate_four_v4, evaluate_eight_v3 and" \
    "evaluate_sixteen_v4" >&2
  exit 1
fi
# Each of the four wide functions by name (the count alone would not notice one missing: GCC's
# .cold parts are counted too).
for expected in \
  'tread::mf::\(anonymous namespace\)::evaluate_four_cloned\(.*\[clone \.arch_x86_64_v3\]' \
  'tread::mf::four::evaluate_four_v4\(' 'tread::mf::batch::evaluate_eight_v3\(' \
  'tread::mf::batch::evaluate_sixteen_v4\('; do
  if ! grep -qE "^[0-9a-f]+ <$expected" <<<"$listing"; then
    echo "FAIL: no wide function matching '$expected' in $binary" >&2
    exit 1
  fi
done
if ((bad > 0)); then
  echo "FAIL: a wide clone calls an out-of-line function of tread's own (see above)" >&2
  exit 1
fi
echo "ok"
