#pragma once
// Optional real-time setup: SCHED_FIFO priority, locked memory, CPU affinity. Each step is optional
// and reports a clear message when the system refuses it (no privilege, no such CPU,
// RLIMIT_MEMLOCK).

#include <string>

namespace tread::hal {

struct RealtimeRequest {
  int fifo_priority{0};  ///< 1..99 for SCHED_FIFO; 0 = leave the scheduler alone
  bool lock_memory{false};
  int cpu{-1};  ///< pin the calling thread to this CPU; -1 = leave affinity alone
};

struct RealtimeReport {
  bool ok{true};         ///< every requested step succeeded
  std::string messages;  ///< one line per step: what was done or why the system refused it
};

/// Applies the request to the calling thread/process. Never throws; failures are reported.
RealtimeReport apply_realtime(const RealtimeRequest& request);

}  // namespace tread::hal
