#!/bin/sh
# host_area_deps_selftest.sh CHECKER: the dependency check finds an undeclared include (naming file
# and line) and a cycle, and passes a tree that keeps its declarations.
checker=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/low" "$tmp/high"
printf '#pragma once\n' >"$tmp/low/low.hpp"
printf '#include "low/low.hpp"\n' >"$tmp/low/low.cpp"
printf '#pragma once\n' >"$tmp/high/high.hpp"
printf '#include "high/high.hpp"\n#include "mf/mf_evaluate.hpp"\n' >"$tmp/high/high.cpp"
status=0
/usr/bin/python3 "$checker" "$tmp" low: high:low || { echo "a clean tree failed"; status=1; }
printf '#include "high/high.hpp"\n' >>"$tmp/low/low.cpp"
out=$(/usr/bin/python3 "$checker" "$tmp" low: high:low) && { echo "an upward include passed"; status=1; }
echo "$out" | grep -q "sim/low/low.cpp:2: includes high/high.hpp, but low does not depend on high" ||
  { echo "no file:line for the upward include: $out"; status=1; }
out=$(/usr/bin/python3 "$checker" "$tmp" low:high high:low) && { echo "a cycle passed"; status=1; }
echo "$out" | grep -q "cycle between areas" || { echo "the cycle was not named: $out"; status=1; }
exit $status
