#include "posix/realtime.hpp"

#include <fcntl.h>
#include <malloc.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace tread::hal {

namespace {

// The CPUs a thread pinned by apply_realtime could use before (the process's, e.g. as `taskset`
// gave them): what become_helper hands its helper threads, less the pinned one.
std::mutex g_unpinned_mutex;
cpu_set_t g_unpinned;
bool g_have_unpinned = false;

// Touches `bytes` below the current frame (the stack grows down): the pages become present.
__attribute__((noinline)) void prefault_stack(std::size_t bytes) {
  constexpr std::size_t kChunk = 16U * 1024U;
  std::array<unsigned char, kChunk> chunk;
  std::memset(chunk.data(), 0, chunk.size());
  asm volatile("" : : "r"(chunk.data()) : "memory");  // the stores are not optimised away
  if (bytes > kChunk) {
    prefault_stack(bytes - kChunk);
  }
}

// Grows the heap by `bytes`, touches it and frees it: with trimming off it stays with the process.
void prefault_heap(std::size_t bytes) {
  auto* block = static_cast<unsigned char*>(std::malloc(bytes));
  if (block == nullptr) {
    return;
  }
  for (std::size_t i = 0; i < bytes; i += 4096U) {
    static_cast<volatile unsigned char*>(block)[i] = 0;
  }
  std::free(block);
}

}  // namespace

RealtimeReport apply_realtime(const RealtimeRequest& request) {
  RealtimeReport report;
  auto refuse = [&report](const std::string& what, int err, const char* hint) {
    report.ok = false;
    report.messages += what + ": refused (" + std::strerror(err) + "). " + hint + "\n";
  };

  if (request.lock_memory) {
    // Freed heap stays in the process (and locked): no trimming, no mmap'ed blocks.
    static_cast<void>(::mallopt(M_TRIM_THRESHOLD, -1));
    static_cast<void>(::mallopt(M_MMAP_MAX, 0));
    if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      report.messages += "mlockall: memory locked";
      if (request.prefault_heap_bytes > 0U) {
        prefault_heap(request.prefault_heap_bytes);
        report.messages +=
            ", " + std::to_string(request.prefault_heap_bytes >> 10U) + " KiB of heap reserved";
      }
      report.messages += "\n";
    } else {
      refuse("mlockall", errno,
             "Needs CAP_IPC_LOCK or a large enough RLIMIT_MEMLOCK (ulimit -l); running unlocked.");
    }
  }
  if (request.cpu >= 0) {
    {
      const std::lock_guard<std::mutex> lock(g_unpinned_mutex);
      cpu_set_t before;
      CPU_ZERO(&before);
      if (!g_have_unpinned &&
          ::pthread_getaffinity_np(::pthread_self(), sizeof(before), &before) == 0) {
        g_unpinned = before;
        g_have_unpinned = true;
      }
    }
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
  if (request.no_idle_states) {
    // Held open for the process's lifetime: closing it would end the request.
    static int qos_fd = -1;
    if (qos_fd < 0) {
      qos_fd = ::open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
    }
    const std::int32_t zero = 0;
    if (qos_fd >= 0 && ::write(qos_fd, &zero, sizeof(zero)) == static_cast<ssize_t>(sizeof(zero))) {
      report.messages += "cpu_dma_latency: 0 us (no deep idle states)\n";
    } else {
      refuse("/dev/cpu_dma_latency", errno,
             "Needs root (or write access to it); idle states may add to the wake-up latency.");
    }
  }
  if (request.prefault_stack_bytes > 0U) {
    prefault_stack(request.prefault_stack_bytes);
    report.messages +=
        "stack: " + std::to_string(request.prefault_stack_bytes >> 10U) + " KiB prefaulted\n";
  }
  return report;
}

void leave_fifo() noexcept {
  sched_param param{};
  param.sched_priority = 0;
  static_cast<void>(::pthread_setschedparam(::pthread_self(), SCHED_OTHER, &param));
}

void become_helper(int cpu) noexcept {
  leave_fifo();
  if (cpu < 0 || cpu >= CPU_SETSIZE) {
    return;
  }
  // The CPUs the real-time thread had before apply_realtime pinned it, else this thread's own
  // (inherited from an unpinned creator), less the real-time one; none left: stay.
  cpu_set_t others;
  CPU_ZERO(&others);
  {
    const std::lock_guard<std::mutex> lock(g_unpinned_mutex);
    if (g_have_unpinned) {
      others = g_unpinned;
    } else if (::pthread_getaffinity_np(::pthread_self(), sizeof(others), &others) != 0) {
      return;
    }
  }
  CPU_CLR(static_cast<std::size_t>(cpu), &others);
  if (CPU_COUNT(&others) > 0) {
    static_cast<void>(::pthread_setaffinity_np(::pthread_self(), sizeof(others), &others));
  }
}

}  // namespace tread::hal
