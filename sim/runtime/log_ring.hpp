#pragma once
// Logging off the real-time thread: the loop's observer puts every frame it receives and sends
// into a lock-free ring (no I/O, no lock, no heap on the loop's side), and a writer thread at
// normal priority takes them out and writes the candump log. A full ring drops the record and
// counts it: the loop never waits for the disk. A log with dropped records is not complete:
// CandumpWriter::finish(dropped) keeps it as `<path>.incomplete` and says so.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "core/spsc_ring.hpp"
#include "proto/can_frame.hpp"
#include "runtime/candump_log.hpp"

namespace tread::host {

struct LogRecord {
  proto::CanFrame frame{};
  std::int64_t time_ns{0};
};

/// 16384 records (1.5 MiB): a 1 kHz node with 4 tyres and 2 wheelsets logs ~30 frames a cycle, so
/// the ring holds about half a second of a stalled writer; the writer empties it every 2 ms.
using LogRingBuffer = core::SpscRing<LogRecord, 16384>;

/// The loop's observer (hal::LoopRunner): records into the ring.
struct RingRecorder {
  LogRingBuffer* ring{nullptr};
  std::uint64_t dropped{0};  ///< records the full ring refused (read after the loop stops)
  void on_rx(const proto::CanFrame& frame, std::int64_t time_ns) noexcept { put(frame, time_ns); }
  void on_tx(const proto::CanFrame& frame, std::int64_t time_ns) noexcept { put(frame, time_ns); }

 private:
  void put(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
    if (ring != nullptr && !ring->push(LogRecord{frame, time_ns})) {
      ++dropped;
    }
  }
};

/// The writer thread: drains the ring into a CandumpWriter until stopped, then drains the rest. It
/// runs on the default scheduler and off `realtime_cpu` (the loop's CPU; -1: anywhere), whatever
/// the thread that starts it (hal::become_helper): never at the loop's priority, nor on its CPU
/// unless that is the only one the process may use.
class LogRingWriter {
 public:
  /// Starts the thread; `writer` must be open and outlive this.
  LogRingWriter(LogRingBuffer& ring, CandumpWriter& writer, int realtime_cpu);
  LogRingWriter(const LogRingWriter&) = delete;
  LogRingWriter& operator=(const LogRingWriter&) = delete;
  ~LogRingWriter();

  /// Stops the thread after it has written every record left in the ring.
  void stop();

 private:
  LogRingBuffer& ring_;
  CandumpWriter& writer_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// A candump log written off the real-time thread: the writer, the ring and the writer thread, for
/// a loop whose observer is recorder(). Without a path nothing is recorded or written.
class RingLog {
 public:
  /// Opens the log (throws std::runtime_error if it cannot) and starts the writer thread, off
  /// `realtime_cpu` (see LogRingWriter).
  RingLog(const std::filesystem::path& path, const std::string& interface, int realtime_cpu);

  [[nodiscard]] RingRecorder& recorder() noexcept { return recorder_; }
  /// Records the full ring refused (read after the loop has stopped).
  [[nodiscard]] std::uint64_t dropped() const noexcept { return recorder_.dropped; }
  /// After the loop has stopped: writes what is left in the ring, stops the thread and closes the
  /// log. "" when it is whole, else why not (CandumpWriter::finish, with the dropped records); a
  /// second call gives the first one's answer.
  [[nodiscard]] std::string finish();

 private:
  // Destroyed in reverse: the thread is stopped before the ring and the writer go.
  CandumpWriter writer_;
  std::unique_ptr<LogRingBuffer> ring_;
  RingRecorder recorder_;
  std::optional<std::string> finished_;  ///< finish()'s answer, once given
  std::optional<LogRingWriter> thread_;
};

}  // namespace tread::host
