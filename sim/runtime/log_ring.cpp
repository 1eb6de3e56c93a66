#include "runtime/log_ring.hpp"

#include <chrono>

#include "posix/realtime.hpp"

namespace tread::host {

LogRingWriter::LogRingWriter(LogRingBuffer& ring, CandumpWriter& writer, int realtime_cpu)
    : ring_(ring), writer_(writer) {
  thread_ = std::thread([this, realtime_cpu] {
    hal::become_helper(realtime_cpu);
    LogRecord r;
    for (;;) {
      const bool last = stop_.load(std::memory_order_acquire);
      while (ring_.pop(r)) {
        writer_.write(r.frame, r.time_ns);
      }
      if (last) {
        return;  // stop was seen before this drain: nothing can follow
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
}

LogRingWriter::~LogRingWriter() {
  stop();
}

void LogRingWriter::stop() {
  if (thread_.joinable()) {
    stop_.store(true, std::memory_order_release);
    thread_.join();
  }
}

RingLog::RingLog(const std::filesystem::path& path, const std::string& interface,
                 int realtime_cpu) {
  if (path.empty()) {
    return;
  }
  writer_.open(path, interface);
  ring_ = std::make_unique<LogRingBuffer>();
  recorder_.ring = ring_.get();
  thread_.emplace(*ring_, writer_, realtime_cpu);
}

std::string RingLog::finish() {
  if (!finished_) {
    if (thread_) {
      thread_->stop();
    }
    finished_ = writer_.finish(recorder_.dropped);
  }
  return *finished_;
}

}  // namespace tread::host
