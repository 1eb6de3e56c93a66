#include "runtime/node_session.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "gpiod/gpiod_pin.hpp"
#include "node/log_replay.hpp"
#include "posix/posix_clock.hpp"
#include "runtime/candump_log.hpp"
#include "runtime/log_ring.hpp"
#include "runtime/protocol_socket.hpp"
#include "socketcan/socketcan_bus.hpp"
#include "stub/stub_can_bus.hpp"

namespace tread::host {
namespace {

hal::LoopConfig loop_config(const NodeSettings& s, std::int64_t period_us) {
  hal::LoopConfig c;
  c.period_ns = period_us * 1000;
  c.schedule = s.node.schedule;
  return c;
}

template <typename Bus, typename Pin>
SessionReport run_with(Bus& bus, Pin& pin, NodeRuntime& runtime, const NodeSettings& settings,
                       const LiveOptions& options, RingLog& log, const std::atomic<bool>* stop,
                       SessionReport report) {
  hal::PosixClock clock;
  report.loop = runtime.visit([&](auto& node) {
    hal::LoopRunner loop(node, bus, clock, pin, loop_config(settings, options.period_us),
                         log.recorder());
    loop.run(options.cycles == 0 ? ~std::uint64_t{0} : options.cycles, stop);
    return loop.stats();
  });
  report.counters = runtime.counters();
  report.log_error = log.finish();
  return report;
}

}  // namespace

SessionReport run_live(const NodeSettings& settings, const LiveOptions& options,
                       const std::atomic<bool>* stop) {
  NodeRuntime runtime(settings);
  SessionReport report;
  if (!runtime.tir_warning().empty()) {
    report.notes += "note: " + runtime.tir_warning() + "\n";
  }
  hal::GpiodPin pin;
  if (!options.gpio_chip.empty()) {
    if (pin.open(options.gpio_chip, static_cast<unsigned>(options.gpio_cycle_line)) != Status::ok) {
      report.notes += "GPIO: " + pin.error() + "; running without the cycle pin\n";
    }
  }
  // The bus first: a run that cannot open it leaves no log behind.
  hal::PosixClock stub_clock;
  std::optional<hal::StubCanNetwork> network;
  hal::SocketCanBus bus;
  if (options.can == "stub") {
    network.emplace(&hal::clock_now<hal::PosixClock>, &stub_clock);
  } else {
    open_protocol_socket(bus, options.can, settings.node.layout, proto::Direction::rig_to_node);
    report.receive_buffer_bytes = bus.receive_buffer_bytes();
  }
  // The log: the loop puts its frames into a lock-free ring, a writer thread (default scheduler,
  // off the loop's CPU) writes them; no I/O on the real-time thread. Opened before the real-time
  // settings, so that the ring and the thread's stack are allocated before mlockall (which locks
  // them) and the thread starts on the default scheduler, not at the loop's priority.
  RingLog log(options.log, options.can, options.realtime.cpu);
  hal::RealtimeRequest request = options.realtime;
  request.no_idle_states = request.fifo_priority > 0;  // a real-time run, as cyclictest
  const hal::RealtimeReport rt = hal::apply_realtime(request);
  report.notes += rt.messages;
  // What was granted or refused, said at once too, not only in the report at the end (a refusal
  // means the run that follows is not real-time).
  std::cerr << rt.messages << std::flush;

  if (network) {
    return run_with(network->endpoint(0), pin, runtime, settings, options, log, stop, report);
  }
  report = run_with(bus, pin, runtime, settings, options, log, stop, report);
  report.rx_queue_overflows = bus.rx_overflows();
  return report;
}

namespace {

/// The host replay's sink: the replayed frames as log lines (and into the --tx-log file).
struct ReplaySink {
  std::string interface;
  CandumpWriter* writer{nullptr};
  std::vector<std::string> lines;
  void on_logged_tx(const proto::CanFrame& /*frame*/, std::int64_t /*time_ns*/) noexcept {}
  void on_tx(const proto::CanFrame& frame, std::int64_t now_ns) {
    char line[kCandumpLineMax];
    format_candump_line(frame, now_ns, interface, line);
    lines.emplace_back(line);
    writer->write(frame, now_ns);
  }
};

}  // namespace

ReplayResult run_replay(const NodeSettings& settings, const std::filesystem::path& log,
                        std::int64_t period_us, const std::filesystem::path& tx_log) {
  const std::vector<LoggedFrame> frames = read_candump_log(log);
  if (frames.empty()) {
    throw std::runtime_error(log.string() + ": no frames");
  }
  const proto::Layout layout = settings.node.layout;
  // The node's own frames mark its cycles (node/log_replay.hpp, the schedule the firmware image
  // replays with too); here the log need not be in time order: it is replayed stably sorted.
  std::vector<std::string> logged_tx;
  std::vector<const LoggedFrame*> ordered;
  char line[kCandumpLineMax];
  for (const LoggedFrame& f : frames) {
    if (node::is_node_output(layout, f.frame)) {
      format_candump_line(f.frame, f.time_ns, f.interface, line);
      logged_tx.emplace_back(line);
    }
    ordered.push_back(&f);
  }
  if (logged_tx.empty()) {
    throw std::runtime_error(log.string() +
                             ": holds no frames sent by the node, so its cycles are unknown "
                             "(record with tread node --log, which logs both directions)");
  }
  std::stable_sort(ordered.begin(), ordered.end(), [](const LoggedFrame* a, const LoggedFrame* b) {
    return a->time_ns < b->time_ns;
  });

  NodeRuntime runtime(settings);
  CandumpWriter writer;
  ReplaySink sink{frames.front().interface, &writer, {}};
  if (!tx_log.empty()) {
    writer.open(tx_log, sink.interface);
  }
  const node::ReplayCounts counts = runtime.visit([&](auto& node) {
    node::LogReplay replay(node, sink, period_us * 1000);
    for (const LoggedFrame* f : ordered) {
      static_cast<void>(replay.add(f->frame, f->time_ns));  // in time order: always ok
    }
    replay.finish();
    return replay.counts();
  });

  ReplayResult result;
  result.report.log_error = writer.finish();
  result.report.loop.cycles = counts.cycles;
  result.report.loop.overruns = counts.overruns;
  result.report.counters = runtime.counters();
  result.input_frames = counts.input_frames;
  result.tx_frames = counts.tx_frames;
  result.logged_tx_frames = logged_tx.size();
  const std::vector<std::string>& replayed_tx = sink.lines;
  result.identical = logged_tx == replayed_tx;
  if (!result.identical) {
    const std::size_t n = std::min(logged_tx.size(), replayed_tx.size());
    std::size_t i = 0;
    while (i < n && logged_tx[i] == replayed_tx[i]) ++i;
    result.first_difference = i < n ? "TX frame " + std::to_string(i + 1) + ": log '" +
                                          logged_tx[i] + "', replay '" + replayed_tx[i] + "'"
                                    : "different number of TX frames (log " +
                                          std::to_string(logged_tx.size()) + ", replay " +
                                          std::to_string(replayed_tx.size()) + ")";
  }
  return result;
}

std::string percentile_text(const hal::LatencyHistogram& h, double q) {
  const std::int64_t us = h.percentile_us(q);
  return (us >= hal::LatencyHistogram::kOverflowUs ? ">= " : "") + std::to_string(us);
}

void print_report(std::ostream& out, const SessionReport& r, bool timing) {
  const node::NodeCounters& c = r.counters;
  out << "cycles            " << r.loop.cycles << "\n";
  out << "overruns          " << r.loop.overruns << "\n";
  if (timing) {
    const auto row = [&out](const char* name, const hal::LatencyHistogram& h) {
      out << name << " p50 " << percentile_text(h, 0.50) << " us, p99 " << percentile_text(h, 0.99)
          << " us, max " << std::fixed << std::setprecision(1)
          << static_cast<double>(h.max_ns()) / 1000.0 << " us\n";
      out.unsetf(std::ios::floatfield);
    };
    if (r.loop.wake_latency.count() > 0U) {
      row("wake latency     ", r.loop.wake_latency);
    } else {
      out << "wake latency      - (sync mode: the node wakes on the rig's cycle frame, not on a "
             "deadline)\n";
    }
    row("cycle time       ", r.loop.cycle_time);
  }
  out << "frames received   " << c.rx_frames << " (accepted " << c.rx_accepted << ", ignored "
      << c.rx_ignored << ", error frames " << c.rx_error_frames << ")\n";
  out << "frames rejected   " << c.rx_rejected() << " (bad CRC " << c.rx_bad_crc << ", bad counter "
      << c.rx_bad_counter << ", bad length " << c.rx_bad_length << ")\n";
  out << "frames lost       " << c.lost_frames << " (counter gaps)\n";
  if (r.rx_queue_overflows) {
    out << "rx queue overflow " << *r.rx_queue_overflows
        << " (frames the kernel dropped for a full receive queue, SO_RXQ_OVFL; buffer "
        << r.receive_buffer_bytes << " bytes)\n";
  }
  // Sent: what went onto the bus; the node computed the refused ones too (and --log records
  // every computed frame, so that a replay reproduces the node, refused sends included).
  out << "frames sent       " << c.tx_frames - std::min(c.tx_frames, r.loop.tx_failed)
      << " (computed " << c.tx_frames << ", send refused " << r.loop.tx_failed << ")\n";
  out << "stale / clamped   " << c.stale_events << " / " << c.clamp_events << " channel-cycles\n";
  out << "outputs saturated " << c.saturated_outputs
      << " frames (a value beyond its signal's range, sent at the limit), not finite "
      << c.non_finite_outputs << "\n";
  if (!r.notes.empty()) {
    out << r.notes;
  }
}

}  // namespace tread::host
