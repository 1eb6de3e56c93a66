#include "rig/curving_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "contact/contact_setup.hpp"
#include "plot/gnuplot.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::host {
namespace {

constexpr double kGravity = 9.81;

}  // namespace

CurvingScenario::CurvingScenario(const CurvingSettings& settings)
    : settings_(settings),
      contact_(build_wheelset_contact(settings.setup)),
      model_(contact_, settings.setup, settings.params) {
  if (settings_.radii_m.empty()) {
    throw std::runtime_error("curving: no curve radii");
  }
  // The step's matrix: the straight track's linearisation (it only steadies the step).
  const WheelsetContactModel::Linearisation lin = model_.linearise(settings_.speed_m_s);
  jacobian_ = rail::system_matrix(settings_.params, lin.stiffness, lin.damping);
}

std::string CurvingScenario::description() const {
  std::ostringstream s;
  s << "suspended wheelset through right-hand curves of " << settings_.radii_m.front() << " to "
    << settings_.radii_m.back() << " m at " << settings_.speed_m_s * 3.6
    << " km/h, cant deficiency " << settings_.uncompensated_acceleration_m_s2
    << " m/s^2, on the node's wheel-rail forces (" << settings_.setup.wheelset_profile
    << ", Polach '" << settings_.setup.friction << "')";
  return s.str();
}

double CurvingScenario::duration_s() const {
  return static_cast<double>(settings_.radii_m.size()) *
             (settings_.transition_s + settings_.hold_s) +
         1.0;
}

double CurvingScenario::curvature_per_m() const {
  if (curve_ >= settings_.radii_m.size()) {
    return 0.0;
  }
  const double ramp = std::min(1.0, t_curve_ / settings_.transition_s);
  return ramp / settings_.radii_m[curve_];
}

double CurvingScenario::cant_deficiency_force_n() const {
  // Outward (+y, toward the outer rail): the axle's mass times the uncompensated acceleration,
  // ramped in with the curvature.
  if (curve_ >= settings_.radii_m.size()) {
    return 0.0;
  }
  const double ramp = std::min(1.0, t_curve_ / settings_.transition_s);
  return ramp * 2.0 * settings_.params.wheel_load_n / kGravity *
         settings_.uncompensated_acceleration_m_s2;
}

void CurvingScenario::inputs(double /*t_s*/, proto::RigData& data) {
  if (finished()) {
    return;
  }
  proto::WheelsetInput& w = data.wheelsets[0];
  w.lateral_mm = static_cast<float>(state_.q(0) * 1000.0);
  w.yaw_rad = static_cast<float>(state_.q(1));
  w.yaw_valid = true;
  w.speed_mps = static_cast<float>(settings_.speed_m_s);
  w.lateral_velocity_mps = static_cast<float>(state_.v(0));
  // Yaw rate over ground: the track turns right (clockwise) at V / R, plus the wheelset's own.
  w.yaw_rate_radps = static_cast<float>(-settings_.speed_m_s * curvature_per_m() + state_.v(1));
  w.load_left_n = static_cast<float>(settings_.params.wheel_load_n);
  w.load_right_n = static_cast<float>(settings_.params.wheel_load_n);
}

