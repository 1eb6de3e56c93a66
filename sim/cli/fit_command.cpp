// `tread fit`: fit Magic Formula constants to measurements (CSV or TYDEX). Stage 1 (--model
// simple): the basic formula per load for Fx(kappa), Fy(alpha), Mz(alpha); writes the constants
// (CSV), a Markdown report and plots of measurement vs fit.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "fit/measurement.hpp"
#include "fit/mf_lateral_fit.hpp"
#include "fit/simple_fit.hpp"
#include "mf/mf_parameters_from_tir.hpp"
#include "tir/tir_file.hpp"

namespace tread::cli {
namespace {

struct FitCliState {
  std::string model = "simple";
  std::string input, output, report, plots, start;
  unsigned seed = 1;
  bool asymmetric_e = false;
};

void run_mf61_lateral(const FitCliState& s) {
  if (s.start.empty()) {
    throw std::runtime_error(
        "--model mf61 needs --start START.tir (FNOMIN, scalings and the "
        "coefficients not fitted come from it)");
  }
  if (std::filesystem::path(s.output).extension() != ".tir") {
    throw std::runtime_error("--output " + s.output + ": --model mf61 writes a .tir");
  }
  tir::TirFile file = tir::read_tir(s.start);
  const mf::MfTirParameters start = mf::mf_parameters_from_tir(file);
  if (start.params.fit_type != mf::FitType::mf61 && start.params.fit_type != mf::FitType::mf62) {
    throw std::runtime_error(s.start + ": --model mf61 needs an MF 6.1/6.2 (FITTYP 61/62) start");
  }
  const fit::MeasurementSet data = fit::load_measurements(s.input);
  std::cerr << "tread fit: " << data.points.size() << " points from " << data.source
            << "; MF 6.1 pure lateral (13 coefficients)\n";
  const fit::LateralFit result = fit::fit_mf_pure_lateral(
      data, start.params,
      [](const std::string& line) { std::cerr << "tread fit: " << line << "\n"; });
  fit::set_lateral_coefficients(file, result);
  tir::write_tir(file, s.output);
  std::cerr << "tread fit: RMS " << result.rms_n << " N, R2 " << result.r2 << " -> " << s.output
            << "\n";
  if (!s.report.empty()) {
    std::ofstream out(s.report);
    fit::write_lateral_report(result, data.source, out);
    if (!out) throw std::runtime_error(s.report + ": cannot write");
  }
}

void run_fit(const FitCliState& s) {
  if (s.model == "mf61") {
    run_mf61_lateral(s);
    return;
  }
  if (s.model != "simple") {
    throw std::runtime_error("--model " + s.model + ": not implemented yet");
  }
  const std::string ext = std::filesystem::path(s.output).extension().string();
  if (ext != ".csv") {
    throw std::runtime_error("--output " + s.output +
                             ": --model simple writes the per-load constants as .csv (a .tir needs "
                             "a full coefficient set, Stage 2)");
  }
  const fit::MeasurementSet data = fit::load_measurements(s.input);
  std::cerr << "tread fit: " << data.points.size() << " points from " << data.source << "\n";
  fit::SimpleFitSettings settings;
  settings.asymmetric_e = s.asymmetric_e;
  const fit::SimpleFit result = fit::fit_simple(
      data, settings, [](const std::string& line) { std::cerr << "tread fit: " << line << "\n"; });
  if (result.fits.empty()) {
    throw std::runtime_error(data.source + ": no pure-slip sweep with enough points to fit");
  }
  {
    std::ofstream out(s.output);
    fit::write_simple_fit_csv(result, out);
    if (!out) throw std::runtime_error(s.output + ": cannot write");
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
}

void add_fit_command(CLI::App& app) {
  auto* fit = app.add_subcommand("fit", "Fit Magic Formula constants to measurements");
  static FitCliState state;
  fit->add_option("--model", state.model,
                  "simple (Stage 1: basic formula per load) or mf61 (Stage 2: pure lateral so far)")
      ->check(CLI::IsMember({"simple", "pac2002", "mf61"}))
      ->capture_default_str();
  fit->add_option("--input", state.input, "measurements: .csv (tread mf eval columns) or .tdx")
      ->required()
      ->check(CLI::ExistingFile);
  fit->add_option("--output", state.output, "result: per-load constants (.csv) for simple")
      ->required();
  fit->add_option("--report", state.report, "Markdown report (RMS, R², standard deviations)");
  fit->add_option("--plots", state.plots, "directory for PNG plots of measurement vs fit");
  fit->add_option("--start", state.start,
                  "starting .tir (mf61: FNOMIN, scalings, everything not fitted)");
  fit->add_option("--seed", state.seed,
                  "random seed (the simple model's multi-start grid is deterministic and does not "
                  "use it)")
      ->capture_default_str();
  fit->add_flag("--asymmetric-e", state.asymmetric_e,
                "simple: also fit EA, a curvature that differs on either side of the origin "
                "(E*(1 - EA*sgn(x)), as MF's PEX4/PEY3)");
  fit->callback([] { run_fit(state); });
}

}  // namespace

TREAD_REGISTER_COMMAND("fit", add_fit_command);

}  // namespace tread::cli
