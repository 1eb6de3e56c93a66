#!/bin/sh
# vcan_soak.sh TREAD TIR [DURATION_S]: the node and the rig as two processes on vcan0 (classic layout)
# for DURATION_S seconds (default 600) with faults injected periodically; run in the VM by
# scripts/soak.sh. The node runs its own periodic schedule (5 ms: the guest is emulated, TCG on one
# vCPU, where the 1 kHz loop does not fit beside the rig) with a 25 ms input timeout, SCHED_FIFO and
# mlockall; the rig streams the tyre-test-machine sweep and is restarted every round.
#
# A fault-free baseline (30 s) first, then rounds of 60 s, each with, in order:
#   link down for 1 s and up again; 10 error frames; a burst of garbage (5000 random extended-ID
#   frames, 100 wrong-length frames on WheelSlip_0's ID, 50 bad-CRC frames on WheelSlip_1's ID); the
#   rig stalled for 2 s (SIGSTOP/SIGCONT); the node stalled for 50 ms (its injected overruns); the
#   rig killed (SIGKILL) at the end of the round and a new one started;
# then a fault-free tail (30 s). Every fault is bracketed on the bus by marker frames (ID 0x7F0)
# so that the candump capture (node status, WheelSlip_0, markers) places it in the capture's time.
#
# Checked (each a FAIL line, exit 1):
#  - every frame on the bus is accounted for: vcan0's transmitted frames = the node's sent frames +
#    the node's received frames + its receive-queue overflows + the injected frames that its filter
#    drops (flood, markers), within the kernel's backlog drops either way; the node's counters add up
#    (received = accepted + rejected + ignored + error frames) and count each injected fault
#    (error frames, wrong lengths, bad CRCs; bad counters at most one per message per rig restart
#    and link down, where the rig's counters jump);
#  - stale → safe: after the rig's inputs stop (rig stalled, link down, rig killed), the node's status
#    says wheel 0 stale within the input timeout + 2 periods + 20 ms of the last input; never stale
#    while inputs arrive (none within the timeout − 10 ms of an input); recovery: stale cleared within
#    2 periods + 20 ms of the inputs' return, after every fault;
#  - the node's memory (RSS, anonymous RSS) and file descriptors flat from the end of the first round
#    to the end (mlockall: RSS is what is resident);
#  - overruns: the node stall injects some (seen in its status within the stall's window); outside
#    those windows the overrun rate is not above the fault-free baseline's (2x + 3: the guest's timer
#    jitter, measured in the same run, is the environment's, not the node's) or under 5 % of the
#    cycles (the host's load may change during the run); in all, no more than the injected ones and
#    5 % of the cycles, or twice the baseline's rate where that is more, + 3 (a node that a fault
#    left degraded misses most of its deadlines). Where a status
#    frame is late itself (the emulator held the guest back), stale and recovery are not timed by it;
#  - node and rig exit cleanly (the node on SIGTERM, with its report).
# Each check's lines go to the console and to OUT/soak_summary.txt (OUT: TREAD_OUT_DIR or
# /work/out).
tread=$1
tir=$2
duration=${3:-600}
out=${TREAD_OUT_DIR:-/work/out}
tmp=${TMPDIR:-/tmp}/soak
mkdir -p "$out" "$tmp"
period_us=5000
timeout_ms=25
status=0
fail() { echo "vcan_soak: FAIL: $*" | tee -a "$out/soak_summary.txt"; status=1; }
say() { echo "$*" | tee -a "$out/soak_summary.txt"; }
# report NAME FILE: a check's lines to the console and the summary; its FAIL lines fail NAME.
report() {
  tee -a "$out/soak_summary.txt" <"$2"
  grep -q FAIL "$2" && fail "$1 (the lines above)"
}
: >"$out/soak_summary.txt"
injected_dropped=0  # injected frames the node's filter drops (flood, markers)
injected_error=0
injected_bad_length=0
injected_bad_crc=0
marker_n=0
marker() {  # marker CODE PHASE: a frame on 0x7F0 (not a protocol ID) with the fault's code
  cansend vcan0 "7F0#$1$2"
  injected_dropped=$((injected_dropped + 1))
  marker_n=$((marker_n + 1))
}
tx_count() { cat /sys/class/net/vcan0/statistics/tx_packets; }
rx_dropped() { cat /sys/class/net/vcan0/statistics/rx_dropped; }