void CurvingScenario::advance(const proto::RigData& /*inputs_seen*/, const proto::NodeData& answers,
                              double dt_s) {
  if (finished()) {
    return;
  }
  if (answers.rail_wheels[0].status == 0U && answers.rail_wheels[1].status == 0U) {
    answer_[0] = answers.rail_wheels[0];
    answer_[1] = answers.rail_wheels[1];
    force_ = generalised_force(answer_[0], answer_[1], settings_.params.half_contact_base_m);
  }
  const double f_q = cant_deficiency_force_n();
  rail::Vector2<double> applied = force_;
  applied(0) += f_q;
  rail::wheelset_step(state_, applied, jacobian_, settings_.params, dt_s);
  t_curve_ += dt_s;

  const proto::RailWheelOutput& outer = answer_[0];
  const proto::RailWheelOutput& inner = answer_[1];
  const double n_total = static_cast<double>(outer.n1_n + outer.n2_n);
  const double equilibrium =
      force_(0) + f_q - settings_.params.lateral_stiffness_n_per_m * state_.q(0);
  Steady now;
  now.radius_m = settings_.radii_m[curve_];
  now.y_mm = state_.q(0) * 1000.0;
  now.yaw_mrad = state_.q(1) * 1000.0;
  now.outer_y_n = static_cast<double>(outer.y_n);
  now.outer_q_n = static_cast<double>(outer.q_n);
  now.outer_y_over_q = static_cast<double>(outer.y_over_q);
  now.outer_nadal_margin = static_cast<double>(outer.nadal_margin);
  now.inner_y_over_q = static_cast<double>(inner.y_over_q);
  now.flange_share = n_total > 0.0 ? static_cast<double>(outer.n2_n) / n_total : 0.0;
  now.equilibrium_n = equilibrium;
  sum_.max_outer_y_over_q = std::max(sum_.max_outer_y_over_q, now.outer_y_over_q);
  row_ = {now.radius_m,
          curvature_per_m() * 1000.0,
          f_q,
          now.y_mm,
          now.yaw_mrad,
          now.outer_y_n,
          now.outer_y_over_q,
          now.outer_nadal_margin,
          now.inner_y_over_q,
          now.flange_share,
          equilibrium};
  const double end = settings_.transition_s + settings_.hold_s;
  if (t_curve_ > end - 1.0) {
    sum_.y_mm += now.y_mm;
    sum_.yaw_mrad += now.yaw_mrad;
    sum_.outer_y_n += now.outer_y_n;
    sum_.outer_q_n += now.outer_q_n;
    sum_.outer_y_over_q += now.outer_y_over_q;
    sum_.outer_nadal_margin += now.outer_nadal_margin;
    sum_.inner_y_over_q += now.inner_y_over_q;
    sum_.flange_share += now.flange_share;
    sum_.equilibrium_n += now.equilibrium_n;
    ++samples_;
  }
  if (t_curve_ >= end - 1e-9) {
    const double n = samples_ > 0 ? static_cast<double>(samples_) : 1.0;
    Steady s;
    s.radius_m = settings_.radii_m[curve_];
    s.y_mm = sum_.y_mm / n;
    s.yaw_mrad = sum_.yaw_mrad / n;
    s.outer_y_n = sum_.outer_y_n / n;
    s.outer_q_n = sum_.outer_q_n / n;
    s.outer_y_over_q = sum_.outer_y_over_q / n;
    s.outer_nadal_margin = sum_.outer_nadal_margin / n;
    s.inner_y_over_q = sum_.inner_y_over_q / n;
    s.flange_share = sum_.flange_share / n;
    s.equilibrium_n = sum_.equilibrium_n / n;
    s.max_outer_y_over_q = sum_.max_outer_y_over_q;
    done_.push_back(s);
    // The next curve starts from straight track again, the wheelset centred.
    ++curve_;
    t_curve_ = 0.0;
    state_ = rail::WheelsetState<double>{};
    sum_ = Steady{};
    samples_ = 0;
  }
}

std::vector<std::string> CurvingScenario::trace_columns() const {
  return {"radius_m",
          "curvature_per_km",
          "cant_deficiency_force_n",
          "y_mm",
          "yaw_mrad",
          "outer_y_n",
          "outer_y_over_q",
          "outer_nadal_margin",
          "inner_y_over_q",
          "outer_flange_share",
          "equilibrium_n"};
}

void CurvingScenario::trace_values(std::vector<double>& row) const {
  row.insert(row.end(), row_.begin(), row_.end());
}

