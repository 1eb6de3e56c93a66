#!/usr/bin/env bash
# The main job, from a fresh clone: installs the Debian packages, builds the host tools and runs
# `tread demo` (node + rig on the in-process bus). Extra arguments go to `tread demo`.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh >/dev/null
cmake --preset host >/dev/null
cmake --build --preset host --target tread
exec build/host/sim/tread demo "$@"
