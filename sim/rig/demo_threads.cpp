#include "rig/demo_threads.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "loop/loop_runner.hpp"
#include "posix/posix_clock.hpp"
#include "posix/realtime.hpp"
#include "posix/thread_can_link.hpp"
#include "rig/demo_rig.hpp"
#include "runtime/log_ring.hpp"
#include "runtime/protocol_socket.hpp"
#include "socketcan/socketcan_bus.hpp"

namespace tread::host {
namespace {

constexpr std::size_t kNodeStackPrefault = 512U * 1024U;  // the loop's frame holds ~170 KiB
constexpr std::size_t kNodeHeapReserve = 8U * 1024U * 1024U;
constexpr std::int64_t kStartDelayNs = 20'000'000;  // from the node's ready to its first deadline
constexpr std::int64_t kSyncAnswerTimeoutNs = 1'000'000'000;
// On the in-process link the rig looks for the node's answer this often instead of sleeping until
// the node's send wakes it: that wake-up would be made on the node's real-time thread, inside its
// cycle, and waking a thread asleep on another CPU cost the waker a median 31 µs on one VM of these
// machines, 15–30 times the node's own work. The answer's time is its send stamp, so the interval
// adds nothing to the latencies reported.
constexpr std::int64_t kRigPollNs = 20'000;

std::int64_t clock_ns(clockid_t id) {
  timespec ts{};
  ::clock_gettime(id, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

/// The rig's thread: the CPU and priority of DemoSettings (see there for the automatic choice).
hal::RealtimeRequest rig_request(const DemoSettings& s) {
  hal::RealtimeRequest r;
  r.cpu = s.rig_cpu;
  if (r.cpu < 0 && s.realtime.cpu >= 0 && std::thread::hardware_concurrency() > 1) {
    r.cpu = s.realtime.cpu == 0 ? 1 : 0;
  }
  r.fifo_priority = s.rig_priority;
  if (r.fifo_priority < 0) {
    r.fifo_priority = s.realtime.fifo_priority > 0 ? std::max(1, s.realtime.fifo_priority - 10) : 0;
  }
  return r;
}

/// Stops and joins the node's thread however the rig's side ends (an exception included): a thread
/// still waiting for its first deadline is released first.
class NodeThreadGuard {
 public:
  NodeThreadGuard(std::thread& thread, std::atomic<bool>& stop, std::atomic<std::int64_t>& t0)
      : thread_(thread), stop_(stop), t0_(t0) {}
  NodeThreadGuard(const NodeThreadGuard&) = delete;
  NodeThreadGuard& operator=(const NodeThreadGuard&) = delete;
  ~NodeThreadGuard() { join(); }
  void join() {
    stop_.store(true, std::memory_order_release);
    std::int64_t unset = -1;
    t0_.compare_exchange_strong(unset, 0, std::memory_order_acq_rel);
    if (thread_.joinable()) {
      thread_.join();
    }
  }

 private:
  std::thread& thread_;
  std::atomic<bool>& stop_;
  std::atomic<std::int64_t>& t0_;
};

/// `frame_offset_ns`: what to subtract from a received frame's timestamp to put it on
/// CLOCK_MONOTONIC (SocketCAN stamps with CLOCK_REALTIME; the thread link with CLOCK_MONOTONIC).
template <typename NodeBus, typename RigBus>
DemoResult run_threads(const DemoSettings& s, NodeRuntime& runtime, NodeBus& node_bus,
                       RigBus& rig_bus, std::int64_t frame_offset_ns) {
  const node::NodeConfig& cfg = runtime.config();
  const bool periodic = cfg.schedule == node::Schedule::periodic;
  const std::int64_t period_ns = s.period_us * 1000;
  DemoRig rig(s, runtime);
  DemoResult result;
  result.threaded = true;

  // The log: written by a normal thread, off the node's CPU, from the ring the node's loop fills.
  RingLog log(s.log, s.can, s.realtime.cpu);

  // The node's thread.
  std::atomic<bool> ready{false};
  std::atomic<std::int64_t> first_deadline_ns{-1};
  std::atomic<bool> stop{false};
  hal::RealtimeReport node_rt;
  auto stats = std::make_unique<hal::LoopStats>();
  hal::RealtimeRequest node_request = s.realtime;
  node_request.prefault_stack_bytes = kNodeStackPrefault;
  node_request.prefault_heap_bytes = s.realtime.lock_memory ? kNodeHeapReserve : 0U;
  node_request.no_idle_states = s.realtime.fifo_priority > 0;  // a real-time run, as cyclictest
  std::thread node_thread([&] {
    node_rt = hal::apply_realtime(node_request);
    runtime.visit([&](auto& node) {
      hal::PosixClock clock;
      hal::NoPin pin;
      hal::LoopConfig config;
      config.period_ns = period_ns;
      config.schedule = cfg.schedule;
      hal::LoopRunner loop(node, node_bus, clock, pin, config, log.recorder());
      ready.store(true, std::memory_order_release);
      std::int64_t t0 = -1;
      while ((t0 = first_deadline_ns.load(std::memory_order_acquire)) < 0) {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
      }
      if (periodic) {
        loop.set_first_deadline_ns(t0);
      }
      loop.run(~std::uint64_t{0}, &stop);
      *stats = loop.stats();
    });
  });
  NodeThreadGuard guard(node_thread, stop, first_deadline_ns);

  // The rig: on its own CPU and priority for the cycles, back to normal for the outcomes.
  while (!ready.load(std::memory_order_acquire)) {
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  // What the node's thread was granted or refused, said at once (a refusal means the run that
  // follows is not real-time), and again in the summary.
  std::cerr << node_rt.messages << std::flush;
  const hal::RealtimeReport rig_rt = hal::apply_realtime(rig_request(s));
  hal::PosixClock clock;
  // The node's deadlines a quarter period after the clock's grid of periods (whole milliseconds at
  // 1 kHz): off the kernel's tick, which lies on that grid (HZ 250: every 4 ms), so its interrupt
  // does not share the node's wake-up, and at a known phase, so that a yardstick run beside it
  // (scripts/bench-timing.sh: cyclictest --secaligned 750) wakes half a period from the node,
  // also off the tick, instead of at a random phase that may sit on the node's deadlines.
  const std::int64_t t0 =
      ((clock.now_ns() + kStartDelayNs) / period_ns + 1) * period_ns + period_ns / 4;
  first_deadline_ns.store(t0, std::memory_order_release);

  std::uint32_t rig_cycle = 0;
  std::int64_t k = 0;
  proto::CanFrame f{};
  for (auto& runner : rig.runners()) {
    while (!runner->done()) {
      const std::int64_t deadline = t0 + k * period_ns;  // the node's k-th (periodic mode)
      const std::int64_t send_at = periodic ? deadline - period_ns / 2 : deadline;
      static_cast<void>(clock.sleep_until_ns(send_at));
      // What came since the last window is not this cycle's answer.
      while (rig_bus.receive(f) == Status::ok) {
        static_cast<void>(runner->on_frame(f));
        result.stray_answers += f.id == proto::kNodeStatusId ? 1U : 0U;
      }
      const std::span<const proto::CanFrame> frames =
          runner->begin_cycle(runner->time_s(), rig_cycle++);
      std::int64_t cycle_frame_ns = 0;
      for (std::size_t i = 0; i < frames.size(); ++i) {
        if (i + 1 == frames.size()) {
          cycle_frame_ns = clock.now_ns();
        }
        static_cast<void>(rig_bus.send(frames[i]));
      }
      const std::int64_t sent = clock.now_ns();
      const bool late_send = periodic && sent >= deadline;
      // Periodic: the answer belongs to the node's deadline, so it is due within half a period of
      // it. Sync: lockstep; the answer is awaited even when it is late (the latency says how late)
      // and the rig catches up with its schedule afterwards, so the trace is that of the
      // simulated clock.
      const std::int64_t give_up =
          periodic ? deadline + period_ns / 2 : sent + kSyncAnswerTimeoutNs;
      // This cycle's answer is one the node computed after the inputs reached it: in periodic
      // mode at or after the deadline, in sync mode after the cycle frame. An answer that began
      // (its NodeStatus, sent first) earlier is a late one of an earlier cycle: taken (its E2E
      // counters count) but not as this cycle's.
      const std::int64_t valid_from = periodic ? deadline : cycle_frame_ns;
      // The answer is looked for from a quarter period after the node's deadline (periodic) or
      // the cycle frame (sync) on: its time is its send stamp, so looking late changes no figure,
      // and the rig's own wake-up stays clear of the node's, and of the cyclictest run beside the
      // node half a period from its deadlines (scripts/bench-timing.sh).
      static_cast<void>(clock.sleep_until_ns((periodic ? deadline : sent) + period_ns / 4));
      bool valid = false;
      bool answered = false;
      std::int64_t answer_ns = 0;
      for (;;) {
        while (!answered && rig_bus.receive(f) == Status::ok) {
          const std::int64_t at_ns = f.timestamp_ns - frame_offset_ns;
          if (f.id == proto::kNodeStatusId && !f.error && !f.extended) {
            valid = at_ns >= valid_from;
            result.stray_answers += valid ? 0U : 1U;
          }
          answered = runner->on_frame(f) && valid;
          answer_ns = at_ns;
        }
        if (answered || rig_bus.wait_until_ns(give_up) != Status::ok) {
          break;
        }
      }
      if (answered) {
        result.answer_latency.add_ns(answer_ns - (periodic ? deadline : cycle_frame_ns));
      }
      result.unanswered_cycles += answered ? 0U : 1U;
      result.late_sends += late_send ? 1U : 0U;
      runner->end_cycle(rig.step_s(), answered && !late_send);
      ++k;
    }
  }
  guard.join();
  hal::leave_fifo();

  const std::string log_error = log.finish();
  rig.finish(s, result);
  result.report.loop = *stats;
  result.report.counters = runtime.counters();
  result.report.notes = node_rt.messages;
  result.rig_notes = rig_rt.messages.empty() ? "" : "rig thread: " + rig_rt.messages;
  result.log_records_dropped = log.dropped();
  result.report.log_error = log_error;
  return result;
}

}  // namespace

DemoResult run_demo_threads(const DemoSettings& s, NodeRuntime& runtime) {
  if (s.can == "stub") {
    auto link = std::make_unique<hal::ThreadCanLink>();
    link->endpoint(1).set_poll_interval_ns(kRigPollNs);
    return run_threads(s, runtime, link->endpoint(0), link->endpoint(1), 0);
  }
  // Each end set up as `tread node` and `tread rig` set theirs up: only its incoming messages.
  hal::SocketCanBus node_bus;
  hal::SocketCanBus rig_bus;
  open_protocol_socket(node_bus, s.can, s.node.node.layout, proto::Direction::rig_to_node);
  open_protocol_socket(rig_bus, s.can, s.node.node.layout, proto::Direction::node_to_rig);
  const std::int64_t offset = clock_ns(CLOCK_REALTIME) - clock_ns(CLOCK_MONOTONIC);
  DemoResult result = run_threads(s, runtime, node_bus, rig_bus, offset);
  result.report.rx_queue_overflows = node_bus.rx_overflows();
  result.report.receive_buffer_bytes = node_bus.receive_buffer_bytes();
  return result;
}

}  // namespace tread::host