sample_resources() {  # sample_resources LABEL: node RSS, anonymous RSS (kB), open fds
  rss=$(awk '/^VmRSS/ { print $2 }' /proc/$node_pid/status)
  anon=$(awk '/^RssAnon/ { print $2 }' /proc/$node_pid/status)
  fds=$(ls /proc/$node_pid/fd | wc -l)
  echo "$1 $rss $anon $fds" >>"$tmp/resources.txt"
}

start_rig() {
  round_rig=$((round_rig + 1))
  "$tread" rig --can vcan0 --tir "$tir" --scenario sweep --sweep-duration-s 100 --period-us 10000 \
    --pace-us 10000 --answer-timeout-ms 15 --out "$tmp/rig$round_rig" >"$tmp/rig$round_rig.txt" 2>&1 &
  rig_pid=$!
}

: >"$tmp/resources.txt"
tx0=$(tx_count)
drop0=$(rx_dropped)
candump -D -d -r 8388608 -L vcan0,0F0:7FF,100:7FF,7F0:7FF >"$tmp/capture.log" 2>"$tmp/candump.err" &
cap_pid=$!
sleep 0.3
"$tread" node --can vcan0 --tir "$tir" --mode periodic --period-us $period_us --timeout-ms $timeout_ms \
  --rt-priority 80 --mlock >"$out/soak_node.txt" 2>&1 &
node_pid=$!
sleep 0.5
round_rig=0
start_rig
say "soak: ${duration} s, node period ${period_us} us, input timeout ${timeout_ms} ms"
sleep 30
sample_resources baseline
marker 01 00  # end of the baseline
rounds=$(((duration - 60) / 60))
[ $rounds -lt 1 ] && rounds=1
r=1
while [ $r -le $rounds ]; do
  sleep 5
  marker 10 00; ip link set vcan0 down; sleep 1; ip link set vcan0 up; marker 10 01
  sleep 5
  i=0
  while [ $i -lt 10 ]; do
    cansend vcan0 20000040#0000000000000000  # error frame (controller problem class)
    i=$((i + 1))
  done
  injected_error=$((injected_error + 10))
  sleep 5
  marker 30 00
  cangen vcan0 -e -g 0 -n 5000
  injected_dropped=$((injected_dropped + 5000))
  cangen vcan0 -I 100 -L 2 -g 1 -n 100
  injected_bad_length=$((injected_bad_length + 100))
  cangen vcan0 -I 101 -L 8 -D 0003000000000000 -g 1 -n 50  # CRC 00, the right one is A1
  injected_bad_crc=$((injected_bad_crc + 50))
  marker 30 01
  sleep 5
  marker 40 00; kill -STOP $rig_pid; sleep 2; kill -CONT $rig_pid; marker 40 01
  sleep 5
  marker 50 00; kill -STOP $node_pid; sleep 0.05; kill -CONT $node_pid; marker 50 01
  sleep 5
  [ $r -eq 1 ] && sample_resources round1
  # The rest of the round, then the rig is killed and restarted (a new rig: its counters begin anew).
  sleep 24
  marker 60 00; kill -KILL $rig_pid; wait $rig_pid 2>/dev/null; sleep 0.2; start_rig; marker 60 01
  r=$((r + 1))
done
sleep 30
marker 02 00  # end of the tail
sample_resources end
kill -TERM $rig_pid; wait $rig_pid 2>/dev/null
sleep 0.3
kill -TERM $node_pid
wait $node_pid || fail "node exited with an error"
tx1=$(tx_count)
drop1=$(rx_dropped)
sleep 1  # let candump (sharing the guest's CPU) write out what it has queued
kill -INT $cap_pid
wait $cap_pid 2>/dev/null
restarts=$round_rig

