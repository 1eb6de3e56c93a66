#!/usr/bin/env bash
# Fetches Debian's amd64 kernel (the package linux-image-amd64 depends on), unpacks it with dpkg -x
# (it is NOT installed) and keeps vmlinuz plus the CAN modules the vcan VM needs.
# Usage: scripts/vm/fetch-kernel.sh [DEST]   (default: $TREAD_VM_DIR or /var/cache/tread/vm)
# Idempotent: does nothing when DEST already holds a complete kernel.
set -euo pipefail

dest=${1:-${TREAD_VM_DIR:-/var/cache/tread/vm}}
modules=(can can-raw can-dev vcan)

complete() {
  [[ -s $dest/vmlinuz ]] || return 1
  for m in "${modules[@]}"; do [[ -s $dest/modules/$m.ko ]] || return 1; done
}

if complete; then
  echo "fetch-kernel: kernel and CAN modules present in $dest"
  exit 0
fi

resolve() { apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/ {print $2; exit}'; }
pkg=$(resolve)
if [[ -z $pkg ]]; then  # no package lists yet (packages installed, lists cleaned): fetch them once
  apt-get update -q >&2 || true
  pkg=$(resolve)
fi
if [[ -z $pkg ]]; then
  echo "fetch-kernel: cannot resolve the kernel package behind linux-image-amd64 (run apt-get update?)" >&2
  exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get download -q "$pkg")
dpkg -x "$work"/"$pkg"_*.deb "$work/root"

mkdir -p "$dest/modules"
cp "$work"/root/boot/vmlinuz-* "$dest/vmlinuz"
for m in "${modules[@]}"; do
  src=$(find "$work/root/lib/modules" -name "$m.ko" -o -name "$m.ko.xz" -o -name "$m.ko.zst" | head -n 1)
  if [[ -z $src ]]; then
    echo "fetch-kernel: module $m not found in $pkg" >&2
    exit 1
  fi
  case $src in
    *.xz) xz -dc "$src" >"$dest/modules/$m.ko" ;;
    *.zst) zstd -qdc "$src" >"$dest/modules/$m.ko" ;;
    *) cp "$src" "$dest/modules/$m.ko" ;;
  esac
done
echo "$pkg" >"$dest/kernel-package"
complete
echo "fetch-kernel: $pkg unpacked into $dest"
