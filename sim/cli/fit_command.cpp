// `tread fit`: fit Magic Formula coefficients to measurements (CSV or TYDEX).
//  - --model simple (Stage 1): the basic formula per load for Fx(kappa), Fy(alpha), Mz(alpha);
//    writes the constants (CSV), a Markdown report and plots of measurement vs fit.
//  - --model mf61 | pac2002 (Stage 2): the staged fit of the MF 6.1 or PAC2002 (also MF 5.2)
//    coefficient set (sim/fit/mf_staged_fit.hpp) into a copy of --start START.tir; report, plots.
//  - --synthesize FROM.tir: writes synthetic measurements (the test-rig grid of
//    sim/fit/synthetic_measurements.hpp, Gaussian noise --noise × peak, seeded by --seed) as CSV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "fit/measurement.hpp"
#include "fit/mf61_from_mf52.hpp"
#include "fit/mf_coefficients.hpp"
#include "fit/mf_staged_fit.hpp"
#include "fit/simple_fit.hpp"
#include "fit/slope_signs.hpp"
#include "fit/solver_log.hpp"
#include "fit/synthetic_measurements.hpp"
#include "io/text_line.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_units.hpp"
#include "tyre/input_table.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::cli {
namespace {

struct FitCliState {
  std::string model = "simple";
  std::string input, output, report, plots, start, synthesize;
  unsigned seed = 1;
  double noise = 0.01;
  bool asymmetric_e = false;
  bool neutral_start = false;
  std::string convention = "iso-w";
};

tyre::SignConvention convention_of(const FitCliState& s) {
  return *tyre::parse_sign_convention(s.convention);
}

void progress_line(const std::string& line) {
  std::cerr << "tread fit: " << line << "\n";
}

void run_synthesize(const FitCliState& s) {
  if (!(s.noise >= 0.0 && s.noise <= 1.0)) {
    // A share of each channel's peak: 1e308 wrote rows of inf.
    throw std::runtime_error("--noise " + tir::format_number(s.noise) +
                             ": the noise level is a share of each channel's peak, from 0 to 1");
  }
  if (std::filesystem::path(s.output).extension() == ".tir") {
    // Measurements as CSV under a .tir name: a file every .tir reader would refuse.
    throw std::runtime_error("--output " + s.output +
                             ": --synthesize writes measurements as CSV, not a .tir");
  }
  const tyre::MfTirParameters truth = tyre::load_mf_parameters(s.synthesize);
  fit::SyntheticGrid grid;
  grid.noise_rel = s.noise;
  const fit::MeasurementSet data = fit::synthesize_measurements(truth.params, grid, s.seed);
  std::ofstream out(s.output);
  out << "# synthetic measurements (ISO-W axes, SI units) from " << s.synthesize << ", noise "
      << s.noise << " x peak per channel and load, seed " << s.seed << "\n";
  fit::write_measurement_csv(data, out);
  if (!out) throw std::runtime_error(s.output + ": cannot write");
  std::cerr << "tread fit: " << data.points.size() << " synthetic points -> " << s.output << "\n";
}

// Points with Fz ≤ 0 are not fitted (or the whole file is refused: see fit::drop_unloaded).
void drop_unloaded(fit::MeasurementSet& data) {
  std::size_t first_line = 0;
  const std::size_t dropped = fit::drop_unloaded(data, first_line);
  if (dropped > 0) {
    std::cerr << "tread fit: warning: " << dropped << " points with Fz ≤ 0 (a wheel off the "
              << "ground) are not fitted; the first at " << data.source << ":" << first_line
              << "\n";
  }
}

std::string significant(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// The loads' median against the tyre's nominal load (the start file's FNOMIN), or against the
// loads of any tyre without one: loads in kN under an N column fitted a μ of 76 686 and wrote it
// with exit 0.
void check_load_scale(const fit::MeasurementSet& data, const mf::MfParameters<double>* start) {
  if (data.points.empty()) return;
  std::vector<double> fz;
  fz.reserve(data.points.size());
  for (const auto& p : data.points) fz.push_back(p.fz_n);
  std::nth_element(fz.begin(), fz.begin() + static_cast<std::ptrdiff_t>(fz.size() / 2), fz.end());
  const double median = fz[fz.size() / 2];
  const std::string hint =
      ": loads in kN or lbf under a column read as N? (name the column Fz_kN, or give a units "
      "row under the header)";
  if (start != nullptr) {
    constexpr double kFactor = 20.0;
    if (median < start->fnomin_n / kFactor || median > start->fnomin_n * kFactor) {
      throw std::runtime_error(data.source + ": the loads' median is " + significant(median) +
                               " N, " + significant(median / start->fnomin_n) +
                               " × the start file's FNOMIN (" + significant(start->fnomin_n) +
                               " N)" + hint);
    }
    return;
  }
  if (median < 50.0 || median > 1e6) {
    std::cerr << "tread fit: warning: " << data.source << ": the loads' median is "
              << significant(median) << " N, outside any tyre's (50 N…1 MN)" << hint << "\n";
  }
}

// Fits worse than the mean of their points (R² < 0) are failures, not results.
void check_r2(const std::vector<std::string>& failed) {
  if (failed.empty()) return;
  std::string what;
  for (const std::string& f : failed) what += "\n  " + f;
  throw std::runtime_error(
      "the fit failed: R² < 0 (worse than the points' mean) for" + what +
      "\nno result written (a --report or --plots asked for show the failed fit)");
}

// The columns the fit does not read, said rather than dropped silently; a pressure column above
// all: every point is fitted as if measured at the start file's INFLPRES.
void report_ignored(const fit::MeasurementSet& data,
                    const std::optional<mf::MfParameters<double>>& start) {
  if (data.ignored_columns.empty()) return;
  std::cerr << "tread fit: ignored columns:" << host::text::quoted_list(data.ignored_columns)
            << "\n";
  if (data.has_pressure) {
    std::cerr << "tread fit: warning: the pressure column is not used: every point is fitted as if "
                 "measured at "
              << (start ? "the start file's INFLPRES (" + tir::format_number(start->inflpres_pa) +
                              " Pa); data at another pressure need a fit of their own with "
                              "INFLPRES set to it"
                        : "one pressure")
              << "\n";
  }
}

void run_staged(const FitCliState& s) {
  const fit::MfFitModel model =
      s.model == "mf61" ? fit::MfFitModel::mf61 : fit::MfFitModel::pac2002;
  if (s.start.empty()) {
    throw std::runtime_error("--model " + s.model +
                             " needs --start START.tir (FNOMIN, R0, scalings, limits and the "
                             "coefficients not fitted come from it)");
  }
  if (std::filesystem::path(s.output).extension() != ".tir") {
    throw std::runtime_error("--output " + s.output + ": --model " + s.model + " writes a .tir");
  }
  tir::TirFile file = tir::read_tir(s.start);
  mf::MfParameters<double> start = tyre::mf_parameters_from_tir(file).params;
  const bool from_mf52 = model == fit::MfFitModel::mf61 && mf::is_mf5x(start);
  if (from_mf52) {
    std::vector<std::string> notes;
    start = fit::mf61_start_from_mf52(start, notes);
    std::cerr << "tread fit: " << s.start
              << ": a PAC2002 / MF 5.2 start, refitted as MF 6.1 (shared coefficients kept, MF "
                 "6.1's own at their book values)\n";
    for (const std::string& n : notes) std::cerr << "tread fit: note: " << n << "\n";
  }
  fit::check_model(start, model, s.start);
  if (s.neutral_start) start = fit::neutral_start(start, model);
  fit::MeasurementSet data = fit::load_measurements(s.input, convention_of(s));
  std::cerr << "tread fit: " << data.points.size() << " points from " << data.source << "; staged "
            << s.model << " fit\n";
  report_ignored(data, start);
  drop_unloaded(data);
  check_load_scale(data, &start);
  fit::check_rolling(data);
  const fit::StagedFit result = fit::fit_mf_staged(data, start, model, progress_line);
  if (result.stages.empty()) {
    throw std::runtime_error(data.source + ": no pure-slip sweep with enough points to fit");
  }
  if (from_mf52) {
    const std::vector<std::string> removed = fit::rewrite_as_mf61(file, result.params);
    if (!removed.empty()) {
      std::cerr << "tread fit: written as FITTYP 61; keys MF 6.1 does not read, removed:";
      for (const std::string& k : removed) std::cerr << ' ' << k;
      std::cerr << "\n";
    }
  }
  fit::set_fitted_coefficients(file, result);
  if (s.neutral_start) {
    // The coefficients --neutral-start set to their book values but no stage had data for: the
    // later stages and the fit errors below assume those values, so the file takes them too.
    std::vector<std::string> unfitted;
    for (const std::string& key : fit::fitted_keys(model)) {
      bool fitted = false;
      for (const auto& stage : result.stages) {
        fitted = fitted || std::find(stage.keys.begin(), stage.keys.end(), key) != stage.keys.end();
      }
      if (fitted) continue;
      unfitted.push_back(key);
      const int index = fit::required_coefficient_index(key);
      tir::set_si(file, fit::coefficient_section(index), key,
                  fit::coefficient(result.params, index));
    }
    if (!unfitted.empty()) {
      std::cerr << "tread fit: warning: --neutral-start: no stage fitted";
      for (const std::string& k : unfitted) std::cerr << ' ' << k;
      std::cerr << " (no data for them): written at their book values, which the fit used\n";
    }
  }
  std::vector<std::string> failed;
  for (const auto& st : fit::final_stats(result, data)) {
    std::cerr << "tread fit: fit error " << fit::fit_channel_name(st.channel)
              << " at Fz = " << st.fz_n << " N: RMS " << st.rms << ' '
              << fit::fit_channel_unit(st.channel) << ", R² " << st.r2 << " (" << st.points
              << " points)\n";
    if (!(st.r2 >= 0.0)) {
      failed.push_back(std::string(fit::fit_channel_name(st.channel)) + " at Fz = " +
                       tir::format_number(st.fz_n) + " N (R² " + significant(st.r2) + ")");
    }
  }
  if (!s.report.empty()) {
    std::ofstream out(s.report);
    fit::write_staged_report(result, data, out);
    if (!out) throw std::runtime_error(s.report + ": cannot write");
  }
  if (!s.plots.empty()) {
    fit::plot_staged_fit(result, data, s.plots);
    std::cerr << "tread fit: plots in " << s.plots << "\n";
  }
  for (const std::string& d : fit::sign_doubts(result, data)) {
    std::cerr << "tread fit: warning: " << d << "\n";
  }
  check_r2(failed);
  tir::write_tir(file, s.output);
  std::cerr << "tread fit: " << result.stages.size() << " stages in " << result.seconds << " s -> "
            << s.output << "\n";
}

// Options of another mode than the one run do nothing: refused rather than ignored (--noise
// without --synthesize, --start with --model simple, --input with --synthesize, ...).
void check_mode_options(const CLI::App& cmd, const FitCliState& s) {
  const auto given = [&](const char* option) { return cmd.count(option) > 0; };
  const auto refuse = [](const char* option, const char* why) {
    throw CLI::ValidationError(option, why);
  };
  if (!s.synthesize.empty()) {
    for (const char* o : {"--input", "--model", "--start", "--neutral-start", "--report", "--plots",
                          "--asymmetric-e", "--convention"}) {
      if (given(o)) refuse(o, "applies to a fit, not to --synthesize (which writes measurements)");
    }
    return;
  }
  for (const char* o : {"--noise", "--seed"}) {
    if (given(o)) refuse(o, "applies to --synthesize only");
  }
  if (s.model == "simple") {
    for (const char* o : {"--start", "--neutral-start"}) {
      if (given(o)) refuse(o, "applies to --model mf61 or pac2002 (simple fits no .tir)");
    }
  } else if (given("--asymmetric-e")) {
    refuse("--asymmetric-e", "applies to --model simple (mf61/pac2002 have PEX4/PEY3)");
  }
}

void run_fit(const FitCliState& s) {
  fit::quiet_solver_log();
  if (!s.synthesize.empty()) {
    run_synthesize(s);
    return;
  }
  if (s.input.empty()) throw std::runtime_error("--input is required (or --synthesize FROM.tir)");
  if (s.model == "mf61" || s.model == "pac2002") {
    run_staged(s);
    return;
  }
  const std::string ext = std::filesystem::path(s.output).extension().string();
  if (ext != ".csv") {
    throw std::runtime_error("--output " + s.output +
                             ": --model simple writes the per-load constants as .csv (a .tir needs "
                             "a full coefficient set: --model mf61 or pac2002)");
  }
  fit::MeasurementSet data = fit::load_measurements(s.input, convention_of(s));
  std::cerr << "tread fit: " << data.points.size() << " points from " << data.source << "\n";
  report_ignored(data, std::nullopt);
  drop_unloaded(data);
  check_load_scale(data, nullptr);
  fit::SimpleFitSettings settings;
  settings.asymmetric_e = s.asymmetric_e;
  const fit::SimpleFit result = fit::fit_simple(data, settings, progress_line);
  if (result.fits.empty()) {
    throw std::runtime_error(data.source + ": no pure-slip sweep with enough points to fit");
  }
  if (!s.report.empty()) {
    std::ofstream out(s.report);
    fit::write_simple_fit_report(result, data.source, out);
    if (!out) throw std::runtime_error(s.report + ": cannot write");
  }
  if (!s.plots.empty()) {
    fit::plot_simple_fit(result, s.plots);
    std::cerr << "tread fit: plots in " << s.plots << "\n";
  }
  // A standard deviation the covariance did not give (its points do not determine every constant,
  // e.g. a braking-only sweep and the curve's other side): written as nan, and said.
  for (const fit::ChannelFit& f : result.fits) {
    const std::size_t fitted = s.asymmetric_e ? 7 : 6;
    const bool undetermined = std::any_of(f.stddev.begin(), f.stddev.begin() + fitted,
                                          [](double v) { return !std::isfinite(v); });
    if (undetermined) {
      std::cerr << "tread fit: warning: " << fit::channel_name(f.channel)
                << " at Fz = " << tir::format_number(f.fz_n)
                << " N: standard deviations not determined (the points do not determine every "
                   "constant: the covariance is rank deficient); written as nan\n";
    }
  }
  std::vector<std::string> failed;
  for (const fit::ChannelFit& f : result.fits) {
    if (!(f.r2 >= 0.0)) {
      failed.push_back(std::string(fit::channel_name(f.channel)) + " at Fz = " +
                       tir::format_number(f.fz_n) + " N (R² " + significant(f.r2) + ")");
    }
  }
  for (const fit::Channel c : fit::kChannels) {
    std::vector<fit::LoadSlope> slopes;
    for (const fit::ChannelFit& f : result.fits) {
      if (f.channel == c) slopes.push_back({f.fz_n, fit::slope_at_origin(f.constants)});
    }
    const fit::SlopeOf which = c == fit::Channel::fx_kappa   ? fit::SlopeOf::fx_kappa
                               : c == fit::Channel::fy_alpha ? fit::SlopeOf::fy_alpha
                                                             : fit::SlopeOf::mz_alpha;
    const std::string d = fit::slope_sign_doubt(which, slopes);
    if (!d.empty()) std::cerr << "tread fit: warning: " << d << "\n";
  }
  check_r2(failed);
  std::ofstream out(s.output);
  fit::write_simple_fit_csv(result, out);
  if (!out) throw std::runtime_error(s.output + ": cannot write");
}

void add_fit_command(CLI::App& app) {
  auto* fit = app.add_subcommand("fit", "Fit Magic Formula coefficients to measurements");
  static FitCliState state;
  fit->footer(
      "Axes: ISO-W (TYDEX W, as tread mf eval and MFeval): x forward, y left, z up; load Fz > 0; "
      "alpha > 0 when the contact patch moves towards +y (a normal tyre gives Fy < 0, Mz > 0); SI "
      "units. Measurements in other axes: --convention. Written .tir files and synthetic "
      "measurements are ISO-W.");
  fit->add_option("--convention", state.convention,
                  "sign convention of a CSV --input: iso-w (default), sae (SAE J670, e.g. FSAE "
                  "TTC data: Fz, alpha, Fy, My, Mz change sign), adapted-iso (alpha, Fy, Mz "
                  "change sign); .tdx files are TYDEX W (ISO-W)")
      ->check(CLI::IsMember({"iso-w", "sae", "adapted-iso"}))
      ->capture_default_str();
  fit->add_option("--model", state.model,
                  "simple (Stage 1: basic formula per load), mf61 or pac2002 (Stage 2: staged "
                  "pure and combined slip coefficient set; pac2002 also for MF 5.2 files; mf61 "
                  "also from a PAC2002 / MF 5.2 --start, written as an MF 6.1 file)")
      ->check(CLI::IsMember({"simple", "pac2002", "mf61"}))
      ->capture_default_str();
  fit->add_option("--input", state.input,
                  "measurements: .tdx, or .csv read as tread mf eval reads it (',', ';' or tab; "
                  "decimal commas with ';' or tab; a units row under the header) with Fx_N|FX|FXW, "
                  "Fy_N|FY|FYW [N], Fx_kN, Fy_kN [kN], Mz_Nm|MZ|MZW [N m], Mz_kNm [kN m] and the "
                  "inputs: " +
                      tyre::input_column_help() + ". Points with Fz <= 0 are not fitted")
      ->check(CLI::ExistingFile);
  fit->add_option("--output", state.output,
                  "result: per-load constants (.csv) for simple, a .tir for mf61/pac2002, the "
                  "measurements (.csv) for --synthesize")
      ->required();
  fit->add_option("--report", state.report, "Markdown report (RMS, R², standard deviations)");
  fit->add_option("--plots", state.plots, "directory for PNG plots of measurement vs fit");
  fit->add_option("--start", state.start,
                  "starting .tir (mf61/pac2002: FNOMIN, R0, scalings, limits, everything not "
                  "fitted, and the starting values)");
  fit->add_flag("--neutral-start", state.neutral_start,
                "mf61/pac2002: start every fitted coefficient from its book (MFeval default) value "
                "instead of the --start file's");
  fit->add_option("--synthesize", state.synthesize,
                  "write synthetic measurements of this .tir (test-rig grid, Gaussian noise) to "
                  "--output instead of fitting")
      ->check(CLI::ExistingFile);
  fit->add_option("--noise", state.noise,
                  "--synthesize: noise standard deviation relative to the peak of each channel "
                  "and load")
      ->capture_default_str();
  fit->add_option("--seed", state.seed,
                  "--synthesize: seed of the noise (same seed, same file). The fits are "
                  "deterministic and draw no random numbers")
      ->capture_default_str();
  fit->add_flag("--asymmetric-e", state.asymmetric_e,
                "simple: also fit EA, a curvature that differs on either side of the origin "
                "(E*(1 - EA*sgn(x)), as MF's PEX4/PEY3)");
  fit->callback([fit] {
    check_mode_options(*fit, state);
    run_fit(state);
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("fit", add_fit_command);

}  // namespace tread::cli
