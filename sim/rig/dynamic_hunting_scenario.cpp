#include "rig/dynamic_hunting_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "contact/contact_setup.hpp"
#include "contact/equivalent_conicity.hpp"
#include "contact/klingel.hpp"
#include "plot/gnuplot.hpp"
#include "runtime/node_runtime.hpp"

namespace tread::host {
namespace {

int phase_code(DynamicHuntingScenario::Phase p) {
  return static_cast<int>(p);
}

const char* phase_name(DynamicHuntingScenario::Phase p) {
  switch (p) {
    case DynamicHuntingScenario::Phase::low_speed:
      return "low speed";
    case DynamicHuntingScenario::Phase::scan:
      return "scan";
    case DynamicHuntingScenario::Phase::refine:
      return "refine";
    case DynamicHuntingScenario::Phase::below:
      return "below";
    case DynamicHuntingScenario::Phase::above:
      return "above";
    case DynamicHuntingScenario::Phase::done:
      break;
  }
  return "done";
}

}  // namespace

DynamicHuntingScenario::DynamicHuntingScenario(const DynamicHuntingSettings& settings)
    : settings_(settings),
      contact_(build_wheelset_contact(settings.setup)),
      reference_(
          contact_.table(-settings.setup.ymax_mm, settings.setup.ymax_mm, settings.setup.step_mm)),
      model_(contact_, settings.setup, settings.params) {
  if (settings_.scan_speeds_m_s.size() < 2) {
    throw std::runtime_error("dynamic-hunting: need at least two scan speeds");
  }
  // The linear analysis needs a contact that is smooth at the centre: compare the slope of delta r
  // at y = 0 with its secant over the stability runs' amplitude.
  const double h = 0.05;
  const double a = settings_.initial_y_mm;
  const double local =
      (contact::delta_r_at(reference_, h) - contact::delta_r_at(reference_, -h)) / (2.0 * h);
  const double secant =
      (contact::delta_r_at(reference_, a) - contact::delta_r_at(reference_, -a)) / (2.0 * a);
  if (!(std::abs(local - secant) <= 0.25 * std::abs(secant))) {
    std::ostringstream n;
    n.precision(3);
    n << "delta r is not smooth at the centre (slope " << local << " at y = 0, " << secant
      << " over +-" << a << " mm): the linearisation does not describe the motion";
    smoothness_note_ = n.str();
  }
  critical_linear_ =
      linear_critical_speed(settings_.params, model_, 1.0, 1.5 * settings_.scan_speeds_m_s.back());
  if (std::isfinite(critical_linear_)) {
    mode_at_critical_ = least_damped_mode(settings_.params, model_, critical_linear_);
  }
  start(Phase::low_speed, settings_.low_speed_m_s, settings_.low_speed_amplitude_mm,
        settings_.low_speed_run_s);
}

std::string DynamicHuntingScenario::description() const {
  std::ostringstream s;
  const rail::WheelsetParams<double>& p = settings_.params;
  s << "suspended wheelset (m " << p.mass_kg << " kg, I " << p.yaw_inertia_kgm2 << " kg m^2, k_y "
    << p.lateral_stiffness_n_per_m / 1e6 << " MN/m, k_psi " << p.yaw_stiffness_nm_per_rad / 1e6
    << " MN m/rad, Q " << p.wheel_load_n / 1000.0 << " kN) on the node's wheel-rail forces ("
    << settings_.setup.wheelset_profile << ", Polach '" << settings_.setup.friction << "')";
  return s.str();
}

double DynamicHuntingScenario::duration_s() const {
  // Upper bound: every run of the plan; finished() ends it when the plan is done.
  const DynamicHuntingSettings& s = settings_;
  return s.low_speed_run_s +
         s.run_s * static_cast<double>(s.scan_speeds_m_s.size() +
                                       static_cast<std::size_t>(s.refinements) + 1U) +
         s.above_run_s + 1.0;
}

void DynamicHuntingScenario::start(Phase phase, double speed_m_s, double y0_mm, double duration_s) {
  phase_ = phase;
  speed_ = speed_m_s;
  run_duration_ = duration_s;
  run_t_ = 0.0;
  state_ = rail::WheelsetState<double>{};
  state_.q(0) = y0_mm * 1e-3;
  const WheelsetContactModel::Linearisation lin = model_.linearise(speed_m_s);
  jacobian_ = rail::system_matrix(settings_.params, lin.stiffness, lin.damping);
  force_.setZero();
  answer_[0] = answer_[1] = proto::RailWheelOutput{};
  run_time_.clear();
  run_y_.clear();
  const auto n = static_cast<std::size_t>(duration_s * 1000.0) + 2;
  run_time_.reserve(n);
  run_y_.reserve(n);
  current_ = Run{};
  current_.phase = phase;
  current_.speed_m_s = speed_m_s;
  current_.max_y_over_q = -std::numeric_limits<double>::infinity();
  current_.min_nadal_margin = std::numeric_limits<double>::infinity();
}

void DynamicHuntingScenario::inputs(double /*t_s*/, proto::RigData& data) {
  if (phase_ == Phase::done) {
    return;
  }
  proto::WheelsetInput& w = data.wheelsets[0];
  w.lateral_mm = static_cast<float>(state_.q(0) * 1000.0);
  w.yaw_rad = static_cast<float>(state_.q(1));
  w.yaw_valid = true;
  w.speed_mps = static_cast<float>(speed_);
  w.lateral_velocity_mps = static_cast<float>(state_.v(0));
  w.yaw_rate_radps = static_cast<float>(state_.v(1));
  w.load_left_n = static_cast<float>(settings_.params.wheel_load_n);
  w.load_right_n = static_cast<float>(settings_.params.wheel_load_n);
}

void DynamicHuntingScenario::advance(const proto::RigData& /*inputs_seen*/,
                                     const proto::NodeData& answers, double dt_s) {
  if (phase_ == Phase::done) {
    return;
  }
  // A stale or flagged answer carries no forces: hold the last ones rather than drop them.
  const bool fresh = answers.rail_wheels[0].status == 0U && answers.rail_wheels[1].status == 0U;
  if (fresh) {
    answer_[0] = answers.rail_wheels[0];
    answer_[1] = answers.rail_wheels[1];
    force_ = generalised_force(answer_[0], answer_[1], settings_.params.half_contact_base_m);
  } else {
    ++current_.held_answers;
  }
  rail::wheelset_step(state_, force_, jacobian_, settings_.params, dt_s);
  run_t_ += dt_s;
  run_time_.push_back(run_t_);
  run_y_.push_back(state_.q(0) * 1000.0);
  // Y/Q and the margin of fresh answers only: the zeros before the run's first answer, and the
  // held values of a flagged one (perhaps saturated at the signal's limit), are not measurements.
  if (fresh) {
    current_.answered = true;
    for (const proto::RailWheelOutput& w : answer_) {
      current_.max_y_over_q = std::max(current_.max_y_over_q, static_cast<double>(w.y_over_q));
      current_.min_nadal_margin =
          std::min(current_.min_nadal_margin, static_cast<double>(w.nadal_margin));
    }
  }
  row_ = {static_cast<double>(runs_.size()),
          static_cast<double>(phase_code(phase_)),
          speed_,
          run_t_,
          state_.q(0) * 1000.0,
          state_.q(1) * 1000.0,
          static_cast<double>(answer_[0].y_n),
          static_cast<double>(answer_[1].y_n),
          static_cast<double>(answer_[0].y_over_q),
          static_cast<double>(answer_[1].y_over_q),
          static_cast<double>(answer_[0].nadal_margin),
          static_cast<double>(answer_[1].nadal_margin)};
  if (run_t_ >= run_duration_ - 1e-9) {
    finish_run();
  }
}

double DynamicHuntingScenario::growth_rate(const std::vector<double>& t,
                                           const std::vector<double>& y, double cap_mm) {
  // The largest |y| of each half swing (between zero crossings) after the first one (the start is
  // not on the mode's shape), up to cap_mm (beyond it the flanges bound a growing motion: no longer
  // the small-amplitude growth); ln(peak) against time by least squares. A fast growth that passes
  // the cap within three half swings is measured on its first three.
  std::vector<double> pt;
  std::vector<double> pa;
  double peak = 0.0;
  double peak_t = 0.0;
  int crossings = 0;
  for (std::size_t i = 1; i < y.size(); ++i) {
    if (std::abs(y[i]) > peak) {
      peak = std::abs(y[i]);
      peak_t = t[i];
    }
    if ((y[i - 1] < 0.0) != (y[i] < 0.0)) {
      if (++crossings > 1 && peak > 0.0 && (peak < cap_mm || pt.size() < 3)) {
        pt.push_back(peak_t);
        pa.push_back(std::log(peak));
      }
      peak = 0.0;
    }
  }
  if (pt.size() < 3) {
    return std::nan("");
  }
  double st = 0.0;
  double sa = 0.0;
  double stt = 0.0;
  double sta = 0.0;
  for (std::size_t k = 0; k < pt.size(); ++k) {
    st += pt[k];
    sa += pa[k];
    stt += pt[k] * pt[k];
    sta += pt[k] * pa[k];
  }
  const auto n = static_cast<double>(pt.size());
  return (n * sta - st * sa) / (n * stt - st * st);
}

double DynamicHuntingScenario::wavelength(const std::vector<double>& t,
                                          const std::vector<double>& y, double speed_m_s) {
  // Mean time between upward zero crossings (interpolated): the symmetric wheelset oscillates about
  // y = 0 however fast the motion decays.
  std::vector<double> up;
  for (std::size_t i = 1; i < y.size(); ++i) {
    if (y[i - 1] < 0.0 && y[i] >= 0.0) {
      up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-y[i - 1]) / (y[i] - y[i - 1]));
    }
  }
  if (up.size() < 2) {
    return std::nan("");
  }
  return speed_m_s * (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

void DynamicHuntingScenario::finish_run() {
  Run& r = current_;
  r.growth_rate_per_s = growth_rate(run_time_, run_y_, 3.0 * settings_.initial_y_mm);
  r.wavelength_m = wavelength(run_time_, run_y_, speed_);
  for (std::size_t i = 0; i < run_time_.size(); ++i) {
    if (run_time_[i] > run_duration_ - 1.0) {
      r.amplitude_mm = std::max(r.amplitude_mm, std::abs(run_y_[i]));
    }
  }
  runs_.push_back(r);
  const DynamicHuntingSettings& s = settings_;
  const double sigma = r.growth_rate_per_s;
  switch (r.phase) {
    case Phase::low_speed:
      start(Phase::scan, s.scan_speeds_m_s[0], s.initial_y_mm, s.run_s);
      return;
    case Phase::scan:
      if (std::isfinite(sigma) && sigma > 0.0 && scan_index_ > 0 && lo_v_ > 0.0) {
        hi_v_ = r.speed_m_s;
        hi_sigma_ = sigma;
      } else if (std::isfinite(sigma) && sigma <= 0.0) {
        lo_v_ = r.speed_m_s;
        lo_sigma_ = sigma;
      }
      if (hi_v_ > 0.0) {
        refined_ = 0;
        const double v = lo_v_ - lo_sigma_ * (hi_v_ - lo_v_) / (hi_sigma_ - lo_sigma_);
        start(Phase::refine, v, s.initial_y_mm, s.run_s);
        return;
      }
      if (++scan_index_ < s.scan_speeds_m_s.size()) {
        start(Phase::scan, s.scan_speeds_m_s[scan_index_], s.initial_y_mm, s.run_s);
        return;
      }
      break;  // no sign change on the scan: no critical speed found
    case Phase::refine:
      if (std::isfinite(sigma)) {
        // Illinois: halve the retained end's value when the same end is kept twice.
        if (sigma > 0.0) {
          hi_v_ = r.speed_m_s;
          hi_sigma_ = sigma;
          if (side_ == 1) lo_sigma_ *= 0.5;
          side_ = 1;
        } else {
          lo_v_ = r.speed_m_s;
          lo_sigma_ = sigma;
          if (side_ == -1) hi_sigma_ *= 0.5;
          side_ = -1;
        }
      }
      critical_ = lo_v_ - lo_sigma_ * (hi_v_ - lo_v_) / (hi_sigma_ - lo_sigma_);
      if (++refined_ < s.refinements) {
        start(Phase::refine, critical_, s.initial_y_mm, s.run_s);
        return;
      }
      start(Phase::below, s.below_factor * critical_, s.initial_y_mm, s.run_s);
      return;
    case Phase::below:
      start(Phase::above, s.above_factor * critical_, s.initial_y_mm, s.above_run_s);
      return;
    case Phase::above:
    case Phase::done:
      break;
  }
  phase_ = Phase::done;
}

double DynamicHuntingScenario::klingel_wavelength_m() const {
  for (const Run& r : runs_) {
    if (r.phase != Phase::low_speed) {
      continue;
    }
    try {
      contact::ConicityOptions o;
      o.r0_mm = model_.r_spin_mm();
      o.e0_mm = settings_.params.half_contact_base_m * 1000.0;
      const double tan_gamma_e =
          contact::equivalent_conicity(reference_, settings_.low_speed_amplitude_mm, o).tan_gamma_e;
      return contact::klingel_wavelength_mm(tan_gamma_e, o.r0_mm, o.e0_mm) / 1000.0;
    } catch (const std::domain_error&) {
      return std::nan("");
    }
  }
  return std::nan("");
}

std::vector<std::string> DynamicHuntingScenario::trace_columns() const {
  return {"run",           "phase",          "speed_mps",         "run_t_s",
          "y_mm",          "yaw_mrad",       "y_left_n",          "y_right_n",
          "y_over_q_left", "y_over_q_right", "nadal_margin_left", "nadal_margin_right"};
}

void DynamicHuntingScenario::trace_values(std::vector<double>& row) const {
  row.insert(row.end(), row_.begin(), row_.end());
}

std::string DynamicHuntingScenario::no_critical_speed_reason() const {
  // The scan runs tell why no sign change was found: all decayed, all grew, or the growth rate
  // could not be measured (fewer than three half swings: a slow or a flange-bound motion).
  int decayed = 0;
  int grew = 0;
  int unmeasured = 0;
  for (const Run& r : runs_) {
    if (r.phase != Phase::scan) continue;
    if (!std::isfinite(r.growth_rate_per_s)) {
      ++unmeasured;
    } else if (r.growth_rate_per_s > 0.0) {
      ++grew;
    } else {
      ++decayed;
    }
  }
  const std::vector<double>& v = settings_.scan_speeds_m_s;
  std::ostringstream s;
  s.precision(4);
  s << "not found on the scan " << v.front() << "..." << v.back() << " m/s: ";
  if (grew == 0 && unmeasured == 0) {
    s << "the motion decayed in every run (stable up to " << v.back() << " m/s)";
  } else if (decayed == 0 && unmeasured == 0) {
    s << "the motion grew in every run (unstable from " << v.front() << " m/s)";
  } else {
    s << decayed << " runs decayed, " << grew << " grew, " << unmeasured
      << " without three half swings to measure a growth rate, and no decaying run below a "
         "growing one";
  }
  if (std::isfinite(critical_linear_) && critical_linear_ > v.back()) {
    s << "; the linear model's " << critical_linear_ << " m/s is above the scan";
  }
  return s.str();
}

std::vector<ScenarioMetric> DynamicHuntingScenario::metrics() const {
  std::vector<ScenarioMetric> m;
  const double dev = 100.0 * (critical_ / critical_linear_ - 1.0);
  std::ostringstream note;
  note.precision(3);
  if (std::isfinite(critical_)) {
    note << "from " << runs_.size() << " runs with the node in the loop";
    if (std::isfinite(dev)) note << "; linear " << (dev >= 0 ? "+" : "") << dev << " % away";
  } else {
    note << no_critical_speed_reason();
  }
  m.push_back({"critical_speed", critical_, "m/s", note.str()});
  std::ostringstream lin;
  lin.precision(4);
  if (std::isfinite(critical_linear_)) {
    lin << "eigenvalues of the linearised model; hunting " << mode_at_critical_.frequency_hz
        << " Hz, wavelength " << mode_at_critical_.wavelength_m << " m";
  } else {
    lin << "not found: no eigenvalue of the linearised model crosses to growth below "
        << 1.5 * settings_.scan_speeds_m_s.back() << " m/s";
  }
  m.push_back({"critical_speed_linear", critical_linear_, "m/s", lin.str()});
  std::string target;
  if (!std::isfinite(dev)) {
    target = "not computed: a critical speed is missing (above)";
  } else {
    target = std::abs(dev) <= 5.0 ? "target: within 5 %: met" : "target: within 5 %: NOT met";
    if (!smoothness_note_.empty()) target += "; " + smoothness_note_;
  }
  m.push_back({"critical_speed_difference", dev, "%", target});
  for (const Run& r : runs_) {
    if (r.phase == Phase::low_speed) {
      const double klingel = klingel_wavelength_m();
      const double d = 100.0 * (r.wavelength_m / klingel - 1.0);
      std::ostringstream n;
      n.precision(4);
      n << "at " << r.speed_m_s << " m/s; ";
      if (!std::isfinite(r.wavelength_m)) {
        n << "not measured: fewer than two upward zero crossings in the "
          << settings_.low_speed_run_s << " s run (" << r.speed_m_s * settings_.low_speed_run_s
          << " m of track); ";
      }
      if (std::isfinite(klingel)) {
        n << "Klingel " << klingel << " m at the EN 15302 conicity";
        if (std::isfinite(d)) n << ", " << (d >= 0 ? "+" : "") << d << " %";
      } else {
        n << "no Klingel wavelength: no restoring delta r at " << settings_.low_speed_amplitude_mm
          << " mm";
      }
      m.push_back({"low_speed_wavelength", r.wavelength_m, "m", n.str()});
    }
    if (r.phase == Phase::below) {
      m.push_back({"growth_rate_below", r.growth_rate_per_s, "1/s",
                   "at 0.9 x critical: the motion decays"});
    }
    if (r.phase == Phase::above) {
      m.push_back({"growth_rate_above", r.growth_rate_per_s, "1/s",
                   "at 1.1 x critical, from a 1 mm start"});
      m.push_back({"limit_cycle_amplitude", r.amplitude_mm, "mm", "last second at 1.1 x critical"});
      if (!r.answered) {
        const char* none = "not measured: every answer of the run was flagged (stale, saturated)";
        m.push_back({"max_y_over_q", std::nan(""), "-", none});
        m.push_back({"min_nadal_margin", std::nan(""), "-", none});
      } else {
        // Flagged answers (stale, or a value beyond its signal's range) are held, not measured:
        // how many, so that a limit cycle whose peaks were flagged is not read as measured.
        const std::string held = r.held_answers == 0
                                     ? ""
                                     : "; " + std::to_string(r.held_answers) +
                                           " cycles' answers flagged (stale, saturated): not in it";
        m.push_back({"max_y_over_q", r.max_y_over_q, "-", "in the limit cycle" + held});
        m.push_back(
            {"min_nadal_margin", r.min_nadal_margin, "-",
             (r.min_nadal_margin < 0.0
                  ? "Nadal's limit minus Y/Q: BELOW 0, beyond Nadal's limit (flange climbing)"
                  : "Nadal's limit minus Y/Q") +
                 held});
      }
    }
  }
  return m;
}

std::vector<std::filesystem::path> DynamicHuntingScenario::plot(
    const std::filesystem::path& trace_csv, const std::filesystem::path& out_dir) const {
  // The stability runs' growth rates beside the trace, for the second panel.
  const std::filesystem::path runs_csv = out_dir / "dynamic-hunting-runs.csv";
  {
    std::ofstream out(runs_csv);
    out << "phase,speed_mps,growth_rate_per_s,amplitude_mm\n";
    for (const Run& r : runs_) {
      out << phase_name(r.phase) << ',' << r.speed_m_s << ',' << r.growth_rate_per_s << ','
          << r.amplitude_mm << '\n';
    }
  }
  const std::filesystem::path png = out_dir / "dynamic-hunting.png";
  const std::string data = gnuplot_quote(trace_csv.string());
  const std::string runs = gnuplot_quote(runs_csv.string());
  const std::string below = std::to_string(phase_code(Phase::below));
  const std::string above = std::to_string(phase_code(Phase::above));
  std::ostringstream v;
  v.precision(4);
  v << "critical speed " << critical_ << " m/s (node in the loop), " << critical_linear_
    << " m/s (linear)";
  std::string script = gnuplot_terminal(png.string(), 1500, 500);
  script += "set output " + gnuplot_quote(png.string()) + "\n";
  script += "set datafile separator ','\nset grid\nset multiplot layout 1,3 title " +
            gnuplot_quote("Dynamic hunting: " + v.str()) + "\n";
  const bool demonstrated =
      std::any_of(runs_.begin(), runs_.end(), [](const Run& r) { return r.phase == Phase::above; });
  if (demonstrated) {
    script +=
        "set xlabel 't (s)'\nset ylabel 'y (mm)'\nset title 'below and above the critical "
        "speed'\nplot " +
        data + " using (column('phase')==" + below +
        " ? column('run_t_s') : 1/0):'y_mm' with lines lw 2 title '0.9 x critical', " + data +
        " using (column('phase')==" + above +
        " ? column('run_t_s') : 1/0):'y_mm' with lines lw 2 title '1.1 x critical'\n";
  } else {
    script +=
        "set xlabel 't (s)'\nset ylabel 'y (mm)'\nset title 'every run (no critical speed "
        "found)'\nplot " +
        data + " using 'run_t_s':'y_mm' with lines title 'y'\n";
  }
  script +=
      "set xlabel 'V (m/s)'\nset ylabel 'growth rate (1/s)'\nset title 'stability runs'\n"
      "plot " +
      runs +
      " using 2:3 with points pt 7 ps 1.2 title 'runs (node in the loop)', 0 with "
      "lines lc rgb 'black' notitle\n";
  if (demonstrated) {
    script += "set xlabel 't (s)'\nset ylabel 'Y/Q'\nset title 'Y/Q in the limit cycle'\nplot " +
              data + " using (column('phase')==" + above +
              " ? column('run_t_s') : 1/0):'y_over_q_left' with lines title 'left', " + data +
              " using (column('phase')==" + above +
              " ? column('run_t_s') : 1/0):'y_over_q_right' with lines title 'right'\n";
  }
  script += "unset multiplot\n";
  run_gnuplot(script, png.string());
  return {png};
}

}  // namespace tread::host
