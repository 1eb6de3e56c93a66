#include "fit/mf_staged_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "fit/mf_aligning_fit.hpp"
#include "fit/mf_coefficients.hpp"
#include "fit/mf_combined_fit.hpp"
#include "fit/mf_lateral_fit.hpp"
#include "fit/mf_longitudinal_fit.hpp"
#include "fit/slope_signs.hpp"
#include "io/text_line.hpp"
#include "plot/gnuplot.hpp"
#include "tir/tir_units.hpp"

namespace tread::fit {
namespace {

using host::text::format_significant;

const char* model_name(MfFitModel m) {
  return m == MfFitModel::mf61 ? "mf61" : "pac2002";
}

void append(std::vector<std::string>& a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
}

}  // namespace

std::vector<std::string> fitted_keys(MfFitModel model) {
  std::vector<std::string> keys = longitudinal_keys();
  keys.emplace_back("PDX3");
  keys.insert(keys.end(), kLateralCoefficientNames.begin(), kLateralCoefficientNames.end());
  append(keys, lateral_camber_keys(model));
  append(keys, aligning_keys());
  append(keys, aligning_camber_keys(model));
  append(keys, combined_fx_keys(model));
  append(keys, combined_fy_keys(model));
  append(keys, combined_mz_keys());
  return keys;
}

mf::MfParameters<double> neutral_start(const mf::MfParameters<double>& p, MfFitModel model) {
  mf::MfParameters<double> out = p;
  for (const auto& key : fitted_keys(model)) {
    const int i = required_coefficient_index(key);
    coefficient(out, i) = coefficient_default(i);
  }
  return out;
}

void check_model(const mf::MfParameters<double>& p, MfFitModel model, const std::string& origin) {
  const bool mf6 = p.fit_type == mf::FitType::mf61 || p.fit_type == mf::FitType::mf62;
  if (model == MfFitModel::mf61 && !mf6) {
    throw std::runtime_error(origin + ": --model mf61 needs an MF 6.1/6.2 (FITTYP 61/62) start");
  }
  if (model == MfFitModel::pac2002 && mf6) {
    throw std::runtime_error(origin +
                             ": --model pac2002 needs a PAC2002 (no FITTYP) or MF 5.2 (FITTYP 6 "
                             "or 21) start");
  }
}

StagedFit fit_mf_staged(const MeasurementSet& data, const mf::MfParameters<double>& start,
                        MfFitModel model, const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  StagedFit fit;
  fit.model = model;
  fit.params = start;
  fit.levels = load_levels(data);
  auto run = [&](std::vector<StageResult> stages) {
    for (auto& s : stages) {
      if (progress) {
        progress(s.name + ": " + std::to_string(s.points) + " points, " +
                 std::to_string(s.iterations) + " iterations" +
                 (s.converged ? "" : " (iteration limit)") + ", " +
                 format_significant(s.seconds, 3) + " s");
        if (!s.held.empty()) {
          std::string keys;
          for (const std::string& k : s.held) keys += " " + k;
          progress("warning: " + s.name +
                   ": not determined by these points, held at their values before the stage:" +
                   keys + (fit.levels.size() < 2 ? " (one load level)" : ""));
        }
      }
      fit.stages.push_back(std::move(s));
    }
  };
  run(fit_longitudinal_stages(data, fit.levels, model, fit.params, progress));
  run(fit_lateral_stages(data, fit.levels, model, fit.params, progress));
  run(fit_aligning_stages(data, fit.levels, model, fit.params, progress));
  run(fit_combined_stages(data, fit.levels, model, fit.params, progress));
  // Second pass of Mz: s·Fx acts on the pure-slip points too (see refit_aligning_pure).
  bool ssz_fitted = false;
  for (const auto& s : fit.stages) ssz_fitted = ssz_fitted || s.name == "Mz (combined)";
  if (ssz_fitted) {
    run(refit_aligning_pure(data, fit.levels, model, fit.params, progress));
    run(fit_combined_mz(data, fit.levels, fit.params, progress, "Mz (combined, pass 2)"));
  }
  fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return fit;
}

void set_fitted_coefficients(tir::TirFile& file, const StagedFit& fit) {
  for (const auto& stage : fit.stages) {
    for (std::size_t i = 0; i < stage.keys.size(); ++i) {
      const int index = required_coefficient_index(stage.keys[i]);
      tir::set_si(file, coefficient_section(index), stage.keys[i], coefficient(fit.params, index));
    }
  }
}

std::vector<ChannelLoadStats> final_stats(const StagedFit& fit, const MeasurementSet& data) {
  std::vector<StageSample> all;
  for (FitChannel c : {FitChannel::fx, FitChannel::fy, FitChannel::mz}) {
    const auto s =
        select_samples(data, fit.levels, c, [](const MeasurementPoint&) { return true; });
    all.insert(all.end(), s.begin(), s.end());
  }
  return channel_load_stats(fit.params, all, fit.levels);
}

double fitted_slope(const StagedFit& fit, FitChannel channel, double fz_n, double vx_mps) {
  StageSample q;
  q.fz_n = fz_n;
  q.vx_mps = vx_mps;
  q.channel = channel;
  const double h = 1e-5;
  double& slip = channel == FitChannel::fx ? q.kappa : q.alpha_rad;
  slip = h;
  const double up = model_value(fit.params, q);
  slip = -h;
  return (up - model_value(fit.params, q)) / (2 * h);
}

std::vector<std::string> sign_doubts(const StagedFit& fit, const MeasurementSet& data) {
  std::vector<std::string> doubts;
  if (data.points.empty()) return doubts;
  const double vx = data.points.front().vx_mps;
  for (const FitChannel c : {FitChannel::fx, FitChannel::fy, FitChannel::mz}) {
    const bool measured = std::any_of(data.points.begin(), data.points.end(), [c](const auto& m) {
      return std::isfinite(c == FitChannel::fx ? m.fx_n : c == FitChannel::fy ? m.fy_n : m.mz_nm);
    });
    if (!measured) continue;
    const SlopeOf which = c == FitChannel::fx   ? SlopeOf::fx_kappa
                          : c == FitChannel::fy ? SlopeOf::fy_alpha
                                                : SlopeOf::mz_alpha;
    std::vector<LoadSlope> slopes;
    for (const double fz : fit.levels) slopes.push_back({fz, fitted_slope(fit, c, fz, vx)});
    std::string d = slope_sign_doubt(which, slopes);
    if (!d.empty()) doubts.push_back(std::move(d));
  }
  return doubts;
}

void write_staged_report(const StagedFit& fit, const MeasurementSet& data, std::ostream& out) {
  out << "# tread fit --model " << model_name(fit.model) << " (staged)\n\nInput: `" << data.source
      << "`, " << data.points.size() << " points; load levels (N):";
  for (double fz : fit.levels) out << ' ' << format_significant(fz, 6);
  out << ". Whole staged fit: " << format_significant(fit.seconds, 3)
      << " s. Each stage is a separate Ceres problem through the templated core (combined slip, "
         "limits on); standard deviations from the Ceres covariance scaled by the residual "
         "variance. A coefficient the stage's points do not determine (without effect, or "
         "acting only as the coefficients before it do, e.g. a load term at one load level) is "
         "held at its start value: \"held\".\n";
  for (const auto& s : fit.stages) {
    out << "\n## " << s.name << "\n\n"
        << s.points << " points, " << s.iterations << " iterations ("
        << (s.converged ? "converged" : "stopped at the iteration limit") << "), "
        << format_significant(s.seconds, 3)
        << " s.\n\n| coefficient | start | fitted | standard deviation |\n"
        << "|---|---|---|---|\n";
    for (std::size_t i = 0; i < s.keys.size(); ++i) {
      const bool held = std::find(s.held.begin(), s.held.end(), s.keys[i]) != s.held.end();
      out << "| " << s.keys[i] << " | " << format_significant(s.start[i]) << " | "
          << format_significant(s.values[i]) << " | "
          << (held ? std::string("held (not determined by these points)")
                   : format_significant(s.stddev[i], 3))
          << " |\n";
    }
    out << "\n| channel | Fz (N) | points | RMS | R² |\n|---|---|---|---|---|\n";
    for (const auto& st : s.stats) {
      out << "| " << fit_channel_name(st.channel) << " | " << format_significant(st.fz_n, 6)
          << " | " << st.points << " | " << format_significant(st.rms, 4) << ' '
          << fit_channel_unit(st.channel) << " | " << format_significant(st.r2, 6) << " |\n";
    }
  }
  out << "\n## Characteristics of the fitted set (gamma = 0, Vx of the data)\n\n"
      << "| Fz (N) | Kx = dFx/dkappa (N) | Kalpha = dFy/dalpha (N/rad) | mux = max abs(Fx)/Fz "
         "(abs(kappa) <= 0.3) | muy = max abs(Fy)/Fz (abs(alpha) <= 0.3 rad) "
         "|\n|---|---|---|---|---|\n";
  const double vx = data.points.empty() ? 16.7 : data.points.front().vx_mps;
  for (double fz : fit.levels) {
    StageSample q;
    q.fz_n = fz;
    q.vx_mps = vx;
    auto at = [&](FitChannel c, double kappa, double alpha) {
      q.channel = c;
      q.kappa = kappa;
      q.alpha_rad = alpha;
      return model_value(fit.params, q);
    };
    const double kx = fitted_slope(fit, FitChannel::fx, fz, vx);
    const double ky = fitted_slope(fit, FitChannel::fy, fz, vx);
    double fx_peak = 0.0, fy_peak = 0.0;
    for (int i = -300; i <= 300; ++i) {
      fx_peak = std::max(fx_peak, std::fabs(at(FitChannel::fx, i * 1e-3, 0)));
      fy_peak = std::max(fy_peak, std::fabs(at(FitChannel::fy, 0, i * 1e-3)));
    }
    out << "| " << format_significant(fz, 6) << " | " << format_significant(kx) << " | "
        << format_significant(ky) << " | " << format_significant(fx_peak / fz, 4) << " | "
        << format_significant(fy_peak / fz, 4) << " |\n";
  }
  out << "\n## Final coefficient set on every point\n\n| channel | Fz (N) | points | RMS | R² |\n"
      << "|---|---|---|---|---|\n";
  for (const auto& st : final_stats(fit, data)) {
    out << "| " << fit_channel_name(st.channel) << " | " << format_significant(st.fz_n, 6) << " | "
        << st.points << " | " << format_significant(st.rms, 4) << ' '
        << fit_channel_unit(st.channel) << " | " << format_significant(st.r2, 6) << " |\n";
  }
}

void plot_staged_fit(const StagedFit& fit, const MeasurementSet& data, const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (std::size_t level = 0; level < fit.levels.size(); ++level) {
    for (FitChannel c : {FitChannel::fx, FitChannel::fy, FitChannel::mz}) {
      const bool fx = c == FitChannel::fx;
      // Pure sweeps of this channel at this load, grouped by camber (rounded to 1e-3 rad).
      std::map<long, std::vector<StageSample>> by_camber;
      const auto samples = select_samples(data, fit.levels, c, [fx](const MeasurementPoint& m) {
        return fx ? std::fabs(m.alpha_rad) <= kPureTolerance : std::fabs(m.kappa) <= kPureTolerance;
      });
      for (const auto& s : samples) {
        if (s.load_level == level) by_camber[std::lround(s.gamma_rad * 1000.0)].push_back(s);
      }
      if (by_camber.empty()) continue;
      const std::string stem = std::string(fit_channel_name(c)) + "_Fz" +
                               std::to_string(std::lround(fit.levels[level])) + "N";
      const std::filesystem::path png = std::filesystem::path(dir) / (stem + ".png");
      const std::filesystem::path dat = std::filesystem::path(dir) / (stem + ".dat");
      std::string plot = "plot ";
      int index = 0;
      {
        std::ofstream d(dat);
        d << std::setprecision(10);
        int colour = 1;
        for (const auto& [mrad, points] : by_camber) {
          double lo = 1e9, hi = -1e9;
          for (const auto& s : points) {
            const double x = fx ? s.kappa : s.alpha_rad;
            d << x << ' ' << s.value << '\n';
            lo = std::min(lo, x);
            hi = std::max(hi, x);
          }
          d << "\n\n";
          StageSample q = points.front();
          for (int i = 0; i <= 300; ++i) {
            const double x = lo + (hi - lo) * i / 300.0;
            (fx ? q.kappa : q.alpha_rad) = x;
            d << x << ' ' << model_value(fit.params, q) << '\n';
          }
          d << "\n\n";
          const std::string g =
              "gamma " + format_significant(static_cast<double>(mrad) / 1000.0, 3);
          if (index > 0) plot += ", ";
          plot += host::format_script(
              "%s index %d with points pt 7 ps 0.4 lc %d title '%s measured', '' index %d with "
              "lines lw 2 lc %d title '%s fit'",
              host::gnuplot_quote(dat.string()).c_str(), index, colour, g.c_str(), index + 1,
              colour, g.c_str());
          index += 2;
          ++colour;
        }
        if (!d) throw std::runtime_error(dat.string() + ": cannot write");
      }
      std::string script = host::gnuplot_terminal(png.string(), 1000, 700);
      script += "set output " + host::gnuplot_quote(png.string()) + "\n";
      script += "set termoption noenhanced\nset grid\nset key outside right\n";
      script +=
          "set title " +
          host::gnuplot_quote(std::string(fit_channel_name(c)) + (fx ? "(kappa)" : "(alpha)") +
                              " at Fz = " + format_significant(fit.levels[level], 5) +
                              " N: measured and fitted (" + model_name(fit.model) + ")") +
          "\n";
      script += std::string("set xlabel ") + (fx ? "'kappa (-)'" : "'alpha (rad)'") + "\n";
      script +=
          std::string("set ylabel '") + fit_channel_name(c) + " (" + fit_channel_unit(c) + ")'\n";
      script += plot + "\n";
      host::run_gnuplot_with_data(script, "plot " + png.string(), dat);
    }
  }
}

}  // namespace tread::fit
