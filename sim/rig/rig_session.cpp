#include "rig/rig_session.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "mf/mf_evaluate.hpp"
#include "mf/mf_parameters_from_tir.hpp"
#include "posix/posix_clock.hpp"
#include "proto/rig_link.hpp"
#include "rig/reference_model.hpp"
#include "socketcan/socketcan_bus.hpp"

namespace tread::host {
namespace {

/// One operating point per wheel: braking, cornering, combined, light load.
proto::RigData operating_points(std::uint32_t cycle) {
  proto::RigData d;
  d.wheels[0] = {-0.08F, 0.0F, 0.0F, 4000.0F, 16.7F, 0.0F, false};
  d.wheels[1] = {0.0F, 0.06F, 0.01F, 4500.0F, 16.7F, 0.0F, false};
  d.wheels[2] = {0.05F, -0.04F, 0.0F, 3500.0F, 16.7F, 0.0F, false};
  d.wheels[3] = {0.02F, 0.02F, -0.01F, 2000.0F, 16.7F, 0.0F, false};
  d.rig_cycle = cycle;
  return d;
}

}  // namespace

RigReport run_rig(const RigSettings& s) {
  const mf::MfTirParameters loaded = mf::load_mf_parameters(s.tir);
  const mf::MfOptions options{};
  hal::SocketCanBus bus;
  const Status opened = bus.open(s.can, s.layout == proto::Layout::fd);
  if (opened != Status::ok) {
    throw std::runtime_error("cannot open CAN interface '" + s.can + "' (" + to_string(opened) +
                             ", errno " + std::to_string(bus.last_errno()) + ")");
  }
  // What the node sees after quantisation: decode the rig's own frames.
  proto::RigLink link(s.layout, s.wheels, 0);
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  proto::RigData quantised{};
  {
    proto::RigLink probe(s.layout, s.wheels, 0);
    const std::size_t n = probe.encode_cycle(operating_points(0), frames);
    for (std::size_t k = 0; k < n; ++k) {
      static_cast<void>(
          proto::decode(*proto::find_message(s.layout, frames[k].id), frames[k], quantised));
    }
  }
  std::array<mf::MfOutput<double>, proto::kMaxWheels> reference{};
  for (std::size_t i = 0; i < s.wheels; ++i) {
    reference[i] = reference_output(loaded.params, quantised.wheels[i], options);
  }

  RigReport r;
  hal::PosixClock clock;
  const std::int64_t period_ns = s.period_us * 1000;
  const auto cycles =
      static_cast<std::uint64_t>(s.duration_s * 1e9 / static_cast<double>(period_ns));
  std::int64_t deadline = clock.now_ns() + period_ns;
  proto::NodeData outputs{};
  for (std::uint64_t c = 0; c < cycles; ++c) {
    const std::size_t n =
        link.encode_cycle(operating_points(static_cast<std::uint32_t>(c)), frames);
    for (std::size_t k = 0; k < n; ++k) {
      if (bus.send(frames[k]) == Status::ok) {
        ++r.frames_sent;
      } else {
        ++r.send_refused;
      }
    }
    ++r.cycles;
    static_cast<void>(clock.sleep_until_ns(deadline));
    deadline += period_ns;
    proto::CanFrame f{};
    while (bus.receive(f) == Status::ok) {
      if (f.error) {
        ++r.error_frames;
        continue;
      }
      const proto::MessageSpec* m = proto::find_message(s.layout, f.id);
      if (f.extended || m == nullptr || m->direction != proto::Direction::node_to_rig) {
        ++r.foreign_frames;
        continue;
      }
      const std::uint64_t rejected_before = link.rejected();
      if (link.receive(f, outputs) != Status::ok) {
        r.node_frames_rejected += link.rejected() - rejected_before;
        continue;
      }
      ++r.node_frames_accepted;
      if (m->id == proto::kNodeStatusId) {
        r.node_overruns = outputs.status.overruns;
        r.node_rejected = outputs.status.rejected;
        r.node_cycle = outputs.status.cycle;
        continue;
      }
      // Check the wheels whose forces this frame carries (the status says whether they are computed
      // values); other wheels' fields may still be from before their first frame.
      for (std::size_t i = 0; i < s.wheels; ++i) {
        bool carried = false;
        for (const proto::SignalSpec& sig : m->signals) {
          carried = carried || (sig.role == proto::Role::fx &&
                                m->instance_of(sig) == static_cast<std::int8_t>(i));
        }
        if (!carried) {
          continue;
        }
        const proto::WheelOutput& w = outputs.wheels[i];
        if (w.status != 0U) {
          r.stale_answers += (w.status & proto::kStatusStale) != 0U ? 1U : 0U;
          continue;
        }
        ++r.answers_checked;
        r.max_force_error_n = std::max({r.max_force_error_n,
                                        std::abs(static_cast<double>(w.fx_n) - reference[i].fx_n),
                                        std::abs(static_cast<double>(w.fy_n) - reference[i].fy_n)});
        r.max_moment_error_nm = std::max(
            r.max_moment_error_nm, std::abs(static_cast<double>(w.mz_nm) - reference[i].mz_nm));
      }
    }
  }
  return r;
}

void print_rig_report(std::ostream& out, const RigReport& r) {
  out << "rig cycles           " << r.cycles << "\n";
  out << "rig frames sent      " << r.frames_sent << " (refused " << r.send_refused << ")\n";
  out << "node frames          " << r.node_frames_accepted << " accepted, "
      << r.node_frames_rejected << " rejected\n";
  out << "other traffic        " << r.foreign_frames << " foreign frames, " << r.error_frames
      << " error frames\n";
  out << "answers checked      " << r.answers_checked << " (stale " << r.stale_answers << ")\n";
  out << "max |dF|             " << r.max_force_error_n << " N, max |dMz| " << r.max_moment_error_nm
      << " N m (vs the reference in double; quantisation 0.5 N / 0.025 N m)\n";
  out << "node status          cycle " << r.node_cycle << ", overruns " << r.node_overruns
      << ", rejected " << r.node_rejected << "\n";
}

}  // namespace tread::host
