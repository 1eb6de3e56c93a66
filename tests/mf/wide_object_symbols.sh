#!/usr/bin/env bash
# The code compiled for x86-64-v3 or x86-64-v4 as a whole (src/mf/mf_evaluate_batch_v3.cpp,
# src/mf/mf_evaluate_batch_v4.cpp, src/mf/mf_evaluate_four_v4.cpp) must define nothing another
# object could bind to but its entry point: an inline function or template instantiation it left
# out of line would be a weak (or global, or unique) definition that the linker may pick for
# baseline code too, which then runs AVX2 or AVX-512 instructions on any CPU (an illegal
# instruction below that level). Nor may it run code at load time (.init_array, .ctors), on any CPU.
# Usage: wide_object_symbols.sh LIBRARY (the static tread_core).
set -euo pipefail
library=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0

# check MEMBER ENTRY_PREFIX ENTRY_NAME PATTERN: one object of the library; PATTERN is what only
# its level's instructions have (the widest registers, or an AVX-512 instruction).
check() {
  local member=$1 entry_prefix=$2 entry_name=$3 pattern=$4
  if ! (cd "$work" && ar x "$library" "$member" 2>/dev/null) || [[ ! -s $work/$member ]]; then
    echo "FAIL: no $member in $library" >&2
    status=1
    return
  fi
  local object=$work/$member symbols bad entries count
  # readelf -sW: Num: Value Size Type Bind Vis Ndx Name. A definition (Ndx not UND) whose binding
  # is not LOCAL (GLOBAL, WEAK, GNU_UNIQUE) other than the entry point.
  symbols=$(readelf -sW "$object")
  bad=$(awk -v entry="$entry_prefix" '$1 ~ /^[0-9]+:$/ && $7 != "UND" && $5 != "LOCAL" &&
    index($8, entry) != 1 { print "  " $5 " " $4 " " $8 }' <<<"$symbols")
  entries=$(awk -v entry="$entry_prefix" '$1 ~ /^[0-9]+:$/ && $7 != "UND" && $5 == "GLOBAL" &&
    index($8, entry) == 1' <<<"$symbols" | wc -l)
  echo "$member: $(grep -c '^ *[0-9]*:' <<<"$symbols") symbols, entry points: $entries"
  if [[ -n $bad ]]; then
    echo "FAIL: $member defines symbols other objects could bind to:" >&2
    c++filt <<<"$bad" >&2
    status=1
  fi
  if ((entries != 1)); then
    echo "FAIL: $member does not define $entry_name (once)" >&2
    status=1
  fi
  if readelf -SW "$object" | grep -qE '\.(init_array|ctors|preinit_array)\b'; then
    echo "FAIL: $member has load-time initialisers (.init_array / .ctors)" >&2
    status=1
  fi
  # Its code has the level's instructions (the -march flag reached the compiler). grep -c reads to
  # the end (grep -q would stop early and fail the pipeline).
  count=$(objdump -d --no-show-raw-insn "$object" | grep -c "$pattern" || true)
  echo "$member: $count instructions matching $pattern"
  if ((count == 0)); then
    echo "FAIL: $member has no instructions matching $pattern: not compiled for its level?" >&2
    status=1
  fi
}

# tread::mf::batch::evaluate_eight_v3(...), tread::mf::batch::evaluate_sixteen_v4(...) and
# tread::mf::four::evaluate_four_v4(...) (four lanes: xmm and ymm registers, its selects AVX-512's
# vpternlogd).
check mf_evaluate_batch_v3.cpp.o _ZN5tread2mf5batch17evaluate_eight_v3E evaluate_eight_v3 ymm
check mf_evaluate_batch_v4.cpp.o _ZN5tread2mf5batch19evaluate_sixteen_v4E evaluate_sixteen_v4 zmm
check mf_evaluate_four_v4.cpp.o _ZN5tread2mf4four16evaluate_four_v4E evaluate_four_v4 vpternlogd
((status == 0)) && echo "ok"
exit "$status"
