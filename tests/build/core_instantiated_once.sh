#!/bin/sh
# core_instantiated_once.sh CORE_ARCHIVE HOST_ARCHIVE...: the core's function templates are compiled
# once for float and double, in the core library with the core's flags (explicit instantiations,
# declared `extern template` in their headers). An instantiation of namespace tread:: that the host
# library defines too (an implicit one, compiled with the host's flags) would let the link order
# choose which of the two a program runs. Counted: function template instantiations (`f<T>(...)`).
# Not counted: plain inline functions, which an unoptimised build emits out of line in every
# library (the same source, no template argument to differ in).
core=$1
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
defined() {
  nm -C --defined-only "$@" 2>/dev/null | awk '$2 ~ /^[TtWw]$/ { $1 = ""; $2 = ""; sub(/^  /, ""); print }' |
    grep '^tread::' | sort -u
}
defined "$core" >"$tmp/core"
defined "$@" >"$tmp/host"
comm -12 "$tmp/core" "$tmp/host" | grep -E '::[a-z_0-9]+<[^()]*>\(' >"$tmp/both"
n=$(wc -l <"$tmp/both")
echo "core functions: $(wc -l <"$tmp/core"); host functions: $(wc -l <"$tmp/host"); in both: $n"
if [ "$n" -ne 0 ]; then
  echo "defined in the host library as well as in the core:"
  cat "$tmp/both"
  exit 1
fi
