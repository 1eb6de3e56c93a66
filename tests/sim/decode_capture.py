#!/usr/bin/python3
"""Decodes a candump capture of a node + rig session with the DBC, independently of tread's codec
(python3-canmatrix), and checks it against the rig's traces.

usage: decode_capture.py DBC CAPTURE.log TRACE.csv [TRACE.csv ...]
  DBC        src/proto/tread_classic.dbc or tread_fd.dbc (the capture's layout)
  CAPTURE    `candump -L` log of the session
  TRACE      the rig's scenario traces in the order they ran (tread rig --out DIR: DIR/<name>.csv)

Checks: every frame is a message of the DBC with its length and FD flag; its E2E CRC (CRC-8/SAE-J1850
over the data ID and the payload, computed here) is right; each message's counter advances by one
(mod 15) from frame to frame, so nothing was lost on the wire. candump runs with -d: a frame its own
socket dropped (a full receive queue: the capture's loss, not the node's) is reported on a
"DROPCOUNT" line; then the capture is incomplete: the frames it holds are checked (DBC, CRC), not
the counters or the cycles, and the check fails as the capture's, not as the node's. Then, cycle by cycle (grouped by the
rig's cycle frame), the values canmatrix decodes equal the rig's traces: the slips, loads and
lateral displacements the rig sent (within half a quantisation step of the trace's unquantised
value, plus float rounding) and the forces, moments and delta r the node answered (equal to what tread decoded).
Every cycle has its answer (group_cycles): with a node in sync mode (NodeStatus State bit 1) the
computation whose NodeStatus Cycle is the cycle's RigCycle (low 16 bits), after the cycle frame;
the node's input-timeout computations, which repeat the last RigCycle, answer none and are counted
apart. In periodic mode, the first computation after the cycle's first frame.
Prints 'decode_capture: ...' and exits non-zero on any mismatch.
"""
import csv
import logging
import os
import re
import sys

logging.disable(logging.CRITICAL)
import canmatrix  # noqa: E402
import canmatrix.formats  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "proto"))
from e2e_crc import e2e_crc  # noqa: E402  (tests/proto/e2e_crc.py)


DROP = re.compile(r"^DROPCOUNT: dropped (\d+) CAN frame")
LINE = re.compile(r"^\((\d+\.\d+)\)\s+(\S+)\s+([0-9A-Fa-f]+)(##[0-9A-Fa-f]|#)([0-9A-Fa-f]*)")


def parse(path):
    """The capture's frames, and the frames candump reported dropping (its -d DROPCOUNT lines)."""
    frames = []
    dropped = 0
    with open(path) as f:
        for n, line in enumerate(f, 1):
            d = DROP.match(line.strip())
            if d:
                dropped += int(d.group(1))
                continue
            m = LINE.match(line.strip())
            if not m:
                raise SystemExit(f"{path}:{n}: not a candump -L line: {line.strip()!r}")
            fd = m.group(4).startswith("##")
            frames.append((n, int(m.group(3), 16), fd, bytes.fromhex(m.group(5))))
    return frames, dropped


def key(frame, signal_name):
    """Signal name with the channel index: classic 'WheelForce_2'.'Fx' -> 'Fx_2'; FD 'Fx_2' as is."""
    suffix = re.search(r"_(\d)$", frame.name)
    if suffix and not re.search(r"_\d$", signal_name):
        return f"{signal_name}_{suffix.group(1)}"
    return signal_name


