// `tread mf eval`: evaluate a Magic Formula .tir (MF 5.2 / 6.1 / 6.2, PAC2002) on a CSV of inputs.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "mf/mf_csv.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters_from_tir.hpp"
#include "mf/mf_plot.hpp"
#include "plot/gnuplot.hpp"

namespace tread::cli {

namespace {

struct MfEvalArgs {
  std::string tir;
  int mode = 111;
  bool use_float = false;
  std::string side = "as-measured";
  std::string input;
  std::string output;
};

void run_mf_eval(const MfEvalArgs& args) {
  const mf::MfTirParameters loaded = mf::load_mf_parameters(args.tir);
  if (!loaded.warning.empty()) std::cerr << "tread mf eval: warning: " << loaded.warning << '\n';
  const Result<mf::MfOptions> options = mf::options_from_use_mode(args.mode);
  if (!options.ok()) {
    throw std::runtime_error("--mode " + std::to_string(args.mode) +
                             ": expected MFeval's three digits: 1|2 (limits on|off), 1|2 "
                             "(alpha* off|on), 1|2 (turn slip off|on)");
  }
  mf::MfOptions o = options.value;
  if (args.side == "left") o.side = mf::MountedSide::left;
  if (args.side == "right") o.side = mf::MountedSide::right;
  std::ifstream in(args.input);
  if (!in) throw std::runtime_error(args.input + ": cannot open");
  std::ofstream out(args.output);
  if (!out) throw std::runtime_error(args.output + ": cannot write");
  const std::size_t rows = mf::evaluate_csv(loaded.params, o, args.use_float, in, args.input, out);
  out.close();
  if (!out) throw std::runtime_error(args.output + ": write failed");
  std::cerr << "tread mf eval: " << rows << " rows → " << args.output << '\n';
}

struct MfPlotArgs {
  std::string tir;
  int mode = 111;
  std::string output;
};

void run_mf_plot(const MfPlotArgs& args) {
  const mf::MfTirParameters loaded = mf::load_mf_parameters(args.tir);
  if (!loaded.warning.empty()) std::cerr << "tread mf plot: warning: " << loaded.warning << '\n';
  const Result<mf::MfOptions> options = mf::options_from_use_mode(args.mode);
  if (!options.ok()) throw std::runtime_error("--mode " + std::to_string(args.mode) + ": invalid");
  std::filesystem::path png = args.output;
  if (png.extension() != ".png") throw std::runtime_error(args.output + ": expected a .png name");
  std::filesystem::path svg = png;
  svg.replace_extension(".svg");
  mf::MfPlotOptions plot;
  plot.title = std::filesystem::path(args.tir).filename().string() + " (useMode " +
               std::to_string(args.mode) + ")";
  for (const auto& out : {png, svg}) {
    host::run_gnuplot(mf::mf_plot_script(loaded.params, options.value, plot, out), out.string());
    std::cerr << "tread mf plot: wrote " << out.string() << '\n';
  }
}

void add_mf_command(CLI::App& app) {
  auto* mf_cmd = app.add_subcommand("mf", "Magic Formula tyre model (MF 5.2 / 6.1 / 6.2, PAC2002)");
  mf_cmd->require_subcommand(1);
  static MfEvalArgs args;
  auto* eval = mf_cmd->add_subcommand("eval", "Evaluate a .tir on a CSV of inputs");
  eval->add_option("--tir", args.tir, "Tyre property file (.tir)")->required();
  eval->add_option("--mode", args.mode, "MFeval useMode: 111 (default) … 222");
  eval->add_flag("--float", args.use_float, "Evaluate in float (as on the ECU) instead of double");
  eval->add_option("--side", args.side,
                   "Mounted side: as-measured (default, like MFeval), left, right")
      ->check(CLI::IsMember({"as-measured", "left", "right"}));
  eval->add_option("--input", args.input,
                   "CSV with Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps[,phit_1pm][,P_Pa]")
      ->required();
  eval->add_option("--output", args.output, "CSV to write")->required();
  eval->callback([] { run_mf_eval(args); });

  static MfPlotArgs plot_args;
  auto* plot = mf_cmd->add_subcommand(
      "plot", "Plot Fx(κ), Fy(α), Mz(α) at several loads and a Fx(κ, Fz) map (PNG + SVG)");
  plot->add_option("--tir", plot_args.tir, "Tyre property file (.tir)")->required();
  plot->add_option("--mode", plot_args.mode, "MFeval useMode: 111 (default) … 222");
  plot->add_option("--output", plot_args.output, "PNG to write; an SVG is written beside it")
      ->required();
  plot->callback([] { run_mf_plot(plot_args); });
}

}  // namespace

TREAD_REGISTER_COMMAND("mf", add_mf_command);

}  // namespace tread::cli
