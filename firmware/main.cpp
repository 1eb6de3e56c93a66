// The firmware image: replays a recorded rig log through the real node, cycle by cycle, and writes
// the frames the node transmits as a candump log — on the target, through semihosting:
//
//   tread_firmware --replay IN.log --tx-log OUT.log [--expect HOST_TX.log] [--fd] [--sync]
//                  [--period-us N] [--timing]
//
// (qemu: -semihosting-config enable=on,target=native,arg=tread_firmware,arg=--replay,arg=IN,...).
// The node is the host's `tread node` with its defaults: MF 6.1 (data/tyres/
// MagicFormula61_Parameters.tir, useMode 111) on 4 wheels, the flashed S1002/60E1 1:40 contact
// table on 2 wheelsets, 10 ms input timeout; the schedule is node/log_replay.hpp, as the host's
// replay. In float, or (TREAD_FIRMWARE_FIXED, the FPU-less image) in fixed point as
// `tread node --fixed` (node_path.hpp). --timing adds instruction counts (SysTick ticks) per node
// cycle, MF evaluation and contact lookup. --expect checks every transmitted frame against the
// host's replay of the same log (firmware/tx_check.hpp: same time and message, each signal within
// one quantisation step on the float image, bit-identical on the fixed-point one). The exit status
// (SYS_EXIT_EXTENDED) is 0 when the log replayed (and matched), 1 for a bad log or a mismatch, 2
// for bad arguments or I/O.
#include <array>
#include <cstdint>
#include <string_view>

#include "cortex_m/systick_counter.hpp"
#include "log_reader.hpp"
#include "log_writer.hpp"
#include "node/log_replay.hpp"
#include "node/node.hpp"
#include "node_path.hpp"
#include "proto/candump_line.hpp"
#include "semihost/semihost.hpp"
#include "stack_watermark.hpp"
#include "text_line.hpp"
#include "timed_node.hpp"
#include "timing_benchmarks.hpp"
#include "tx_check.hpp"

#ifdef TREAD_HEAP_PROBE
#include "core/heap_probe.hpp"
#endif

namespace {

using namespace tread;
namespace semihost = hal::semihost;
using firmware::TextLine;

constexpr int kExitBadLog = 1;
constexpr int kExitUsage = 2;

struct Options {
  std::string_view replay;
  std::string_view tx_log;
  std::string_view expect;
  bool fd{false};
  bool sync{false};
  std::int64_t period_us{1000};
  bool timing{false};
};

[[noreturn]] void fail(int status, TextLine& message) {
  semihost::console((message << "\n").c_str());
  semihost::exit(status);
}

bool parse_int(std::string_view text, std::int64_t& value) {
  if (text.empty() || text.size() > 9) return false;
  value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
    value = value * 10 + (c - '0');
  }
  return true;
}

/// The semihosting command line: the image's name, then the options (words split at spaces).
Options parse_options(std::string_view cmdline) {
  std::array<std::string_view, 16> words{};
  std::size_t count = 0;
  while (!cmdline.empty() && count < words.size()) {
    const std::size_t space = cmdline.find(' ');
    const std::size_t len = space == std::string_view::npos ? cmdline.size() : space;
    if (len > 0) words[count++] = std::string_view(cmdline.data(), len);
    cmdline.remove_prefix(len == cmdline.size() ? len : len + 1);
  }
  Options o;
  for (std::size_t i = 1; i < count; ++i) {
    const std::string_view w = words[i];
    const bool has_value = i + 1 < count;
    if (w == "--replay" && has_value) {
      o.replay = words[++i];
    } else if (w == "--tx-log" && has_value) {
      o.tx_log = words[++i];
    } else if (w == "--expect" && has_value) {
      o.expect = words[++i];
    } else if (w == "--period-us" && has_value && parse_int(words[i + 1], o.period_us) &&
               o.period_us > 0) {
      ++i;
    } else if (w == "--fd") {
      o.fd = true;
    } else if (w == "--sync") {
      o.sync = true;
    } else if (w == "--timing") {
      o.timing = true;
    } else {
      TextLine m;
      fail(kExitUsage, m << "tread_firmware: bad argument '" << w << "'");
    }
  }
  if (o.replay.empty() || o.tx_log.empty()) {
    TextLine m;
    fail(kExitUsage, m << "usage: tread_firmware --replay IN.log --tx-log OUT.log "
                          "[--expect HOST_TX.log] [--fd] [--sync] [--period-us N] [--timing]");
  }
  return o;
}

/// The replay's sink: the replayed frames into the TX log (and the check, if any).
struct TxSink {
  firmware::LogWriter* writer;
  firmware::TxCheck* check;
  void on_logged_tx(const proto::CanFrame& /*frame*/, std::int64_t /*time_ns*/) noexcept {}
  void on_tx(const proto::CanFrame& frame, std::int64_t now_ns) noexcept {
    writer->write(frame, now_ns);
    if (check != nullptr) check->check(frame, now_ns);
  }
};

void print_ticks(std::string_view name, const firmware::TickStats& s) {
  TextLine m;
  m << "timing " << name << ": " << s.count << " cycles, ticks min " << (s.count > 0 ? s.min : 0U)
    << " mean*100 " << (s.count > 0 ? s.total * 100U / s.count : 0U) << " max " << s.max << "\n";
  semihost::console(m.c_str());
}

}  // namespace

