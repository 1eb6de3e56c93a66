#!/usr/bin/env bash
# The installed package as an ECU team uses it: for each preset (default: host cortex-m4f) runs
# `cmake --install` of its build to build/install/<preset>, checks that every header there finds
# the headers it includes, and builds examples/consumer against that prefix alone (find_package
# (tread)), cross builds with the toolchain and CPU files the package installed. A host consumer
# must run and print "consumer: sane" (a Linux cross one too, under the build's emulator); a
# bare-metal one must link an Arm ELF image.
#
#   scripts/check-install.sh [--no-build] [--out DIR] [PRESET | BUILD_DIR]...
#
# A preset's build directory (build/<preset>) is configured if it is not yet, and the package's
# targets (tread_package) are built unless --no-build. A BUILD_DIR argument is used as it is (the
# host preset's CTest test passes its own). --out: where install/<name> and consumer/<name> go
# (default build). Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source_dir=$PWD

build_package=1
out=build
targets=()
while (($#)); do
  case $1 in
    --no-build) build_package=0 ;;
    --out) out=$2; shift ;;
    -h | --help) sed -n '2,13p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) targets+=("$1") ;;
  esac
  shift
done
((${#targets[@]})) || targets=(host cortex-m4f)
mkdir -p "$out"
out=$(cd "$out" && pwd)
jobs=${TREAD_JOBS:-2}

cache_value() {  # cache_value BUILD_DIR NAME: a variable from a CMakeCache.txt, or nothing
  sed -n "s/^$2:[A-Z]*=//p" "$1/CMakeCache.txt" | head -n 1
}
config_value() {  # config_value CONFIG NAME: a set(NAME [=[...]=]) value of tread-config.cmake
  sed -n "s/^set($2 \[=\[\(.*\)\]=\])\$/\1/p" "$1"
}

# Every #include "..." of an installed header must be an installed header.
check_headers() {
  local include_dir=$1 missing=0 header inc
  while IFS= read -r header; do
    while IFS= read -r inc; do
      if [[ ! -f $include_dir/$inc && ! -f $(dirname "$header")/$inc ]]; then
        echo "check-install: ${header#"$include_dir"/} includes \"$inc\", which is not installed" >&2
        missing=1
      fi
    done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$header")
  done < <(find "$include_dir" -name '*.hpp')
  return $missing
}

check_one() {
  local target=$1 build name
  if [[ -f $target/CMakeCache.txt ]]; then
    build=$target
    name=$(basename "$target")
  else
    build=build/$target
    name=$target
    if [[ ! -f $build/CMakeCache.txt ]]; then
      echo "--- configuring preset $target"
      cmake --preset "$target" >/dev/null
    fi
  fi
  local prefix=$out/install/$name consumer=$out/consumer/$name
  echo "=== install check: $name ($build -> $prefix)"
  if ((build_package)); then
    cmake --build "$build" --target tread_package -j "$jobs" >/dev/null
  fi
  rm -rf "$prefix" "$consumer"
  cmake --install "$build" --prefix "$prefix" >/dev/null
  local config=$prefix/lib/cmake/tread/tread-config.cmake
  [[ -f $config ]] || { echo "check-install: $config was not installed" >&2; return 1; }
  check_headers "$prefix/include/tread"
  echo "headers: $(find "$prefix/include/tread" -name '*.hpp' | wc -l) installed, includes resolve"

  # Configured as an ECU team would: the package's own toolchain and CPU files for a cross build,
  # the build's compiler (and launcher) for a host one.
  local args=(-G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=MinSizeRel)
  local toolchain cpu_file launcher
  toolchain=$(config_value "$config" tread_TOOLCHAIN_FILE)
  cpu_file=$(config_value "$config" tread_CPU_FILE)
  if [[ -n $toolchain ]]; then
    # tread_DIR too: the Linux cross toolchains confine find_package to their sysroot.
    args+=(-DCMAKE_TOOLCHAIN_FILE="$prefix/share/tread/toolchains/$toolchain"
      -Dtread_DIR="$prefix/lib/cmake/tread")
    [[ -z $cpu_file ]] || args+=(-DTREAD_CPU_FILE="$prefix/share/tread/cpu/$cpu_file")
  else
    args+=(-DCMAKE_CXX_COMPILER="$(cache_value "$build" CMAKE_CXX_COMPILER)")
  fi
  launcher=$(cache_value "$build" CMAKE_CXX_COMPILER_LAUNCHER)
  [[ -z $launcher ]] || args+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
  cmake -S "$source_dir/examples/consumer" -B "$consumer" "${args[@]}" | grep -E '^-- tread '
  cmake --build "$consumer" -j "$jobs" >/dev/null

  local system
  system=$(sed -n 's/^set(CMAKE_SYSTEM_NAME "\(.*\)")$/\1/p' \
    "$consumer"/CMakeFiles/*/CMakeSystem.cmake | head -n 1)
  if [[ $system == Generic ]]; then
    local image=$consumer/tread_consumer.elf
    local header
    header=$(readelf -h "$image")
    if ! grep -Eq 'Type: +EXEC' <<<"$header" || ! grep -Eq 'Machine: +ARM$' <<<"$header"; then
      echo "check-install: $image is not an Arm executable" >&2
      return 1
    fi
    echo "bare-metal image: $(arm-none-eabi-size "$image" | tail -n 1 | awk '{print $1 " B text, " $2 " B data, " $3 " B bss"}')"
  else
    # A Linux cross consumer runs under the build's emulator (qemu-user), if it has one.
    local emulator=()
    if [[ -n $toolchain ]]; then
      echo "cross consumer: $(readelf -h "$consumer/tread_consumer" | sed -n 's/^ *Machine: *//p')"
      IFS=';' read -r -a emulator <<<"$(cache_value "$build" CMAKE_CROSSCOMPILING_EMULATOR)"
      ((${#emulator[@]})) || return 0
    fi
    "${emulator[@]}" "$consumer/tread_consumer" | tee "$consumer/output.txt"
    grep -qx 'consumer: sane' "$consumer/output.txt"
  fi
}

for target in "${targets[@]}"; do
  check_one "$target"
done
echo "check-install: passed (${targets[*]})"
