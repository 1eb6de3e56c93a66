#!/usr/bin/env bash
# The image's check must fail when the expected frames differ by more than it allows (one
# quantisation step for the float image, none for the fixed-point one): a copy of the host's TX log
# with the first wheel frame's Fx (bytes 2-3 of 0x180) STEPS raw steps off (default 2).
# Usage: expect_mismatch.sh MACHINE IMAGE RIG_LOG HOST_TX_LOG OUTDIR [STEPS]
set -euo pipefail
machine=$1 image=$2 rig=$3 host_tx=$4 out=$5 steps=${6:-2}
mkdir -p "$out"
done=0
while IFS= read -r line; do
  if ((!done)) && [[ $line == *" 180#"* ]]; then
    data=${line##*#}
    byte=$(printf '%02X' $(((16#${data:4:2} + steps) % 256)))
    line="${line%#*}#${data:0:4}${byte}${data:6}"
    done=1
  fi
  printf '%s\n' "$line"
done <"$host_tx" >"$out/tampered_tx.log"
status=0
"$(dirname "${BASH_SOURCE[0]}")/../../scripts/qemu-semihost.sh" "$machine" "$image" -- \
  --replay "$rig" --tx-log "$out/tx.log" --expect "$out/tampered_tx.log" 2>"$out/console.txt" ||
  status=$?
cat "$out/console.txt"
if [[ $status != 1 ]]; then
  echo "expect_mismatch: the image exited with $status, not 1 (mismatch)" >&2
  exit 1
fi
grep -q "check FAILED: expected log line [0-9]*: signal Fx differs by" "$out/console.txt"
echo "expect_mismatch: OK — the image caught the difference"
