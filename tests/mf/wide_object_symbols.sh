#!/usr/bin/env bash
# The code compiled for x86-64-v3 as a whole (src/mf/mf_evaluate_batch_v3.cpp) must define nothing
# another object could bind to but its entry point: an inline function or template instantiation it
# left out of line would be a weak definition that the linker may pick for baseline code too, which
# then runs AVX2 instructions on any CPU (an illegal instruction below x86-64-v3).
# Usage: wide_object_symbols.sh LIBRARY (the static tread_core).
set -euo pipefail
library=$1
member=mf_evaluate_batch_v3.cpp.o
# nm -A: "archive:member: address type name" for the member's defined symbols.
symbols=$(nm -A -C --defined-only "$library" | grep -F ":$member:" || true)
if [[ -z $symbols ]]; then
  echo "FAIL: $member in $library defines no symbol (not built for x86-64-v3?)" >&2
  exit 1
fi
# Global (upper-case type) or unique (u) symbols other than the entry point.
bad=$(awk '{ type = $3; $1 = $2 = $3 = ""; name = substr($0, 4) }
  type ~ /^[A-Zu]$/ && name !~ /^tread::mf::batch::evaluate_eight_v3\(/ { print "  " type " " name }' \
  <<<"$symbols")
entry=$(grep -c ' T tread::mf::batch::evaluate_eight_v3(' <<<"$symbols" || true)
echo "$member: $(wc -l <<<"$symbols") symbols defined, entry points: $entry"
if [[ -n $bad ]]; then
  echo "FAIL: $member defines symbols other objects could bind to:" >&2
  echo "$bad" >&2
  exit 1
fi
if ((entry != 1)); then
  echo "FAIL: $member does not define evaluate_eight_v3" >&2
  exit 1
fi
# Its code is AVX2 (the -march flag reached the compiler). grep -c reads to the end (grep -q would
# stop early and fail the pipeline).
ymm=$(objdump -d --no-show-raw-insn "$library" 2>/dev/null |
  awk -v m="$member" '/file format/ { inside = index($0, m) == 1 } inside' | grep -c 'ymm' || true)
echo "$member: $ymm instructions on 256-bit (ymm) registers"
if ((ymm == 0)); then
  echo "FAIL: $member has no 256-bit instructions: not compiled for x86-64-v3?" >&2
  exit 1
fi
echo "ok"
