#!/usr/bin/env bash
# Fails if an image links any soft-float routine: the ARM EABI run-time helpers of single and
# double precision (__aeabi_f*, __aeabi_d*, int/long → float/double conversions) and libgcc's
# generic soft-fp entry points (__addsf3, __muldf3, __fixsfsi, __floatsidf, __eqsf2,
# __extendsfdf2, ...), matched as families, not as a list. Prints the offenders and, from the
# linker map next to the image when there is one, the object that pulled each one in.
# Defined and undefined symbols both count, so an object file can be checked too.
# Usage: scripts/check-no-softfloat.sh IMAGE.elf [NM]
set -euo pipefail
image=$1
nm=${2:-arm-none-eabi-nm}
pattern='^(__aeabi_[fd][a-z0-9_]*|__aeabi_u?[il]2[fd]|__aeabi_[fd]2u?[il]z?'
pattern+='|__(add|sub|mul|div|neg|pow)[sdtx]f[23]|__(fix|fixuns)[sdtx]f[sdt]i'
pattern+='|__float(un)?[sdt]i[sdtx]f|__(eq|ne|lt|le|gt|ge|un|cmp)[sdt]f2'
pattern+='|__(extend|trunc)[sdtx]f[sdtx]f2|__powi[sdt]f2)$'
symbols=$("$nm" --format=posix "$image" | awk '{print $1}')
offenders=$(grep -E "$pattern" <<<"$symbols" || true)
if [[ -z $offenders ]]; then
  echo "$image: no soft-float routine linked"
  exit 0
fi
echo "$image: soft-float routines linked:" >&2
map="${image%.elf}.map"
while read -r sym; do
  why=""
  if [[ -f $map ]]; then
    # The archive member line "lib.a(member.o)\n  file.o (symbol)" names who referenced it.
    why=$(grep -B1 -E "^ +[^ ].*\(${sym}\)$" "$map" | head -2 | tr -s ' \n' ' ' || true)
  fi
  echo "  $sym ${why:+— $why}" >&2
done <<<"$offenders"
exit 1
