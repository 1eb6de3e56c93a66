#!/usr/bin/env bash
# Shows the Cortex-M no-heap trap works: the firmware links without TREAD_HEAP_PROBE and fails to link,
# naming the wrapped allocator symbol, when the core contains a deliberate operator new.
# Usage: scripts/check-no-heap-trap.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$src/build/heap-trap}
rm -rf "$build"
cmake -S "$src" -B "$build" -G Ninja --preset cortex-m4f -DTREAD_HEAP_PROBE=ON >"$build.configure.log" 2>&1 || {
  cat "$build.configure.log"
  exit 1
}
if cmake --build "$build" >"$build.log" 2>&1; then
  echo "check-no-heap-trap: FAIL — the firmware linked although the core calls operator new" >&2
  exit 1
fi
if ! grep -E "undefined reference to \`__wrap_(_Znw|malloc)" "$build.log"; then
  echo "check-no-heap-trap: FAIL — the build failed, but not at the no-heap trap:" >&2
  tail -n 30 "$build.log" >&2
  exit 1
fi
echo "check-no-heap-trap: OK — the link refused the heap allocation"
