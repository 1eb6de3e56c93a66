#!/bin/sh
# host_area_deps_selftest.sh CHECKER: the dependency check finds an undeclared include (naming file
# and line), a cycle, an area named like a core folder and a host file in a core namespace, and
# passes a tree that keeps its declarations.
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
printf '#include "low/low.hpp"\n' >"$tmp/low/low.cpp"
mkdir -p "$tmp/core/mf" "$tmp/mf"
printf 'namespace tread::mf {\n}\n' >"$tmp/core/mf/core.hpp"
printf 'namespace tread::tyre {\n}\n' >"$tmp/high/high.hpp"
/usr/bin/python3 "$checker" "$tmp" --core "$tmp/core" low: high:low ||
  { echo "a host namespace of its own failed"; status=1; }
printf 'namespace tread::mf {\n}\n' >"$tmp/high/high.hpp"
out=$(/usr/bin/python3 "$checker" "$tmp" --core "$tmp/core" low: high:low) &&
  { echo "a host file in the core's namespace passed"; status=1; }
echo "$out" | grep -q "sim/high/high.hpp:1: opens namespace tread::mf, the core's" ||
  { echo "the namespace was not named: $out"; status=1; }
printf '#pragma once\n' >"$tmp/high/high.hpp"
printf '#pragma once\n' >"$tmp/mf/mf.hpp"
printf '#include "mf/mf.hpp"\n' >"$tmp/mf/mf.cpp"
out=$(/usr/bin/python3 "$checker" "$tmp" --core "$tmp/core" low: high:low mf:) &&
  { echo "an area named like a core folder passed"; status=1; }
echo "$out" | grep -q "sim/mf: has the name of core/mf" ||
  { echo "the folder clash was not named: $out"; status=1; }
exit $status
