#include "rig/hunting_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "contact/contact_setup.hpp"
#include "contact/equivalent_conicity.hpp"
#include "contact/klingel.hpp"
#include "plot/gnuplot.hpp"

namespace tread::host {

HuntingScenario::HuntingScenario(const HuntingSettings& settings) : settings_(settings) {
  if (settings_.wheelsets == 0 || settings_.wheelsets > proto::kMaxWheelsets) {
    throw std::runtime_error("hunting: needs 1.." + std::to_string(proto::kMaxWheelsets) +
                             " wheelsets");
  }
  const contact::ContactSetup setup = contact::parse_wheelset_profile(settings_.wheelset_profile);
  reference_ =
      contact::build_contact(setup).table(-settings_.ymax_mm, settings_.ymax_mm, settings_.step_mm);
  WheelsetHuntingParams p;
  p.speed_mps = settings_.speed_mps;
  // The wheelset given: r0 the mean of its wheels' nominal radii, e0 = b2b/2 + 70 mm.
  p.r0_mm = contact::nominal_r0_mm(setup);
  p.e0_mm = contact::half_contact_base_mm(setup);
  // The centre of the oscillation (EN 15302 Annex B: midway between its turning points; an
  // asymmetric pair need not oscillate about 0 nor about the root of delta r).
  centre_mm_ = contact::equivalent_conicity(reference_, settings_.amplitude_mm[0]).centre_y_mm;
  // Long enough for at least four periods of the slowest wheelset (low conicity: long waves).
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    contact::ConicityOptions o;
    o.r0_mm = p.r0_mm;
    o.e0_mm = p.e0_mm;
    const double wavelength_m =
        contact::equivalent_conicity(reference_, settings_.amplitude_mm[j], o).wavelength_mm /
        1000.0;
    settings_.duration_s = std::max(settings_.duration_s, 4.5 * wavelength_m / p.speed_mps);
  }
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    // Start at the upper turning point of the kinematic oscillation of that amplitude.
    wheelsets_[j] = WheelsetHunting(
        p, contact::equivalent_conicity(reference_, settings_.amplitude_mm[j]).y_max_mm);
    const auto n = static_cast<std::size_t>(settings_.duration_s * 1000.0) + 1;
    y_trace_[j].reserve(n);
  }
  t_trace_.reserve(static_cast<std::size_t>(settings_.duration_s * 1000.0) + 1);
}

std::string HuntingScenario::description() const {
  std::ostringstream s;
  s << static_cast<int>(settings_.wheelsets) << " free wheelset(s) hunting at "
    << settings_.speed_mps * 3.6 << " km/h, initial amplitude";
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    s << (j == 0 ? " " : " / ") << settings_.amplitude_mm[j];
  }
  s << " mm (" << settings_.wheelset_profile << ")";
  return s.str();
}

void HuntingScenario::inputs(double /*t_s*/, proto::RigData& data) {
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    data.wheelsets[j] = {static_cast<float>(wheelsets_[j].y_mm()),
                         static_cast<float>(wheelsets_[j].yaw_rad()), true};
  }
}

void HuntingScenario::advance(const proto::RigData& /*inputs_seen*/, const proto::NodeData& answers,
                              double dt_s) {
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    // A stale or disabled answer carries no delta r: hold the last one rather than steer by zeros.
    if (answers.wheelsets[j].status == 0U) {
      delta_r_mm_[j] = static_cast<double>(answers.wheelsets[j].delta_r_mm);
    }
    wheelsets_[j].step(delta_r_mm_[j], dt_s);
    y_trace_[j].push_back(wheelsets_[j].y_mm());
  }
  t_s_ += dt_s;
  t_trace_.push_back(t_s_);
}

std::vector<std::string> HuntingScenario::trace_columns() const {
  std::vector<std::string> c;
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    const std::string k = std::to_string(j);
    c.insert(c.end(), {"ws" + k + "_y_mm", "ws" + k + "_yaw_mrad", "ws" + k + "_delta_r_mm"});
  }
  return c;
}

void HuntingScenario::trace_values(std::vector<double>& row) const {
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    row.push_back(wheelsets_[j].y_mm());
    row.push_back(wheelsets_[j].yaw_rad() * 1000.0);
    row.push_back(delta_r_mm_[j]);
  }
}