int main() {
  firmware::StackWatermark::paint();
  std::array<char, 512> cmdline{};
  const Result<std::size_t> got = semihost::command_line(cmdline);
  if (!got.ok()) {
    TextLine m;
    fail(kExitUsage, m << "tread_firmware: no semihosting command line");
  }
  const Options options = parse_options(std::string_view(cmdline.data(), got.value));

  static std::array<firmware::TyreChannel, 4> tyres{};
  for (auto& t : tyres) {
    t = firmware::TyreChannel(firmware::kTyreParameters, firmware::tyre_options());
  }
  static std::array<firmware::ContactChannel, 2> contacts{};
  for (auto& c : contacts) {
    c = firmware::ContactChannel(firmware::contact_table());
  }
  const node::NodeConfig config{
      .layout = options.fd ? proto::Layout::fd : proto::Layout::classic,
      .wheels = 4,
      .wheelsets = 2,
      .input_timeout_ns = 10'000'000,
      .schedule = options.sync ? node::Schedule::sync : node::Schedule::periodic,
      .start_enabled = true,
      .e2e_max_delta = 3,
  };
  static node::Node<firmware::TyreChannel, firmware::ContactChannel> node(config, tyres, contacts);
  hal::SysTickCounter counter;
  counter.start();
  firmware::TimedNode timed(node, counter);

  static firmware::LogReader reader;
  if (reader.open(options.replay) != Status::ok) {
    TextLine m;
    fail(kExitUsage, m << options.replay << ": cannot open");
  }
  static firmware::LogWriter writer;
  static firmware::TxCheck check;
  const bool checking = !options.expect.empty();
  if (checking && check.open(options.expect, config.layout, firmware::kMaxRawSteps) != Status::ok) {
    TextLine m;
    fail(kExitUsage, m << options.expect << ": cannot open");
  }
  TxSink sink{&writer, checking ? &check : nullptr};
  node::LogReplay replay(timed, sink, options.period_us * 1000);
  std::string_view line;
  std::uint64_t line_no = 0;
  bool opened = false;
  for (;;) {
    const Status next = reader.next(line);
    if (next == Status::would_block) break;
    ++line_no;
    if (next != Status::ok) {
      TextLine m;
      fail(kExitBadLog, m << options.replay << ":" << line_no << ": "
                          << (next == Status::out_of_range ? "line too long" : "cannot read"));
    }
    if (line.empty() || line.front() == '#') continue;
    proto::CandumpLine parsed;
    const proto::CandumpError error = proto::parse_candump_line(line, parsed);
    if (error != proto::CandumpError::none) {
      TextLine m;
      fail(kExitBadLog, m << options.replay << ":" << line_no << ": " << proto::describe(error));
    }
    if (!opened) {  // the TX log names the interface of the log's first frame, as the host's
      if (writer.open(options.tx_log, parsed.interface) != Status::ok) {
        TextLine m;
        fail(kExitUsage, m << options.tx_log << ": cannot create");
      }
      opened = true;
    }
    if (replay.add(parsed.frame, parsed.time_ns) != Status::ok) {
      TextLine m;
      fail(kExitBadLog, m << options.replay << ":" << line_no
                          << ": earlier than the line before (the log is not in time order)");
    }
  }
  replay.finish();
  reader.close();
  if (writer.close() != Status::ok) {
    TextLine m;
    fail(kExitUsage, m << options.tx_log << ": cannot write");
  }
  const node::ReplayCounts& counts = replay.counts();
  TextLine summary;
  summary << "replay " << counts.cycles << " cycles, " << counts.input_frames << " input frames, "
          << counts.tx_frames << " frames transmitted; the log holds " << counts.logged_tx_frames
          << "; overruns " << counts.overruns << ", rejected " << node.counters().rx_rejected()
          << "\n";
  semihost::console(summary.c_str());
  if (counts.logged_tx_frames == 0) {
    TextLine m;
    fail(kExitBadLog, m << options.replay << ": holds no frames sent by the node");
  }
  if (checking) {
    check.finish();
    TextLine m;
    m << "check " << check.frames() << " frames against " << options.expect << ": "
      << check.identical() << " bit-identical, " << check.failures() << " failed ("
      << (firmware::kFixedPoint ? "a signal not bit-identical"
                                : "a signal beyond one quantisation step")
      << ", another time or message, a bad CRC, a frame too many or too few)\n";
    semihost::console(m.c_str());
    if (!check.passed()) {
      TextLine f;
      fail(kExitBadLog, f << "check FAILED: " << check.first_failure());
    }
  }
  if (options.timing) {
    print_ticks("node_cycle_all", timed.all_cycles());
    print_ticks("node_cycle_full", timed.full_cycles());
    print_ticks("receive_frame", timed.receives());
    firmware::run_timing_benchmarks(counter);
    TextLine m;
    m << "memory stack_peak_bytes: " << firmware::StackWatermark::peak_bytes() << "\n";
    semihost::console(m.c_str());
  }
#ifdef TREAD_HEAP_PROBE
  static_cast<void>(tread::core_heap_probe());
#endif
  semihost::exit(0);
}
