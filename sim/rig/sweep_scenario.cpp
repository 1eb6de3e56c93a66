#include "rig/sweep_scenario.hpp"

#include <algorithm>
#include <cmath>

#include "plot/gnuplot.hpp"

namespace tread::host {

std::string SweepScenario::description() const {
  return "tyre test machine: wheel 0 kappa sweep, 1 alpha sweep, 2 combined, 3 load sweep; "
         "wheelsets: lateral displacement sine";
}

void SweepScenario::inputs(double t_s, proto::RigData& data) {
  const proto::RigData d = rig_.inputs_at(t_s, 0);
  for (std::size_t i = 0; i < wheels_; ++i) {
    data.wheels[i] = d.wheels[i];
  }
  for (std::size_t j = 0; j < wheelsets_; ++j) {
    data.wheelsets[j] = d.wheelsets[j];
  }
}

void SweepScenario::advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
                            double /*dt_s*/) {
  seen_ = inputs_seen;
  answers_ = answers;
  if (wheels_ > 0 && answers.wheels[0].status == 0U) {
    peak_fx_n_ = std::max(peak_fx_n_, static_cast<double>(std::abs(answers.wheels[0].fx_n)));
  }
  if (wheels_ > 1 && answers.wheels[1].status == 0U) {
    peak_fy_n_ = std::max(peak_fy_n_, static_cast<double>(std::abs(answers.wheels[1].fy_n)));
  }
}

std::vector<std::string> SweepScenario::trace_columns() const {
  std::vector<std::string> c;
  for (std::size_t i = 0; i < wheels_; ++i) {
    const std::string k = std::to_string(i);
    c.insert(c.end(),
             {"kappa_" + k, "alpha_rad_" + k, "Fz_N_" + k, "Fx_N_" + k, "Fy_N_" + k, "Mz_Nm_" + k});
  }
  for (std::size_t j = 0; j < wheelsets_; ++j) {
    const std::string k = std::to_string(j);
    c.insert(c.end(), {"ws" + k + "_y_mm", "ws" + k + "_delta_r_mm"});
  }
  return c;
}

void SweepScenario::trace_values(std::vector<double>& row) const {
  const auto d = [](float v) { return static_cast<double>(v); };
  for (std::size_t i = 0; i < wheels_; ++i) {
    const proto::WheelInput& in = seen_.wheels[i];
    const proto::WheelOutput& out = answers_.wheels[i];
    row.insert(row.end(),
               {d(in.kappa), d(in.alpha_rad), d(in.fz_n), d(out.fx_n), d(out.fy_n), d(out.mz_nm)});
  }
  for (std::size_t j = 0; j < wheelsets_; ++j) {
    row.insert(row.end(), {d(seen_.wheelsets[j].lateral_mm), d(answers_.wheelsets[j].delta_r_mm)});
  }
}

std::vector<ScenarioMetric> SweepScenario::metrics() const {
  std::vector<ScenarioMetric> m;
  if (wheels_ > 0) m.push_back({"peak |Fx| wheel 0 (kappa sweep)", peak_fx_n_, "N", ""});
  if (wheels_ > 1) m.push_back({"peak |Fy| wheel 1 (alpha sweep)", peak_fy_n_, "N", ""});
  return m;
}

std::vector<std::filesystem::path> SweepScenario::plot(const std::filesystem::path& trace_csv,
                                                       const std::filesystem::path& out_dir) const {
  if (wheels_ < 2) {
    return {};
  }
  const std::filesystem::path png = out_dir / "sweep.png";
  const std::string data = gnuplot_quote(trace_csv.string());
  std::string script = gnuplot_terminal(png.string(), 1200, 900);
  script += "set output " + gnuplot_quote(png.string()) + "\n";
  script += "set datafile separator ','\nset grid\n";
  script +=
      "set multiplot layout 2,2 title 'tread: tyre test machine sweeps, node answers over CAN'\n";
  const auto panel = [&](const std::string& x, const std::string& y, const std::string& xl,
                         const std::string& yl, const std::string& title) {
    script += "set xlabel '" + xl + "'\nset ylabel '" + yl + "'\nset title '" + title + "'\n";
    script +=
        "plot " + data + " using '" + x + "':'" + y + "' every 5 with points pt 7 ps 0.3 notitle\n";
  };
  panel("kappa_0", "Fx_N_0", "kappa (-)", "Fx (N)", "wheel 0: longitudinal sweep");
  panel("alpha_rad_1", "Fy_N_1", "alpha (rad)", "Fy (N)", "wheel 1: lateral sweep");
  panel("alpha_rad_1", "Mz_Nm_1", "alpha (rad)", "Mz (N m)", "wheel 1: aligning moment");
  if (wheelsets_ > 0) {
    panel("ws0_y_mm", "ws0_delta_r_mm", "y (mm)", "delta r (mm)", "wheelset 0: delta r");
  } else if (wheels_ > 3) {
    panel("Fz_N_3", "Fy_N_3", "Fz (N)", "Fy (N)", "wheel 3: load sweep at alpha 0.05");
  }
  script += "unset multiplot\n";
  run_gnuplot(script, png.string());
  return {png};
}

}  // namespace tread::host