HuntingScenario::Result HuntingScenario::result(std::size_t wheelset) const {
  Result r;
  r.motion = analyse_hunting(t_trace_, y_trace_.at(wheelset), settings_.speed_mps);
  r.tan_gamma_e = std::nan("");
  r.klingel_wavelength_m = std::nan("");
  if (r.motion.valid) {
    try {
      contact::ConicityOptions o;
      o.e0_mm = wheelsets_[wheelset].params().e0_mm;
      o.r0_mm = wheelsets_[wheelset].params().r0_mm;
      r.tan_gamma_e =
          contact::equivalent_conicity(reference_, r.motion.amplitude_mm, o).tan_gamma_e;
      r.klingel_wavelength_m =
          contact::klingel_wavelength_mm(r.tan_gamma_e, o.r0_mm, o.e0_mm) / 1000.0;
    } catch (const std::domain_error&) {
      // amplitude outside the table or no restoring delta r: leave NaN
    }
  }
  return r;
}

std::vector<ScenarioMetric> HuntingScenario::metrics() const {
  std::vector<ScenarioMetric> m;
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    const Result r = result(j);
    const std::string w = "wheelset " + std::to_string(j) + " ";
    if (!r.motion.valid) {
      // Fewer than two full periods: no wavelength, and no amplitude of a periodic motion.
      const std::string why = "not measured: " + std::to_string(r.motion.periods) +
                              " full periods in the run, two needed";
      m.push_back({w + "amplitude", std::nan(""), "mm", why});
      m.push_back({w + "hunting wavelength", std::nan(""), "m", why});
      m.push_back({w + "equivalent conicity", std::nan(""), "-", why});
      m.push_back({w + "wavelength vs Klingel", std::nan(""), "%", why});
      continue;
    }
    m.push_back({w + "amplitude", r.motion.amplitude_mm, "mm", ""});
    m.push_back({w + "hunting wavelength", r.motion.wavelength_m, "m",
                 std::to_string(r.motion.periods) + " periods"});
    if (!std::isfinite(r.klingel_wavelength_m)) {
      std::ostringstream why;
      why.precision(3);
      why << "not computed: no EN 15302 conicity at " << r.motion.amplitude_mm
          << " mm (outside the contact table, or no restoring delta r)";
      m.push_back({w + "equivalent conicity", r.tan_gamma_e, "-", why.str()});
      m.push_back({w + "wavelength vs Klingel", std::nan(""), "%", why.str()});
      continue;
    }
    m.push_back({w + "equivalent conicity", r.tan_gamma_e, "-", "EN 15302 at that amplitude"});
    const double dev = 100.0 * (r.motion.wavelength_m / r.klingel_wavelength_m - 1.0);
    std::ostringstream note;
    note.precision(3);
    note << "Klingel " << r.klingel_wavelength_m << " m, " << (dev >= 0 ? "+" : "") << dev << " %";
    m.push_back({w + "wavelength vs Klingel", dev, "%", note.str()});
  }
  return m;
}

std::vector<std::filesystem::path> HuntingScenario::plot(
    const std::filesystem::path& trace_csv, const std::filesystem::path& out_dir) const {
  const std::filesystem::path png = out_dir / "hunting.png";
  const std::string data = gnuplot_quote(trace_csv.string());
  std::string script = gnuplot_terminal(png.string(), 1200, 500);
  script += "set output " + gnuplot_quote(png.string()) + "\n";
  script += "set datafile separator ','\nset grid\nset multiplot layout 1,2 title " +
            gnuplot_quote("Kinematic hunting: " + description()) + "\n";
  script += "set xlabel 't (s)'\nset ylabel 'y (mm)'\nset title 'lateral displacement'\nplot ";
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    const std::string k = std::to_string(j);
    script += std::string(j == 0 ? "" : ", ") + data + " using 't_s':'ws" + k +
              "_y_mm' with lines lw 2 title 'wheelset " + k + "'";
  }
  script +=
      "\nset xlabel 'y (mm)'\nset ylabel 'delta r (mm)'\nset title 'working points on the "
      "delta r function (node answers over CAN)'\nplot ";
  for (std::size_t j = 0; j < settings_.wheelsets; ++j) {
    const std::string k = std::to_string(j);
    script += std::string(j == 0 ? "" : ", ") + data + " using 'ws" + k + "_y_mm':'ws" + k +
              "_delta_r_mm' every 7 with points pt 7 ps 0.4 title 'wheelset " + k + "'";
  }
  script += "\nunset multiplot\n";
  run_gnuplot(script, png.string());
  return {png};
}

}  // namespace tread::host
