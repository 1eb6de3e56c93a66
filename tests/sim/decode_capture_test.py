#!/usr/bin/python3
"""Tests of decode_capture.group_cycles (which computation of the node answers which rig cycle), on
made-up event sequences: the race that once let a stale answer through (the node's input-timeout
computation before, inside and after the rig's first cycle), classic and FD shapes, the 16-bit
wrap, and periodic mode. Exits non-zero on a failure."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from decode_capture import group_cycles  # noqa: E402

SYNC = 2 | 1  # State: enabled, sync mode
PERIODIC = 1


def rig_inputs(value):
    return (True, {"Kappa_0": value})


def rig_cycle(c):
    return (True, {"RigCycle": float(c)})


def status(cycle, state=SYNC):
    return (False, {"Cycle": float(cycle), "State": float(state)})


def answer(fx):
    return (False, {"Fx_0": fx})


failures = []


def check(name, got, want):
    if got != want:
        failures.append(f"{name}: got {got!r}, want {want!r}")


def answers(cycles):
    return [c["node"].get("Fx_0") if c["answered"] else None for c in cycles]


# Classic shape (inputs, then the cycle frame). The node's timeout computation (65535: no cycle
# frame yet) lands before, among and after the first cycle's frames; each time only the answer
# naming RigCycle 0 is cycle 0's.
for where in range(4):
    events = [rig_inputs(0.1), rig_inputs(0.2), rig_cycle(0)]
    events[where:where] = [status(65535), answer(-1.0)]
    events += [status(0), answer(10.0), rig_inputs(0.1), rig_cycle(1), status(1), answer(11.0)]
    cycles, other = group_cycles(events)
    check(f"timeout computation at {where}: answers", answers(cycles), [10.0, 11.0])
    check(f"timeout computation at {where}: other answers", other, 1)

# The timeout computation after the cycle frame but before the answer (it repeats the last cycle).
cycles, other = group_cycles([rig_cycle(0), status(0), answer(10.0), rig_cycle(1), status(0),
                              answer(-1.0), status(1), answer(11.0)])
check("repeat of the last cycle: answers", answers(cycles), [10.0, 11.0])
check("repeat of the last cycle: other answers", other, 1)

# FD shape: the cycle frame carries the inputs; a cycle whose answer never came has none.
cycles, other = group_cycles([rig_cycle(0), status(65535), answer(-1.0), rig_cycle(1), status(1),
                              answer(11.0)])
check("fd: answers", answers(cycles), [None, 11.0])
check("fd: other answers", other, 1)

# The 16-bit echo of RigCycle 65536 is 0, and the timeout computation before it repeats 65535.
cycles, other = group_cycles([rig_inputs(0.1), status(65535), answer(-1.0), rig_cycle(65536),
                              status(0), answer(12.0)])
check("wrap: answers", answers(cycles), [12.0])
check("wrap: other answers", other, 1)

# Periodic mode: the first computation after the cycle's first frame, whatever its Cycle.
cycles, other = group_cycles([rig_inputs(0.1), rig_cycle(0), status(7, PERIODIC), answer(10.0),
                              status(8, PERIODIC), answer(-1.0), rig_cycle(1), status(9, PERIODIC),
                              answer(11.0)])
check("periodic: answers", answers(cycles), [10.0, 11.0])
check("periodic: other answers", other, 1)

# Computations before the rig's first frame answer nothing.
cycles, other = group_cycles([status(65535), answer(-1.0), rig_cycle(0), status(0), answer(10.0)])
check("before the rig: answers", answers(cycles), [10.0])
check("before the rig: other answers", other, 1)

for f in failures:
    print("FAIL:", f)
print(f"decode_capture_test: {len(failures)} failures")
sys.exit(1 if failures else 0)
