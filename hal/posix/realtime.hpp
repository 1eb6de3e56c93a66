#pragma once
// Optional real-time setup: SCHED_FIFO priority, locked memory, CPU affinity. Each step is optional
// and reports a clear message when the system refuses it (no privilege, no such CPU,
// RLIMIT_MEMLOCK).

#include <cstddef>
#include <string>

namespace tread::hal {

struct RealtimeRequest {
  int fifo_priority{0};  ///< 1..99 for SCHED_FIFO; 0 = leave the scheduler alone
  /// mlockall(MCL_CURRENT | MCL_FUTURE), after telling malloc never to give memory back to the
  /// system nor to serve large blocks by mmap (so freed and reused heap stays locked and mapped),
  /// and with `prefault_heap_bytes` of heap touched and freed for later use.
  bool lock_memory{false};
  int cpu{-1};  ///< pin the calling thread to this CPU; -1 = leave affinity alone
  /// Touch this much of the calling thread's stack, so that its pages are present (and, locked,
  /// stay so) before the loop runs: no page fault on the first deep call.
  std::size_t prefault_stack_bytes{0};
  std::size_t prefault_heap_bytes{0};  ///< with lock_memory: heap reserve touched at set-up
  /// Ask the kernel's power management for a CPU wake-up latency of 0 (PM QoS: /dev/cpu_dma_latency
  /// held open with 0 written, as cyclictest does) for as long as the process runs: no deep idle
  /// states between cycles (in a VM: the guest polls instead of halting its virtual CPU).
  bool no_idle_states{false};
};

struct RealtimeReport {
  bool ok{true};         ///< every requested step succeeded
  std::string messages;  ///< one line per step: what was done or why the system refused it
};

/// Applies the request to the calling thread/process. Never throws; failures are reported. The
/// first call that pins a thread keeps the CPUs that thread could use before (for become_helper):
/// the process's, as long as no thread was narrowed by other means first.
RealtimeReport apply_realtime(const RealtimeRequest& request);

/// Puts the calling thread back on the default scheduler (SCHED_OTHER); affinity and locked memory
/// stay. For a thread that has real-time work and then ordinary work (writing files, plotting).
void leave_fifo() noexcept;

/// For a helper thread of a real-time process (a log writer): on the default scheduler, and off
/// `cpu` (the real-time thread's; -1: affinity unchanged) — on the CPUs the real-time thread had
/// before apply_realtime pinned it (the process's, as `taskset` or the cpuset gave them; without
/// such a pin, the helper's own), less `cpu`; where `cpu` is the only one, unchanged. A thread
/// inherits its creator's policy and affinity, so one started from the pinned SCHED_FIFO loop
/// would otherwise share its CPU at its priority.
void become_helper(int cpu) noexcept;

}  // namespace tread::hal
