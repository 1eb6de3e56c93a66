#include "posix/realtime.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstring>

namespace tread::hal {

RealtimeReport apply_realtime(const RealtimeRequest& request) {
  RealtimeReport report;
  auto refuse = [&report](const std::string& what, int err, const char* hint) {
    report.ok = false;
    report.messages += what + ": refused (" + std::strerror(err) + "). " + hint + "\n";
  };

  if (request.lock_memory) {
    if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      report.messages += "mlockall: memory locked\n";
    } else {
      refuse("mlockall", errno,
             "Needs CAP_IPC_LOCK or a large enough RLIMIT_MEMLOCK (ulimit -l); running unlocked.");
    }
  }
  if (request.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(static_cast<std::size_t>(request.cpu), &set);
    const int rc = ::pthread_setaffinity_np(::pthread_self(), sizeof(set), &set);
    if (rc == 0) {
      report.messages += "affinity: pinned to CPU " + std::to_string(request.cpu) + "\n";
    } else {
      refuse("affinity CPU " + std::to_string(request.cpu), rc,
             "Is the CPU online and allowed by the cpuset? Running unpinned.");
    }
  }
  if (request.fifo_priority > 0) {
    sched_param param{};
    param.sched_priority = request.fifo_priority;
    const int rc = ::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &param);
    if (rc == 0) {
      report.messages +=
          "scheduler: SCHED_FIFO priority " + std::to_string(request.fifo_priority) + "\n";
    } else {
      refuse(
          "SCHED_FIFO priority " + std::to_string(request.fifo_priority), rc,
          "Needs root or CAP_SYS_NICE (or an rtprio limit); running with the default scheduler.");
    }
  }
  return report;
}

}  // namespace tread::hal
