#pragma once
// The HIL demo on the real clock, run as a rig runs a node: the node on its own thread (its CPU,
// SCHED_FIFO, mlockall with a prefaulted stack and heap, no I/O: the candump log goes through a
// lock-free ring to a writer thread at normal priority), the rig and its answer checker on the
// calling thread (another CPU, a lower priority), the two joined by a lock-free in-process link
// (--can stub) or a SocketCAN interface.
//
// Periodic mode: the node keeps its own grid of deadlines t0 + k·period. The rig sends the inputs
// of cycle k half a period before deadline k and waits for the answer until half a period after
// it; inputs that leave the rig after the deadline are counted (late_sends) and that cycle is not
// checked, as is a cycle without a complete answer in its window. Sync mode: the node sleeps until
// the rig's cycle frame arrives (woken by it, hal::WaitableCanBus) and answers at once; the rig
// sends every period, waits for each answer however late (up to 1 s; the latency says how late,
// and the rig catches up with its schedule afterwards) and measures CAN-in → CAN-out. With an input
// timeout longer than any hold-up of the rig (so that the node never computes on its own between
// the rig's cycles), a sync-mode run gives the same trace as the simulated clock, value for value.
//
// Which answer is a cycle's: one whose NodeStatus (sent first) left the node at or after the
// cycle's deadline (periodic) or cycle frame (sync). An earlier one is a late answer of an earlier
// cycle and is not checked. The rule can be fooled only by a node held up between its wake-up and
// its status frame for longer than the rig's lead (periodic: half a period less the sending), which
// the node's cycle-time maximum shows.

#include "rig/hil_demo.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::host {

/// Throws std::runtime_error when the CAN interface cannot be used.
DemoResult run_demo_threads(const DemoSettings& settings, NodeRuntime& runtime);

}  // namespace tread::host
