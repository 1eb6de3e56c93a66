#include "rig/vehicle_scenario.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "mf/mf_evaluate.hpp"
#include "plot/gnuplot.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "vehicle/manoeuvre_runner.hpp"
#include "vehicle/tyre_function.hpp"

namespace tread::host {

struct VehicleScenario::Impl {
  mf::MfParameters<double> tyre_params;
  vehicle::VehicleParams params;
  vehicle::TyreFunction tyre;
  std::unique_ptr<vehicle::Manoeuvre> manoeuvre;
  std::unique_ptr<vehicle::VehicleModel> model;
  double dt_s{1e-3};
  std::filesystem::path tir;
  mutable std::vector<vehicle::ManoeuvreResult> reference;  ///< computed on first use
};

VehicleScenario::VehicleScenario(const std::string& manoeuvre, const std::filesystem::path& tir,
                                 double dt_s, const mf::MfOptions& tyre_options)
    : impl_(std::make_unique<Impl>()) {
  impl_->tyre_params = tyre::load_mf_parameters(tir).params;
  impl_->params.wheel_radius_m = impl_->tyre_params.unloaded_radius_m;
  impl_->tyre = vehicle::mf_tyre_function(impl_->tyre_params, tyre_options);
  impl_->dt_s = dt_s;
  impl_->tir = tir;
  impl_->manoeuvre = vehicle::make_manoeuvre(manoeuvre, impl_->params, impl_->tyre);
  if (!impl_->manoeuvre) {
    throw std::invalid_argument("unknown manoeuvre '" + manoeuvre + "'");
  }
  impl_->manoeuvre->reset();
  impl_->model =
      std::make_unique<vehicle::VehicleModel>(impl_->params, impl_->manoeuvre->initial_state());
  trace_.reserve(static_cast<std::size_t>(impl_->manoeuvre->duration_s() / dt_s) + 2);
}

VehicleScenario::~VehicleScenario() = default;

std::string VehicleScenario::name() const {
  return std::string(impl_->manoeuvre->name());
}

std::string VehicleScenario::description() const {
  const auto n = impl_->manoeuvre->name();
  std::string what = n == "braking"      ? "straight-line braking from 100 km/h with ABS"
                     : n == "step-steer" ? "ISO 7401 step steer at 80 km/h to 4 m/s^2"
                                         : "sine with dwell (FMVSS 126) at 80 km/h, 0.7 Hz";
  return what + ", 4-wheel vehicle (1500 kg) on the node's tyres";
}

double VehicleScenario::duration_s() const {
  return impl_->manoeuvre->duration_s();
}

bool VehicleScenario::finished() const {
  return impl_->manoeuvre->finished(impl_->model->state().t_s, impl_->model->state());
}

void VehicleScenario::inputs(double /*t_s*/, proto::RigData& data) {
  const vehicle::VehicleState& s = impl_->model->state();
  pending_ = {};
  pending_.t_s = s.t_s;
  pending_.state = s;
  pending_.inputs = impl_->model->wheel_inputs();
  pending_.controls = impl_->manoeuvre->controls(s.t_s, impl_->dt_s, s);
  const auto f = [](double v) { return static_cast<float>(v); };
  for (std::size_t i = 0; i < vehicle::kWheelCount; ++i) {
    const vehicle::WheelKinematics& k = pending_.inputs[i];
    data.wheels[i] = {
        f(k.kappa), f(k.alpha_rad), f(k.gamma_rad), f(k.fz_n), f(k.vx_mps), f(k.omega_radps), true};
  }
}

void VehicleScenario::advance(const proto::RigData& /*inputs_seen*/, const proto::NodeData& answers,
                              double dt_s) {
  for (std::size_t i = 0; i < vehicle::kWheelCount; ++i) {
    const proto::WheelOutput& w = answers.wheels[i];
    // Stale or disabled answers carry zeros: the vehicle then rolls without tyre forces, as it
    // would on a rig whose tyre model dropped out.
    pending_.forces[i] = {static_cast<double>(w.fx_n), static_cast<double>(w.fy_n),
                          static_cast<double>(w.mz_nm)};
  }
  impl_->model->step(pending_.forces, pending_.controls, dt_s);
  trace_.push_back(pending_);
}

std::vector<std::string> VehicleScenario::trace_columns() const {
  std::vector<std::string> c = {"vx_mps", "vy_mps", "yaw_rate_radps", "ax_mps2", "ay_mps2",
                                "x_m",    "y_m",    "steer_wheel_deg"};
  for (std::size_t i = 0; i < vehicle::kWheelCount; ++i) {
    const std::string k = std::to_string(i);
    c.insert(c.end(), {"kappa_" + k, "alpha_rad_" + k, "Fz_N_" + k, "omega_radps_" + k,
                       "brake_Nm_" + k, "Fx_N_" + k, "Fy_N_" + k, "Mz_Nm_" + k});
  }
  return c;
}

void VehicleScenario::trace_values(std::vector<double>& row) const {
  // The state after the step and the exchange (inputs, answers) that drove it.
  const vehicle::VehicleState& s = impl_->model->state();
  row.insert(row.end(), {s.vx_mps, s.vy_mps, s.yaw_rate_radps, s.ax_mps2, s.ay_mps2, s.x_m, s.y_m,
                         s.steer_wheel_rad * 180.0 / std::numbers::pi});
  for (std::size_t i = 0; i < vehicle::kWheelCount; ++i) {
    const vehicle::WheelKinematics& k = pending_.inputs[i];
    const vehicle::WheelForces& f = pending_.forces[i];
    row.insert(row.end(), {k.kappa, k.alpha_rad, k.fz_n, k.omega_radps,
                           pending_.controls.brake_torque_nm[i], f.fx_n, f.fy_n, f.mz_nm});
  }
}

std::vector<vehicle::ManoeuvreResult> VehicleScenario::results() const {
  vehicle::Trace t = trace_;
  // The final state as the last sample, as the in-process runner records it.
  vehicle::TraceSample last;
  last.t_s = impl_->model->state().t_s;
  last.state = impl_->model->state();
  last.inputs = impl_->model->wheel_inputs();
  if (!trace_.empty()) last.forces = trace_.back().forces;
  t.push_back(last);
  return impl_->manoeuvre->results(t);
}

std::vector<vehicle::ManoeuvreResult> VehicleScenario::reference_results() const {
  if (impl_->reference.empty()) {
    auto m = vehicle::make_manoeuvre(impl_->manoeuvre->name(), impl_->params, impl_->tyre);
    impl_->reference = vehicle::run_manoeuvre(*m, impl_->params, impl_->tyre, impl_->dt_s).results;
  }
  return impl_->reference;
}

std::vector<ScenarioMetric> VehicleScenario::metrics() const {
  const std::vector<vehicle::ManoeuvreResult> can = results();
  const std::vector<vehicle::ManoeuvreResult> ref = reference_results();
  std::vector<ScenarioMetric> m;
  for (const vehicle::ManoeuvreResult& r : can) {
    const double r_ref = vehicle::result_value(ref, r.name);
    std::ostringstream note;
    note.precision(5);
    note << "tyre in double: " << r_ref;
    if (r.name == "yaw_rate_ratio_1_00") note << "  (UN R140 with ESC: < 35 %; no ESC here)";
    if (r.name == "yaw_rate_ratio_1_75") note << "  (UN R140 with ESC: < 20 %; no ESC here)";
    m.push_back({r.name, r.value, r.unit, note.str()});
  }
  return m;
}

std::vector<std::filesystem::path> VehicleScenario::plot(
    const std::filesystem::path& trace_csv, const std::filesystem::path& out_dir) const {
  const std::string n = name();
  const std::filesystem::path png = out_dir / (n + ".png");
  // The force curves the working points lie on: the tyre in double at the static front load.
  const std::filesystem::path curves = out_dir / (n + "_curves.dat");
  {
    std::ofstream out(curves);
    const double fz = impl_->params.static_front_wheel_load_n();
    for (int k = -300; k <= 300; ++k) {
      mf::MfInput<double> in;
      in.fz_n = fz;
      in.vx_mps = 20.0;
      in.kappa = 0.001 * k;
      const double fx = mf::evaluate(impl_->tyre_params, in, {}).fx_n;
      in.kappa = 0.0;
      in.alpha_rad = 0.0005 * k;
      const double fy = mf::evaluate(impl_->tyre_params, in, {}).fy_n;
      out << 0.001 * k << ',' << fx << ',' << 0.0005 * k << ',' << fy << '\n';
    }
  }
  const std::string data = gnuplot_quote(trace_csv.string());
  const std::string cur = gnuplot_quote(curves.string());
  std::string script = gnuplot_terminal(png.string(), 1200, 900);
  script += "set output " + gnuplot_quote(png.string()) + "\n";
  script += "set datafile separator ','\nset grid\nset key left bottom\n";
  script += "set multiplot layout 2,2 title " + gnuplot_quote("tread rig: " + description()) + "\n";
  const bool braking = n == "braking";
  if (braking) {
    script += "set xlabel 't (s)'\nset ylabel 'speed (m/s), decel (m/s^2)'\nset title 'body'\n";
    script += "plot " + data + " using 't_s':'vx_mps' with lines lw 2 title 'vx', " + data +
              " using 't_s':(-column('ax_mps2')) with lines title '-ax'\n";
    script += "set xlabel 't (s)'\nset ylabel 'kappa (-)'\nset title 'wheel slip'\n";
    script += "plot " + data + " using 't_s':'kappa_0' with lines title 'front left', " + data +
              " using 't_s':'kappa_2' with lines title 'rear left'\n";
    script += "set xlabel 't (s)'\nset ylabel 'Fz (N)'\nset title 'wheel loads (load transfer)'\n";
    script += "plot " + data + " using 't_s':'Fz_N_0' with lines title 'front left', " + data +
              " using 't_s':'Fz_N_2' with lines title 'rear left'\n";
    script +=
        "set xlabel 'kappa (-)'\nset ylabel 'Fx (N)'\nset xrange [-0.3:0.05]\n"
        "set title 'working points on the Fx(kappa) curve'\n";
    script += "plot " + cur + " using 1:2 with lines lw 2 title 'MF at static front load', " +
              data +
              " using 'kappa_0':'Fx_N_0' every 3 with points pt 7 ps 0.3 title 'front left "
              "over CAN', " +
              data +
              " using 'kappa_2':'Fx_N_2' every 3 with points pt 7 ps 0.3 title 'rear left over "
              "CAN'\n";
  } else {
    script += "set xlabel 't (s)'\nset ylabel 'deg, rad/s x 100'\nset title 'driver and yaw'\n";
    script += "plot " + data +
              " using 't_s':(column('steer_wheel_deg')/10) with lines title "
              "'steering wheel / 10 (deg)', " +
              data +
              " using 't_s':(100*column('yaw_rate_radps')) with lines lw 2 title 'yaw rate x 100 "
              "(rad/s)'\n";
    script += "set xlabel 't (s)'\nset ylabel 'ay (m/s^2)'\nset title 'lateral acceleration'\n";
    script += "plot " + data + " using 't_s':'ay_mps2' with lines lw 2 notitle\n";
    script += "set xlabel 't (s)'\nset ylabel 'Fz (N)'\nset title 'wheel loads (load transfer)'\n";
    script += "plot " + data + " using 't_s':'Fz_N_0' with lines title 'front left', " + data +
              " using 't_s':'Fz_N_1' with lines title 'front right', " + data +
              " using 't_s':'Fz_N_2' with lines title 'rear left', " + data +
              " using 't_s':'Fz_N_3' with lines title 'rear right'\n";
    script +=
        "set xlabel 'alpha (rad)'\nset ylabel 'Fy (N)'\nset xrange [-0.15:0.15]\n"
        "set title 'working points on the Fy(alpha) curve'\n";
    script += "plot " + cur + " using 3:4 with lines lw 2 title 'MF at static front load', " +
              data +
              " using 'alpha_rad_0':'Fy_N_0' every 3 with points pt 7 ps 0.3 title 'front left "
              "over CAN', " +
              data +
              " using 'alpha_rad_3':'Fy_N_3' every 3 with points pt 7 ps 0.3 title 'rear right "
              "over CAN'\n";
  }
  script += "unset multiplot\n";
  run_gnuplot_with_data(script, png.string(), curves);
  return {png};
}

}  // namespace tread::host
