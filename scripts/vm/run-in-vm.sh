#!/usr/bin/env bash
# Runs a program inside a throwaway x86_64 VM whose kernel has SocketCAN, with vcan0 (FD-capable,
# mtu 72) and vcan1 (classic, mtu 16) up, and exits with the program's exit status.
#
# Usage: scripts/vm/run-in-vm.sh [--file SRC[:DEST]]... [--workdir DIR] -- PROGRAM [ARGS...]
#   PROGRAM and every --file are copied into an initramfs built for this run (with the shared
#   libraries ldd names), next to busybox-static and the can-utils binaries. Inside the guest the
#   working directory is /work (files land there unless DEST is absolute); --workdir copies the guest's
#   /work/out back to DIR after the run.
# Environment: TREAD_VM_DIR (kernel, default /var/cache/tread/vm), TREAD_VM_TIMEOUT_S (default 300),
#   TREAD_VM_CPUS (virtual CPUs, default 1; more run as threads of the emulator, one per CPU, for a
#   node and a rig on CPUs of their own), TREAD_VM_VERBOSE=1 to show the whole console.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
vm_dir=${TREAD_VM_DIR:-/var/cache/tread/vm}
timeout_s=${TREAD_VM_TIMEOUT_S:-300}
cpus=${TREAD_VM_CPUS:-1}
if ! [[ $cpus =~ ^[1-9][0-9]?$ ]]; then
  echo "run-in-vm: TREAD_VM_CPUS must be a whole number from 1 to 99, not '$cpus'" >&2
  exit 2
fi

files=()
outdir=""
while (($#)); do
  case $1 in
    --file) files+=("$2"); shift 2 ;;
    --workdir) outdir=$2; shift 2 ;;
    --) shift; break ;;
    *) break ;;
  esac
done
if (($# == 0)); then
  echo "run-in-vm: no program given" >&2
  exit 2
fi
program=$1
shift

for tool in qemu-system-x86_64 busybox cpio gzip; do
  if ! command -v "$tool" >/dev/null; then
    echo "run-in-vm: '$tool' not found; run scripts/install-deps.sh" >&2
    exit 1
  fi
done
if [[ ! -s $vm_dir/vmlinuz ]]; then
  "$here/fetch-kernel.sh" "$vm_dir" >&2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root=$work/root
mkdir -p "$root"/{bin,sbin,proc,sys,dev,tmp,work/out,modules,lib,lib64,usr/bin}

cp "$(command -v busybox)" "$root/bin/busybox"
cp "$vm_dir"/modules/*.ko "$root/modules/"

# Copy an executable and the shared libraries it needs, at the same absolute paths.
copy_with_libs() {
  local bin=$1 dest=$2
  mkdir -p "$(dirname "$root$dest")"
  cp "$bin" "$root$dest"
  chmod +x "$root$dest"
  # Debug info is of no use in the guest and would swell the RAM-backed root file system.
  strip --strip-debug "$root$dest" 2>/dev/null || true
  { ldd "$bin" 2>/dev/null || true; } | { grep -oE '/[^ ]+' || true; } | while read -r lib; do
    if [[ -f $lib && ! -e $root$lib ]]; then
      mkdir -p "$(dirname "$root$lib")"
      cp -L "$lib" "$root$lib"
    fi
  done
}

for tool in candump cansend cangen canplayer; do
  if command -v "$tool" >/dev/null; then copy_with_libs "$(command -v "$tool")" "/usr/bin/$tool"; fi
done
copy_with_libs "$(readlink -f "$program")" "/work/$(basename "$program")"
for spec in "${files[@]}"; do
  src=${spec%%:*}
  dst=$(basename "$src")
  [[ $spec == *:* ]] && dst=${spec#*:}
  [[ $dst == /* ]] || dst=/work/$dst
  if [[ -f $src && -x $src ]]; then
    copy_with_libs "$src" "$dst"
  else
    mkdir -p "$(dirname "$root$dst")"
    cp -r "$src" "$root$dst"
  fi
done

args=""
for a in "$@"; do args+=" $(printf '%q' "$a")"; done
cat >"$root/init" <<INIT
#!/bin/busybox sh
/bin/busybox --install -s /bin
export PATH=/usr/bin:/bin:/sbin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev 2>/dev/null
for m in can can-dev can-raw vcan; do insmod /modules/\$m.ko || echo "TREAD_GUEST_SETUP_FAILED insmod \$m"; done
ip link add dev vcan0 type vcan && ip link set vcan0 mtu 72 && ip link set vcan0 up || echo "TREAD_GUEST_SETUP_FAILED vcan0"
ip link add dev vcan1 type vcan && ip link set vcan1 up || echo "TREAD_GUEST_SETUP_FAILED vcan1"
cd /work
echo TREAD_GUEST_BEGIN
./$(basename "$program")$args
rc=\$?
echo TREAD_GUEST_END
if [ -d /work/out ] && [ -n "\$(ls /work/out)" ]; then
  echo TREAD_GUEST_OUT_BEGIN
  tar -C /work/out -cf - . | gzip | base64
  echo TREAD_GUEST_OUT_END
fi
echo "TREAD_GUEST_EXIT=\$rc"
poweroff -f
INIT
chmod +x "$root/init"

(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) >"$work/initrd.gz"

console=$work/console.log
set +e
timeout "$timeout_s" qemu-system-x86_64 -accel tcg,thread=multi -m 512 -smp "$cpus" -nographic -no-reboot \
  -kernel "$vm_dir/vmlinuz" -initrd "$work/initrd.gz" \
  -append "console=ttyS0 panic=-1 quiet loglevel=3" </dev/null >"$console" 2>&1
qemu_rc=$?
set -e
tr -d '\r' <"$console" >"$console.clean"

if [[ ${TREAD_VM_VERBOSE:-0} == 1 ]]; then
  cat "$console.clean"
else
  # The guest program's own output, between the markers.
  sed -n '/TREAD_GUEST_BEGIN$/,/^TREAD_GUEST_END$/p' "$console.clean" | sed '1d;$d'
fi

if grep -q TREAD_GUEST_SETUP_FAILED "$console.clean"; then
  echo "run-in-vm: guest setup failed:" >&2
  grep TREAD_GUEST_SETUP_FAILED "$console.clean" >&2
  exit 1
fi
if [[ -n $outdir ]] && grep -q '^TREAD_GUEST_OUT_BEGIN$' "$console.clean"; then
  mkdir -p "$outdir"
  sed -n '/^TREAD_GUEST_OUT_BEGIN$/,/^TREAD_GUEST_OUT_END$/p' "$console.clean" | sed '1d;$d' |
    base64 -d | gzip -dc | tar -C "$outdir" -xf -
fi
rc_line=$(grep -o 'TREAD_GUEST_EXIT=[0-9]*' "$console.clean" | tail -n 1 || true)
if [[ -z $rc_line ]]; then
  echo "run-in-vm: the guest did not report an exit status (qemu exit $qemu_rc; timeout ${timeout_s}s?)." >&2
  echo "---- last console lines ----" >&2
  tail -n 30 "$console.clean" >&2
  exit 1
fi
rc=${rc_line#TREAD_GUEST_EXIT=}
if [[ $rc != 0 ]]; then
  echo "run-in-vm: guest program exited with status $rc" >&2
fi
exit "$rc"