n=$out/soak_node.txt
cat "$n" | tee -a "$out/soak_summary.txt" >/dev/null
# Stale -> safe, recovery, overruns: from the capture (candump -L: "(sec.usec) vcan0 ID#DATA").
# WheelSlip_0 (0x100) stands for the rig's inputs (wheel 0's channel: stale bit 0 of NodeStatus'
# StaleMask, byte 6; Overruns is byte 4, saturating at 255).
grep -q DROPCOUNT "$tmp/capture.log" && fail "candump dropped frames: the capture is incomplete ($(grep DROPCOUNT "$tmp/capture.log" | tail -1))"
awk -v timeout=$((timeout_ms * 1000)) -v period=$period_us -v rounds=$rounds \
  -v rate_file="$tmp/baseline_rate.txt" '
  function hex(s,   i, v) { v = 0; for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789ABCDEF", substr(s, i, 1)) - 1; return v }
  BEGIN { onset_bound = timeout + 2 * period + 20000; recovery_bound = 2 * period + 20000; fresh = timeout - 10000 }
  /^\(/ {
    # The microseconds without their leading zeros: busybox awk (in the guest) reads "073336" as
    # octal.
    t = substr($1, 2, length($1) - 2); split(t, p, "."); frac = p[2]; sub(/^0+/, "", frac)
    us = p[1] * 1000000 + (frac == "" ? 0 : frac)
    split($3, f, "#"); id = f[1]; d = f[2]
  }
  id == "7F0" {
    code = substr(d, 1, 2); phase = substr(d, 3, 2)
    if (code == "01") base_end = us
    if (code == "02") tail_end = us
    if (code == "50" && phase == "00") in_stall = 1
    if (code == "50" && phase == "01") { in_stall = 0; stall_to = us; stall_windows++ }
    next
  }
  id == "100" && length(d) == 16 {
    if (have_in && us - last_in > timeout) gaps++
    if (have_in && us - last_in > onset_bound) long_gaps++
    # A gap that the node status frames covered without a break of their own (the bus up, the guest
    # not frozen: no two of them more than 2 periods + 10 ms apart) must have shown stale.
    if (have_in && us - last_in > onset_bound && last_status > last_in + onset_bound && max_spacing <= 2 * period + 10000 && !stale_since_in) {
      missed_onsets++
      printf "missed onset: no input from %.6f s to %.6f s (%.1f ms); status frames up to %.1f ms after the last input, at most %.1f ms apart, none stale\n", last_in / 1e6, us / 1e6, (us - last_in) / 1000, (last_status - last_in) / 1000, max_spacing / 1000
    }
    if (in_gap) { gap_back = us; waiting_recovery = 1; in_gap = 0 }
    last_in = us; have_in = 1; max_spacing = 0; stale_since_in = 0; next
  }
  id == "0F0" && length(d) == 16 {
    if (!have_status) { first_status = us; have_status = 1; ovr = hex(substr(d, 9, 2)) }
    o = hex(substr(d, 9, 2)); stale = hex(substr(d, 13, 2)) % 2
    if (o == 255 && !saturated) { saturated = 1; saturated_at = us }
    if (o > ovr && !saturated) {
      inc = o - ovr
      if (in_stall || (stall_to && us <= stall_to + 3 * period + 20000)) injected += inc
      else if (!base_end) base += inc
      else if (!tail_end) spont += inc
    }
    ovr = o
    if (stale && !was_stale && !waiting_recovery) {
      onsets++
      delay = us - last_in
      # Timed only when the status frames of the node were continuous up to it (no two more than 2
      # periods + 10 ms apart): across a link down, a node stall or the emulator holding the guest
      # back there is no frame to see the moment in.
      if (us - last_status > 2 * period + 10000) untimed++
      else {
        if (delay > max_onset) max_onset = delay
        if (delay > onset_bound) late_onsets++
      }
      in_gap = 1
    } else if (stale && !in_gap && !waiting_recovery && have_in && us - last_in < fresh) {
      false_stale++
    }
    if (!stale && waiting_recovery) {
      rec = us - gap_back; recoveries++
      if (us - last_status > 2 * period + 10000) untimed_recoveries++
      else {
        if (rec > max_recovery) max_recovery = rec
        if (rec > recovery_bound) late_recoveries++
      }
      waiting_recovery = 0
    }
    if (have_status_before && us - last_status > max_spacing) max_spacing = us - last_status
    if (stale) stale_since_in = 1
    was_stale = stale; last_status = us; have_status_before = 1
  }
  END {
    bad = 0
    printf "stale: %d onsets (input gaps over the timeout: %d, over the bound: %d), max %.1f ms after the last input (bound %.1f ms; %d not timed: no status frames to time them by); %d late, %d missed, %d while inputs arrived\n", onsets, gaps, long_gaps, max_onset / 1000, onset_bound / 1000, untimed, late_onsets, missed_onsets, false_stale
    printf "recovery: %d, max %.1f ms after the inputs returned (bound %.1f ms; %d not timed); %d late\n", recoveries, max_recovery / 1000, recovery_bound / 1000, untimed_recoveries, late_recoveries
    base_s = (base_end - first_status) / 1e6; run_s = (tail_end - base_end) / 1e6
    # Overruns per cycle in the fault-free baseline: the environment (the emulator timer jitter
    # under the host load), for the overall bound of the accounting.
    printf "%.6f\n", (base_s > 0 ? base / (base_s * 1e6 / period) : 0) > rate_file
    if (saturated) run_s = (saturated_at - base_end) / 1e6
    printf "overruns: baseline %d in %.0f s; node stalls %d (injected, %d stalls); elsewhere %d in %.0f s%s\n", base, base_s, injected, stall_windows, spont, run_s, saturated ? " (then the status counter saturated at 255: the node report has the total)" : ""
    # Each round stops the inputs three times (link down, rig stalled, rig killed).
    if (onsets < 3 * rounds || late_onsets || missed_onsets || false_stale) { print "FAIL: stale detection"; bad = 1 }
    if (recoveries < 3 * rounds || recoveries < onsets - 1 || late_recoveries) { print "FAIL: recovery"; bad = 1 }
    if (stall_windows > 0 && injected < stall_windows && !saturated) { print "FAIL: a node stall injected no overrun"; bad = 1 }
    # After the faults, overruns at no more than twice the baseline rate + 3, or, the emulator jitter
    # being the host load, in under 5 % of the cycles (a node left degraded by a fault misses most).
    if (base_s <= 0 || (spont > 2 * base * run_s / base_s + 3 && spont > 0.05 * run_s * 1e6 / period)) { print "FAIL: more overruns after the faults than the baseline rate allows"; bad = 1 }
    exit bad }' "$tmp/capture.log" >"$tmp/check_capture.txt"
report "stale/recovery/overruns" "$tmp/check_capture.txt"


# Accounting of every frame on the bus.
base_rate=$(cat "$tmp/baseline_rate.txt" 2>/dev/null || echo 0)
awk -v tx=$((tx1 - tx0)) -v dropped=$injected_dropped -v backlog=$((drop1 - drop0)) \
  -v base_rate="$base_rate" \
  -v err=$injected_error -v badlen=$injected_bad_length -v badcrc=$injected_bad_crc \
  -v restarts=$restarts -v rounds=$rounds -v period=$period_us '
  /^frames received/ { gsub(/[(),]/, " "); rx = $3; acc = $5; ign = $7; errf = $10 }
  /^frames rejected/ { gsub(/[(),]/, " "); rej = $3; crc = $6; cnt = $9; len = $12 }
  /^rx queue overflow/ { ovfl = $4 }
  /^frames sent/ { gsub(/[(),]/, " "); sent = $3; refused = $8 }
  /^cycles/ { cycles = $2 }
  /^overruns/ { overruns = $2 }
  END {
    bad = 0
    node_tx = sent  # what reached the bus (the refused sends are not in it)
    # A frame the kernel dropped from its receive backlog (netdev_max_backlog, during the flood)
    # is off by one either way: it reached no socket (the sum falls short), or, as a run on
    # 2026-11-26 showed (sum = bus + 9 with 9 backlog drops, the flood being the injected frames
    # counted as filtered), it never counted on the bus. So the sum is the bus within those drops.
    sum = node_tx + rx + ovfl + dropped
    printf "accounting: frames on the bus %d; node sent %d + node received %d + overflowed %d + injected, filtered out %d = %d (kernel backlog drops %d)\n", tx, node_tx, rx, ovfl, dropped, sum, backlog
    if (sum > tx + backlog || sum < tx - backlog) { print "FAIL: the frames on the bus are not accounted for"; bad = 1 }
    # Overruns in all: those the node stalls inject (50 ms at the period, each), and besides them
    # 5 % of the cycles or, where the fault-free baseline of the same run already missed more (the
    # emulated guest on a loaded host), twice the baseline rate, + 3.
    allowed = 0.05; if (2 * base_rate > allowed) allowed = 2 * base_rate
    printf "overruns: %d in %d cycles (%.2f %%; baseline %.2f %%, allowed beyond the injected %.2f %%)\n", overruns, cycles, 100 * overruns / (cycles > 0 ? cycles : 1), 100 * base_rate, 100 * allowed
    if (overruns > rounds * (50000 / period + 2) + allowed * cycles + 3) { print "FAIL: overruns beyond the injected ones and the allowed share of the cycles"; bad = 1 }
    if (acc < 1000) { printf "FAIL: the node accepted %d frames: the rig did not run\n", acc; bad = 1 }
    if (rx != acc + rej + ign + errf) { print "FAIL: the node'\''s received frames do not add up"; bad = 1 }
    if (errf != err) { printf "FAIL: error frames %d, injected %d\n", errf, err; bad = 1 }
    if (len != badlen) { printf "FAIL: bad length %d, injected %d\n", len, badlen; bad = 1 }
    if (crc != badcrc) { printf "FAIL: bad CRC %d, injected %d\n", crc, badcrc; bad = 1 }
    # A restarted rig, or one whose sends the link refused while it was down (its counters ran on):
    # the first frame of each of its 9 messages after it may be out of sequence (rejected until a
    # second one confirms the new counter); a smaller jump is accepted and counted as lost frames
    # (counter gaps: frames that never reached the bus, not frames the bus lost).
    if (cnt > 9 * (restarts + rounds)) { printf "FAIL: bad counters %d, more than 9 per rig restart and link down (%d)\n", cnt, restarts + rounds; bad = 1 }
    exit bad }' "$n" >"$tmp/check_accounting.txt"
report "frame accounting" "$tmp/check_accounting.txt"

# Memory and file descriptors flat from the end of the first round to the end.
awk '{ rss[$1] = $2; anon[$1] = $3; fds[$1] = $4 }
  END {
    printf "resources (RSS kB / anonymous kB / fds): baseline %d / %d / %d, after round 1 %d / %d / %d, end %d / %d / %d\n", rss["baseline"], anon["baseline"], fds["baseline"], rss["round1"], anon["round1"], fds["round1"], rss["end"], anon["end"], fds["end"]
    if (rss["end"] > rss["round1"] || anon["end"] > anon["round1"] || fds["end"] != fds["round1"]) { print "FAIL: memory or file descriptors grew"; exit 1 } }' \
  "$tmp/resources.txt" >"$tmp/check_resources.txt"
report "resources" "$tmp/check_resources.txt"
grep -q "dropped" "$tmp/candump.err" 2>/dev/null && say "note: candump: $(cat "$tmp/candump.err")"
say "rig restarts: $restarts; markers $marker_n"
# On a failure the capture is kept beside the summary (a few MB) for a look at what happened.
[ $status -eq 0 ] || cp "$tmp/capture.log" "$out/soak_capture.log"
[ $status -eq 0 ] && say "soak: PASS" || say "soak: FAIL"
exit $status
