#!/usr/bin/env bash
# resource_misuse_check.sh TREAD TIR RIG_LOG OUT: what a user gets when the machine says no.
# - a full disk for the log (a file-size limit stands in for it: `ulimit -f`, SIGXFSZ ignored, so
#   writes fail with EFBIG as on a full disk) — for `tread node --replay --tx-log` and for
#   `tread demo --log`: exit status 1, an error naming the file, and no file under the log's name:
#   what reached the disk is kept as LOG.incomplete, never claimed complete;
# - a log in a directory that does not exist: a clear error before anything runs;
# - a CAN interface that does not exist (or no CAN in the kernel): a clear error naming it;
# - SCHED_FIFO and mlockall without the permission (run as nobody): said at once, on stderr, and
#   again in the report; the node runs on, unlocked and at the default priority.
set -uo pipefail
tread=$1 tir=$2 rig_log=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
status=0
fail() { echo "resource_misuse_check: FAIL: $*"; status=1; }
profile=(--wheelsets 2 --wheelset-profile wheel=S1002,rail=60E1,cant=1:40)

# Full disk: --tx-log of a replay, then --log of the demo.
(trap '' XFSZ; ulimit -f 32; "$tread" node --tir "$tir" "${profile[@]}" --replay "$rig_log" --clock sim \
  --tx-log "$out/tx.log" >"$out/replay.txt" 2>"$out/replay.err")
rc=$?
[[ $rc == 1 ]] || fail "replay with a full disk exited $rc, not 1"
grep -qF "$out/tx.log: writing the log failed (File too large)" "$out/replay.err" ||
  fail "replay: no error naming the log: $(cat "$out/replay.err")"
[[ ! -e $out/tx.log ]] || fail "replay: a cut log under the log's name"
[[ -s $out/tx.log.incomplete ]] || fail "replay: what was written is not kept as tx.log.incomplete"
(trap '' XFSZ; ulimit -f 32; "$tread" demo --clock sim --scenario sweep --sweep-duration-s 1 --tir "$tir" \
  --no-plot --out "$out/demo" --log "$out/demo.log" >"$out/demo.txt" 2>"$out/demo.err")
rc=$?
[[ $rc == 1 ]] || fail "demo with a full disk exited $rc, not 1"
# (The demo's traces hit the limit too: the first file that cannot be written is named.)
grep -Eq "$out/demo.log: writing the log failed|cannot write $out/demo/" "$out/demo.err" ||
  fail "demo: no error naming the file: $(cat "$out/demo.err")"
[[ ! -e $out/demo.log && -s $out/demo.log.incomplete ]] || fail "demo: the cut log is not kept apart"
# The same runs with room: the logs get their names, nothing incomplete is left.
"$tread" node --tir "$tir" "${profile[@]}" --replay "$rig_log" --clock sim --tx-log "$out/tx_ok.log" \
  >/dev/null 2>&1 || fail "replay with room failed"
[[ -s $out/tx_ok.log && ! -e $out/tx_ok.log.partial && ! -e $out/tx_ok.log.incomplete ]] ||
  fail "a complete log does not have its name alone"

# A log where there is no directory.
"$tread" node --tir "$tir" "${profile[@]}" --replay "$rig_log" --clock sim \
  --tx-log "$out/no/such/dir/tx.log" >/dev/null 2>"$out/nodir.err"
rc=$?
[[ $rc == 1 ]] && grep -qF "no/such/dir/tx.log: cannot open for writing (No such file or directory" \
  "$out/nodir.err" || fail "a log in a missing directory: rc $rc, $(cat "$out/nodir.err")"

# A CAN interface that does not exist.
"$tread" node --tir "$tir" --can nosuchcan0 --duration-s 0.1 >/dev/null 2>"$out/nocan.err"
rc=$?
[[ $rc == 1 ]] && grep -Eq "cannot open CAN interface 'nosuchcan0'|SocketCAN is not available in this kernel" \
  "$out/nocan.err" || fail "a missing CAN interface: rc $rc, $(cat "$out/nocan.err")"

# Real-time requests without the permission (as nobody, no capabilities, no rtprio/memlock limit).
if [[ $(id -u) == 0 ]] && command -v setpriv >/dev/null; then
  # nobody may not reach into OUT (CI clones into a mode-700 directory): the binary and the tyre go
  # into a directory of their own that nobody can read.
  nobody_dir=$(mktemp -d /tmp/tread-rt.XXXXXX)
  chmod 755 "$nobody_dir"
  copy=$nobody_dir/tread
  { cp "$tread" "$copy" && chmod 755 "$copy" && cp "$tir" "$nobody_dir/tyre.tir" &&
    chmod 644 "$nobody_dir/tyre.tir"; } || fail "cannot prepare the unprivileged run in $nobody_dir"
  (ulimit -l 64; ulimit -r 0; cd "$nobody_dir" && setpriv --reuid=nobody --regid=nogroup --clear-groups \
    --inh-caps=-all "$copy" node --tir "$nobody_dir/tyre.tir" --can stub --rt-priority 80 --mlock \
    --duration-s 0.2 >"$out/rt.txt" 2>"$out/rt.err")
  rc=$?
  rm -rf "$nobody_dir"
  [[ $rc == 0 ]] || fail "the node without RT permission exited $rc"
  grep -q "SCHED_FIFO priority 80: refused (Operation not permitted)" "$out/rt.err" ||
    fail "SCHED_FIFO refusal not said at once: $(cat "$out/rt.err")"
  # (AddressSanitizer makes mlockall a no-op that succeeds: no refusal to see in the asan build.)
  if [[ -z ${ASAN_OPTIONS:-} ]]; then
    grep -q "^mlockall: refused" "$out/rt.err" || fail "mlockall refusal not said at once"
  fi
  grep -q "SCHED_FIFO priority 80: refused" "$out/rt.txt" || fail "SCHED_FIFO refusal not in the report"
else
  echo "resource_misuse_check: not root (or no setpriv): the real-time refusal part is not run"
fi
((status == 0)) && echo "resource_misuse_check: OK"
exit $status