std::vector<ScenarioMetric> CurvingScenario::metrics() const {
  std::vector<ScenarioMetric> m;
  double worst_equilibrium = 0.0;
  const double f_q =
      2.0 * settings_.params.wheel_load_n / kGravity * settings_.uncompensated_acceleration_m_s2;
  for (const Steady& s : done_) {
    std::ostringstream r;
    r << "R" << static_cast<int>(std::lround(s.radius_m)) << "_";
    std::ostringstream note;
    note.precision(3);
    note << "y " << s.y_mm << " mm, attack " << s.yaw_mrad << " mrad, Y " << s.outer_y_n / 1000.0
         << " kN, flange share " << 100.0 * s.flange_share << " %, margin " << s.outer_nadal_margin;
    m.push_back({r.str() + "outer_y_over_q", s.outer_y_over_q, "-", note.str()});
    worst_equilibrium = std::max(worst_equilibrium, std::abs(s.equilibrium_n));
  }
  double min_margin = 1e9;
  double max_yq = 0.0;
  for (const Steady& s : done_) {
    min_margin = std::min(min_margin, s.outer_nadal_margin);
    max_yq = std::max(max_yq, s.max_outer_y_over_q);
  }
  if (!done_.empty()) {
    m.push_back({"min_nadal_margin", min_margin, "-",
                 min_margin < 0.0 ? "steady curving, outer wheel: BELOW 0, beyond Nadal's limit "
                                    "(flange climbing)"
                                  : "steady curving, outer wheel"});
    m.push_back({"max_y_over_q", max_yq, "-", "outer wheel, run-in included"});
  }
  if (!done_.empty()) {
    // The widest curve against pure rolling: the outer wheel larger by 2 e0 r0 / R.
    const Steady& w = done_.front();
    const double needed_mm =
        2.0 * settings_.params.half_contact_base_m * model_.r_spin_mm() / w.radius_m;
    std::ostringstream pr;
    pr.precision(3);
    pr << "at R " << w.radius_m << " m; pure rolling needs delta r = 2 e0 r0 / R = " << needed_mm
       << " mm";
    m.push_back({"widest_curve_displacement", w.y_mm, "mm", pr.str()});
  }
  std::ostringstream eq;
  eq.precision(3);
  eq << "of the cant-deficiency force " << f_q / 1000.0 << " kN (steady state)";
  m.push_back({"lateral_equilibrium_error", worst_equilibrium, "N", eq.str()});
  return m;
}

std::vector<std::filesystem::path> CurvingScenario::plot(
    const std::filesystem::path& trace_csv, const std::filesystem::path& out_dir) const {
  const std::filesystem::path steady_csv = out_dir / "curving-steady.csv";
  {
    std::ofstream out(steady_csv);
    out << "radius_m,y_mm,yaw_mrad,outer_y_over_q,nadal_limit,inner_y_over_q,flange_share\n";
    for (const Steady& s : done_) {
      out << s.radius_m << ',' << s.y_mm << ',' << s.yaw_mrad << ',' << s.outer_y_over_q << ','
          << s.outer_y_over_q + s.outer_nadal_margin << ',' << s.inner_y_over_q << ','
          << s.flange_share << '\n';
    }
  }
  const std::filesystem::path png = out_dir / "curving.png";
  const std::string data = gnuplot_quote(trace_csv.string());
  const std::string steady = gnuplot_quote(steady_csv.string());
  std::string script = gnuplot_terminal(png.string(), 1400, 500);
  script += "set output " + gnuplot_quote(png.string()) + "\n";
  std::ostringstream title;
  title << "Curving at " << settings_.speed_m_s * 3.6 << " km/h, cant deficiency "
        << settings_.uncompensated_acceleration_m_s2 << " m/s^2 ("
        << settings_.setup.wheelset_profile << "), node in the loop";
  script += "set datafile separator ','\nset grid\nset multiplot layout 1,2 title " +
            gnuplot_quote(title.str()) + "\n";
  script +=
      "set xlabel 'curve radius (m)'\nset ylabel 'Y/Q'\nset logscale x\n"
      "set title 'steady curving: outer wheel against Nadal'\nplot " +
      steady + " using 1:4 with linespoints pt 7 lw 2 title 'outer wheel Y/Q', " + steady +
      " using 1:5 with lines dt 2 lw 2 title 'Nadal limit', " + steady +
      " using 1:6 with linespoints pt 6 title 'inner wheel Y/Q'\n";
  script +=
      "unset logscale x\nset xlabel 't (s)'\nset ylabel 'y (mm), Y/Q x 10'\n"
      "set title 'every curve: displacement and outer Y/Q'\nplot " +
      data + " using 't_s':'y_mm' with lines lw 2 title 'y (mm)', " + data +
      " using 't_s':(10*column('outer_y_over_q')) with lines title 'outer Y/Q x 10'\n";
  script += "unset multiplot\n";
  run_gnuplot(script, png.string());
  return {png};
}

}  // namespace tread::host
