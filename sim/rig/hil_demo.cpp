#include "rig/hil_demo.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "loop/loop_runner.hpp"
#include "mf/mf_evaluate.hpp"
#include "node/candump_log.hpp"
#include "plot/gnuplot.hpp"
#include "posix/posix_clock.hpp"
#include "proto/rig_link.hpp"
#include "rig/reference_model.hpp"
#include "rig/scripted_rig.hpp"
#include "socketcan/socketcan_bus.hpp"
#include "stub/sim_clock.hpp"
#include "stub/stub_can_bus.hpp"

namespace tread::host {
namespace {

struct TraceRow {
  double t_s;
  proto::WheelInput in[proto::kMaxWheels];
  proto::WheelOutput can[proto::kMaxWheels];
  double fx_ref[proto::kMaxWheels];
  double fy_ref[proto::kMaxWheels];
  double mz_ref[proto::kMaxWheels];
  float y_mm[proto::kMaxWheelsets];
  float dr_mm[proto::kMaxWheelsets];
};

template <typename ClockT, typename NodeBus, typename RigBus>
DemoResult co_simulate(const DemoSettings& s, NodeRuntime& runtime, ClockT& clock,
                       NodeBus& node_bus, RigBus& rig_bus) {
  const node::NodeConfig& cfg = runtime.node().config();
  CandumpWriter writer;
  CandumpRecorder recorder;
  if (!s.log.empty()) {
    writer.open(s.log, s.can);
    recorder.writer = &writer;
  }
  hal::NoPin pin;
  hal::LoopConfig loop_config;
  loop_config.period_ns = s.period_us * 1000;
  hal::LoopRunner loop(runtime.node(), node_bus, clock, pin, loop_config, recorder);
  proto::RigLink link(cfg.layout, cfg.wheels, cfg.wheelsets);
  const ScriptedRig rig;
  const auto cycles =
      static_cast<std::uint64_t>(s.duration_s * 1e6 / static_cast<double>(s.period_us));
  std::vector<TraceRow> trace;
  trace.reserve(cycles);
  DemoResult result;
  std::array<proto::CanFrame, proto::RigLink::kMaxRigFrames> frames{};
  proto::NodeData outputs{};
  for (std::uint64_t c = 0; c < cycles; ++c) {
    const double t = static_cast<double>(c) * static_cast<double>(s.period_us) * 1e-6;
    const proto::RigData inputs = rig.inputs_at(t, static_cast<std::uint32_t>(c));
    const std::size_t n = link.encode_cycle(inputs, frames);
    for (std::size_t k = 0; k < n; ++k) {
      static_cast<void>(rig_bus.send(frames[k]));
    }
    loop.run_periodic_cycle();
    // The node's answer of this cycle (SocketCAN delivers within microseconds; poll briefly).
    std::size_t got = 0;
    const std::int64_t give_up = clock.now_ns() + 200'000;
    proto::CanFrame f{};
    do {
      while (rig_bus.receive(f) == Status::ok) {
        got += link.receive(f, outputs) == Status::ok ? 1U : 0U;
      }
    } while (got == 0 && clock.now_ns() < give_up && !std::is_same_v<ClockT, hal::SimClock>);

    TraceRow row{};
    row.t_s = t;
    const proto::RigData& seen = runtime.node().latest_inputs();
    for (std::size_t i = 0; i < cfg.wheels; ++i) {
      row.in[i] = seen.wheels[i];
      row.can[i] = outputs.wheels[i];
      const mf::MfOutput<double> ref =
          reference_output(runtime.tyre_parameters(), seen.wheels[i], runtime.tyre_options());
      row.fx_ref[i] = ref.fx_n;
      row.fy_ref[i] = ref.fy_n;
      row.mz_ref[i] = ref.mz_nm;
      if (outputs.wheels[i].status == 0U) {
        result.max_force_error_n =
            std::max({result.max_force_error_n,
                      std::abs(static_cast<double>(outputs.wheels[i].fx_n) - ref.fx_n),
                      std::abs(static_cast<double>(outputs.wheels[i].fy_n) - ref.fy_n)});
        result.max_moment_error_nm =
            std::max(result.max_moment_error_nm,
                     std::abs(static_cast<double>(outputs.wheels[i].mz_nm) - ref.mz_nm));
        result.max_force_n = std::max({result.max_force_n, std::abs(ref.fx_n), std::abs(ref.fy_n)});
      }
    }
    result.peak_fx_n =
        std::max(result.peak_fx_n, static_cast<double>(std::abs(outputs.wheels[0].fx_n)));
    result.peak_fy_n =
        std::max(result.peak_fy_n, static_cast<double>(std::abs(outputs.wheels[1].fy_n)));
    for (std::size_t j = 0; j < cfg.wheelsets; ++j) {
      row.y_mm[j] = seen.wheelsets[j].lateral_mm;
      row.dr_mm[j] = outputs.wheelsets[j].delta_r_mm;
      const auto ref = rail::lookup(runtime.contact_table(), seen.wheelsets[j].lateral_mm);
      result.max_delta_r_error_mm = std::max(
          result.max_delta_r_error_mm,
          static_cast<double>(std::abs(outputs.wheelsets[j].delta_r_mm - ref.value.delta_r_mm)));
    }
    trace.push_back(row);
  }
  result.report.loop = loop.stats();
  result.report.counters = runtime.node().counters();
  result.rig_frames_accepted = link.accepted();
  result.rig_frames_rejected = link.rejected();

  // ---- trace and plots ----
  std::filesystem::create_directories(s.out_dir);
  result.trace_csv = s.out_dir / "trace.csv";
  {
    std::ofstream out(result.trace_csv);
    out << "t_s";
    for (std::size_t i = 0; i < cfg.wheels; ++i) {
      out << ",kappa_" << i << ",alpha_rad_" << i << ",Fz_N_" << i << ",Fx_N_" << i << ",Fy_N_" << i
          << ",Mz_Nm_" << i << ",Fx_ref_N_" << i << ",Fy_ref_N_" << i << ",Mz_ref_Nm_" << i;
    }
    for (std::size_t j = 0; j < cfg.wheelsets; ++j) {
      out << ",y_mm_" << j << ",delta_r_mm_" << j;
    }
    out << '\n' << std::setprecision(9);
    for (const TraceRow& r : trace) {
      out << r.t_s;
      for (std::size_t i = 0; i < cfg.wheels; ++i) {
        out << ',' << r.in[i].kappa << ',' << r.in[i].alpha_rad << ',' << r.in[i].fz_n << ','
            << r.can[i].fx_n << ',' << r.can[i].fy_n << ',' << r.can[i].mz_nm << ',' << r.fx_ref[i]
            << ',' << r.fy_ref[i] << ',' << r.mz_ref[i];
      }
      for (std::size_t j = 0; j < cfg.wheelsets; ++j) {
        out << ',' << r.y_mm[j] << ',' << r.dr_mm[j];
      }
      out << '\n';
    }
    if (!out) throw std::runtime_error("cannot write " + result.trace_csv.string());
  }
  if (s.plot && cfg.wheels >= 2) {
    result.plot_png = s.out_dir / "demo.png";
    const std::string data = gnuplot_quote(result.trace_csv.string());
    const int stride = 9;  // columns per wheel
    const auto col = [&](std::size_t wheel, int k) {
      return std::to_string(2 + static_cast<int>(wheel) * stride + k);
    };
    std::string script = gnuplot_terminal(result.plot_png.string(), 1200, 900);
    script += "set output " + gnuplot_quote(result.plot_png.string()) + "\n";
    script += "set datafile separator ','\nset key autotitle columnhead\nset grid\n";
    script +=
        "set multiplot layout 2,2 title 'tread HIL demo: node answers over CAN (points) vs the "
        "reference model in double (line)'\n";
    script +=
        "set xlabel 'kappa (-)'\nset ylabel 'Fx (N)'\nset title 'wheel 0: longitudinal sweep'\n";
    script += "plot " + data + " using " + col(0, 0) + ":" + col(0, 3) +
              " every 20 with points pt 7 ps 0.4 title 'Fx over CAN', " + data + " using " +
              col(0, 0) + ":" + col(0, 6) + " with lines lw 2 title 'reference'\n";
    script += "set xlabel 'alpha (rad)'\nset ylabel 'Fy (N)'\nset title 'wheel 1: lateral sweep'\n";
    script += "plot " + data + " using " + col(1, 1) + ":" + col(1, 4) +
              " every 20 with points pt 7 ps 0.4 title 'Fy over CAN', " + data + " using " +
              col(1, 1) + ":" + col(1, 7) + " with lines lw 2 title 'reference'\n";
    script +=
        "set xlabel 'alpha (rad)'\nset ylabel 'Mz (N m)'\nset title 'wheel 1: aligning moment'\n";
    script += "plot " + data + " using " + col(1, 1) + ":" + col(1, 5) +
              " every 20 with points pt 7 ps 0.4 title 'Mz over CAN', " + data + " using " +
              col(1, 1) + ":" + col(1, 8) + " with lines lw 2 title 'reference'\n";
    if (cfg.wheelsets > 0) {
      const std::string ycol = std::to_string(2 + static_cast<int>(cfg.wheels) * stride);
      const std::string drcol = std::to_string(3 + static_cast<int>(cfg.wheels) * stride);
      script +=
          "set xlabel 'wheelset displacement y (mm)'\nset ylabel 'delta r (mm)'\nset title "
          "'wheelset 0: rolling radius difference'\n";
      script += "plot " + data + " using " + ycol + ":" + drcol +
                " every 5 with points pt 7 ps 0.4 title 'delta r over CAN'\n";
    } else {
      script += "set xlabel 't (s)'\nset ylabel 'Fz (N)'\nset title 'wheel 3: load sweep'\n";
      script += "plot " + data + " using 1:" + col(3, 2) + " with lines title 'Fz'\n";
    }
    script += "unset multiplot\n";
    run_gnuplot(script, result.plot_png.string());
  }
  return result;
}

}  // namespace

DemoResult run_demo(const DemoSettings& s) {
  NodeRuntime runtime(s.node);
  const hal::RealtimeReport rt = hal::apply_realtime(s.realtime);
  DemoResult result;
  if (s.can == "stub") {
    if (s.sim_clock) {
      hal::SimClock clock(0);
      hal::StubCanNetwork net(&hal::clock_now<hal::SimClock>, &clock);
      result = co_simulate(s, runtime, clock, net.endpoint(0), net.endpoint(1));
    } else {
      hal::PosixClock clock;
      hal::StubCanNetwork net(&hal::clock_now<hal::PosixClock>, &clock);
      result = co_simulate(s, runtime, clock, net.endpoint(0), net.endpoint(1));
    }
  } else {
    const bool fd = s.node.node.layout == proto::Layout::fd;
    hal::SocketCanBus node_bus;
    hal::SocketCanBus rig_bus;
    for (hal::SocketCanBus* b : {&node_bus, &rig_bus}) {
      const Status st = b->open(s.can, fd);
      if (st != Status::ok) {
        throw std::runtime_error("cannot open CAN interface '" + s.can + "' (" + to_string(st) +
                                 ", errno " + std::to_string(b->last_errno()) + ")");
      }
    }
    if (s.sim_clock) {
      throw std::runtime_error("--clock sim needs the in-process bus (--can stub)");
    }
    hal::PosixClock clock;
    result = co_simulate(s, runtime, clock, node_bus, rig_bus);
  }
  result.report.notes =
      rt.messages + (runtime.tir_warning().empty() ? "" : "note: " + runtime.tir_warning() + "\n");
  return result;
}

void print_demo(std::ostream& out, const DemoSettings& s, const DemoResult& r) {
  out << "tread HIL demo — node + scripted rig on "
      << (s.can == "stub" ? "the in-process CAN bus" : s.can) << " ("
      << (s.node.node.layout == proto::Layout::fd ? "CAN FD" : "classic CAN") << " layout, "
      << (s.sim_clock ? "simulated" : "real") << " clock, period " << s.period_us << " us)\n";
  out << "tyre model        " << s.node.tir.string() << " (float on the node, double reference)\n";
  out << "rig               4 wheels: kappa sweep, alpha sweep, combined, load sweep";
  if (s.node.node.wheelsets > 0) {
    out << "; " << static_cast<int>(s.node.node.wheelsets)
        << " wheelset(s): " << s.node.wheelset_profile;
  }
  out << "\n\n";
  print_report(out, r.report, !s.sim_clock);
  out << "rig frames        " << r.rig_frames_accepted << " accepted, " << r.rig_frames_rejected
      << " rejected\n";
  out << std::setprecision(4);
  out << "\nresults over CAN vs the reference model (double):\n";
  out << "  peak |Fx| wheel 0  " << r.peak_fx_n << " N,  peak |Fy| wheel 1  " << r.peak_fy_n
      << " N\n";
  out << "  max |dF|           " << r.max_force_error_n << " N  ("
      << 100.0 * r.max_force_error_n / std::max(r.max_force_n, 1.0) << " % of the largest force "
      << r.max_force_n << " N; quantisation 0.5 N + float)\n";
  out << "  max |dMz|          " << r.max_moment_error_nm << " N m\n";
  if (s.node.node.wheelsets > 0) {
    out << "  max |d delta_r|    " << r.max_delta_r_error_mm
        << " mm (vs the table; quantisation 0.0005 mm)\n";
  }
  out << "\ntrace  " << r.trace_csv.string() << "\n";
  if (!r.plot_png.empty()) out << "plot   " << r.plot_png.string() << "\n";
}

}  // namespace tread::host