def read_trace(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [{k: float(v) for k, v in r.items()} for r in rows]


def group_cycles(events):
    """Groups a session's decoded frames into rig cycles and gives each the node's answer.

    events: (is_rig, decoded signals) in capture order. A rig cycle is the rig's frames up to and
    including its cycle frame (the one with RigCycle, sent last). A NodeStatus (the signal Cycle)
    starts a computation of the node, whose frames follow it. With the node in sync mode (State
    bit 1) the computation answering a cycle is the one whose Cycle is that cycle's RigCycle (low
    16 bits), after the cycle frame: the node's input-timeout computations repeat the last RigCycle
    (65535 before any) and answer none. In periodic mode it is the first computation after the
    cycle's first frame. Returns (cycles, other_answers): per cycle {'rig': signals, 'node':
    signals of its answer, 'answered': bool}; other_answers counts the computations that answered
    no cycle.
    """
    cycles = []
    current = None
    taking = False  # the node frames since the last NodeStatus are the current cycle's answer
    other_answers = 0
    for rig, decoded in events:
        if rig:
            if current is None or current["closed"]:
                current = {"rig": {}, "node": {}, "closed": False, "answered": False}
                cycles.append(current)
            current["rig"].update(decoded)
            if "RigCycle" in decoded:
                current["closed"] = True
            continue
        if "Cycle" in decoded:
            if current is None or current["answered"]:
                taking = False
            elif int(decoded["State"]) & 2:
                taking = (current["closed"]
                          and int(decoded["Cycle"]) == int(current["rig"]["RigCycle"]) % 65536)
            else:
                taking = True
            if taking:
                current["answered"] = True
            else:
                other_answers += 1
        if taking:
            current["node"].update(decoded)
    return cycles, other_answers


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    db = canmatrix.formats.loadp_flat(sys.argv[1])
    frames, dropped = parse(sys.argv[2])
    if dropped:
        print(f"decode_capture: candump dropped {dropped} frames (its own receive queue, -d): the "
              "capture is incomplete; its frames are checked, its counters and cycles are not")
    traces = [(p, read_trace(p)) for p in sys.argv[3:]]
    failures = []
    counters = {}
    events = []  # (from the rig, decoded signals) in capture order
    steps = {}
    for n, fid, fd, payload in frames:
        frame = db.frame_by_id(canmatrix.ArbitrationId(fid))
        if frame is None:
            failures.append(f"line {n}: id {fid:#x} is not in the DBC")
            continue
        if frame.size != len(payload) or bool(frame.is_fd) != fd:
            failures.append(f"line {n}: {frame.name} has {len(payload)} bytes (fd {fd}), DBC {frame.size}")
            continue
        if payload[0] != e2e_crc(fid, payload):
            failures.append(f"line {n}: {frame.name}: bad E2E CRC")
        decoded = {key(frame, name): float(v.phys_value) for name, v in frame.decode(payload).items()}
        for sig in frame.signals:
            steps[key(frame, sig.name)] = float(sig.factor)
        counter = int(decoded["Counter"] if "Counter" in decoded else decoded[key(frame, "Counter")])
        if not dropped and fid in counters and counter != (counters[fid] + 1) % 15:
            failures.append(f"line {n}: {frame.name}: counter {counter} after {counters[fid]} (frame lost?)")
        counters[fid] = counter
        events.append(("Rig" in frame.transmitters, decoded))
    cycles, other_answers = group_cycles(events)
    compared = 0
    if dropped:
        # Not the node's loss (its own counters say that), but the check against the traces could
        # not be made: a failure of the capture, said as such.
        failures.append(f"the capture dropped {dropped} frames (candump's receive queue, -d): "
                        "the values could not be compared with the traces; a loss of the capture, "
                        "not of the node")
        cycles = []
        traces = []
    # The traces in order, row by row, are the rig's cycles.
    rows = [(p, i, r, rows_[i - 1] if i > 0 else None) for p, rows_ in traces for i, r in enumerate(rows_)]
    if len(rows) != len(cycles):
        failures.append(f"{len(cycles)} rig cycles in the capture, {len(rows)} trace rows")

    def same(name, got, want, tol):
        nonlocal compared
        compared += 1
        if abs(got - want) > tol:
            failures.append(f"{name}: capture {got}, trace {want} (tolerance {tol:g})")

    for c, (cycle, (path, i, row, prev)) in enumerate(zip(cycles, rows)):
        where = f"cycle {c} ({path} row {i + 1})"
        if int(cycle["rig"].get("RigCycle", -1)) != c:
            failures.append(f"{where}: RigCycle {cycle['rig'].get('RigCycle')} (a cycle missing?)")
        if not cycle.get("answered"):
            failures.append(f"{where}: no answer of the node to this cycle in the capture")
        node, sent = cycle["node"], cycle["rig"]
        for w in range(4):
            if f"Fx_N_{w}" in row:  # road-vehicle traces: inputs of this cycle, answers of this cycle
                if node.get(f"Status_{w}", 0) == 0 and f"Fx_{w}" in node:
                    for sig, col in (("Fx", "Fx_N"), ("Fy", "Fy_N"), ("Mz", "Mz_Nm")):
                        same(f"{where} {sig}_{w}", node[f"{sig}_{w}"], row[f"{col}_{w}"], 2e-7 * abs(row[f"{col}_{w}"]) + 1e-6 * steps[f"{sig}_{w}"])
                if f"kappa_{w}" in row and f"Kappa_{w}" in sent:
                    same(f"{where} Kappa_{w}", sent[f"Kappa_{w}"], row[f"kappa_{w}"], 0.5 * steps[f"Kappa_{w}"] + 1e-6)
                    same(f"{where} Alpha_{w}", sent[f"Alpha_{w}"], row[f"alpha_rad_{w}"], 0.5 * steps[f"Alpha_{w}"] + 1e-6)
                    same(f"{where} Fz_{w}", sent[f"Fz_{w}"], row[f"Fz_N_{w}"], 0.5 * steps[f"Fz_{w}"] + 2e-7 * abs(row[f"Fz_N_{w}"]))
        for j in range(2):
            if f"ws{j}_delta_r_mm" in row and f"DeltaR_{j}" in node:
                # The hunting trace holds the state after the step: what was sent is the row before.
                y_sent = prev[f"ws{j}_y_mm"] if prev is not None and f"ws{j}_y_mm" in prev else None
                if y_sent is not None:
                    same(f"{where} Lateral_{j}", sent[f"Lateral_{j}"], y_sent, 0.5 * steps[f"Lateral_{j}"] + 1e-6)
                same(f"{where} DeltaR_{j}", node[f"DeltaR_{j}"], row[f"ws{j}_delta_r_mm"], 2e-7 * abs(row[f"ws{j}_delta_r_mm"]) + 1e-6 * steps[f"DeltaR_{j}"])
    for f in failures[:20]:
        print("FAIL:", f)
    print(f"decode_capture: {len(frames)} frames, {len(cycles)} rig cycles, {compared} values compared "
          f"with the traces, {other_answers} answers of the node to no rig cycle, capture drops "
          f"{dropped}, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
