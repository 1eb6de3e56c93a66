// `tread mf eval`: evaluate a Magic Formula .tir (MF 5.2 / 6.1 / 6.2, PAC2002) on a CSV of inputs.
// `tread mf plot`: its pure-slip curves at several loads and a Fx(κ, Fz) map, with warnings for
// inverted curves. Both work in ISO-W axes (TYDEX W: x forward, y left, z up), SI units, as MFeval.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "cli/commands.hpp"
#include "io/option_checks.hpp"
#include "io/progress_bar.hpp"
#include "io/table_streams.hpp"
#include "io/text_line.hpp"
#include "mf/mf_options.hpp"
#include "plot/gnuplot.hpp"
#include "tyre/input_table.hpp"
#include "tyre/mf_csv.hpp"
#include "tyre/mf_curve_checks.hpp"
#include "tyre/mf_eval_columns.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "tyre/mf_plot.hpp"

namespace tread::cli {

namespace {

constexpr const char* kAxesNote =
    "Axes: ISO-W (TYDEX W, as MFeval): x forward, y left, z up; load Fz > 0; alpha > 0 when the "
    "contact patch moves towards +y (a normal tyre gives Fy < 0, Mz > 0); SI units.";

std::string input_help() {
  return "CSV of inputs (- for standard input). Column names (any case, any order; Fz, kappa, "
         "alpha, gamma, Vx required, "
         "phit and P optional, P absent or 0: the file's INFLPRES; other columns ignored): " +
         tyre::input_column_help();
}

struct MfEvalArgs {
  std::string tir;
  int mode = 111;
  bool use_float = false;
  bool use_batch = false;
  bool use_fixed = false;
  std::string side = "as-measured";
  std::string input;
  std::string output;
  std::string sep = "auto";
  std::string convention = "iso-w";
  bool strict = false;
  std::string columns;  ///< --columns; empty: the default columns
};

mf::MfOptions options_for(int mode, const char* command) {
  const Result<mf::MfOptions> options = mf::options_from_use_mode(mode);
  if (!options.ok()) {
    throw std::runtime_error(std::string(command) + ": --mode " + std::to_string(mode) +
                             ": expected MFeval's three digits: 1|2 (limits on|off), 1|2 "
                             "(alpha* off|on), 1|2 (turn slip off|on)");
  }
  return options.value;
}

char separator(const std::string& sep) {
  if (sep == "auto") return '\0';
  if (sep == "," || sep == "comma") return ',';
  if (sep == ";" || sep == "semicolon") return ';';
  if (sep == "\\t" || sep == "\t" || sep == "tab") return '\t';
  throw std::runtime_error("--sep " + sep + ": expected auto, ',', ';' or tab");
}

/// Each line of `text` (warnings, one per line) as "PREFIX: warning: line".
void print_warnings(const char* prefix, const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty()) std::cerr << prefix << ": warning: " << line << '\n';
  }
}

void run_mf_eval(const MfEvalArgs& args) {
  const tyre::MfTirParameters loaded = tyre::load_mf_parameters(args.tir);
  print_warnings("tread mf eval", loaded.warning);
  mf::MfOptions o = options_for(args.mode, "tread mf eval");
  // What `tread tir info` says of the curves (a negative slip stiffness, friction beyond reason):
  // at FNOMIN and LONGVL, in the mode asked for.
  for (const std::string& w :
       tyre::curve_warnings(loaded.params, o, {loaded.params.fnomin_n}, loaded.params.longvl_mps)) {
    std::cerr << "tread mf eval: warning: " << args.tir << ": at FNOMIN and LONGVL: " << w << '\n';
  }
  if (args.side == "left") o.side = mf::MountedSide::left;
  if (args.side == "right") o.side = mf::MountedSide::right;
  tyre::MfCsvOptions csv;
  csv.use_float = args.use_float;
  csv.use_batch = args.use_batch;
  csv.use_fixed = args.use_fixed;
  csv.strict = args.strict;
  csv.tyre_name = args.tir;
  csv.table.separator = separator(args.sep);
  csv.table.convention = *tyre::parse_sign_convention(args.convention);
  if (!args.columns.empty()) {
    tyre::EvalColumnSelection selection = tyre::select_eval_columns(args.columns);
    if (!selection.error.empty()) throw std::runtime_error(selection.error);
    csv.columns = std::move(selection.columns);
  }
  host::TableInput in(args.input);  // "-": standard input
  const std::string& in_name = in.name();
  // A progress bar on a terminal, for a run that lasts more than a second.
  std::error_code no_size;
  const std::uintmax_t input_bytes =
      in.is_stdin() ? 0 : std::filesystem::file_size(args.input, no_size);
  host::ProgressBar bar(std::cerr, host::stderr_is_terminal(), no_size ? 0 : input_bytes);
  const auto start = std::chrono::steady_clock::now();
  csv.progress = [&](std::uint64_t bytes, std::uint64_t rows) {
    bar.update(bytes, rows,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
  host::TableOutput out(args.output);  // "-": standard output
  tyre::MfCsvReport report;
  try {
    report = tyre::evaluate_csv(loaded.params, o, csv, in.stream(), in_name, out.stream());
    out.commit();
  } catch (...) {
    bar.finish();
    throw;
  }
  bar.finish();
  for (const std::string& m : report.mapping) std::cerr << "tread mf eval: column " << m << '\n';
  if (!report.ignored.empty()) {
    std::cerr << "tread mf eval: ignored columns:" << host::text::quoted_list(report.ignored)
              << '\n';
  }
  for (const std::string& w : report.warnings) std::cerr << "tread mf eval: warning: " << w << '\n';
  for (const tyre::MfRangeCount& c : report.out_of_range) {
    std::cerr << "tread mf eval: warning: " << c.rows
              << " rows outside the model's range: " << c.limit << " (first: " << in_name << ':'
              << c.first_line << ")" << (o.use_limits && c.clamped ? "; evaluated clamped" : "")
              << c.note << '\n';
  }
  std::cerr << "tread mf eval: " << report.rows << " rows → " << args.output << " (ISO-W, SI)\n";
}

struct MfPlotArgs {
  std::string tir;
  int mode = 111;
  std::string output;
  std::vector<double> loads;
  double vx_mps = 16.7;
};

void run_mf_plot(const MfPlotArgs& args) {
  const tyre::MfTirParameters loaded = tyre::load_mf_parameters(args.tir);
  print_warnings("tread mf plot", loaded.warning);
  const mf::MfOptions options = options_for(args.mode, "tread mf plot");
  for (double fz : args.loads) {
    if (!(fz > 0.0)) {
      throw std::runtime_error("--loads: " + std::to_string(fz) + " is not a positive load in N");
    }
  }
  std::filesystem::path png = args.output;
  if (png.extension() != ".png") throw std::runtime_error(args.output + ": expected a .png name");
  std::filesystem::path svg = png;
  svg.replace_extension(".svg");
  for (const std::string& w :
       tyre::curve_warnings(loaded.params, options, args.loads, args.vx_mps)) {
    std::cerr << "tread mf plot: warning: " << args.tir << ": " << w << '\n';
  }
  tyre::MfPlotOptions plot;
  plot.loads_n = args.loads;
  for (const double fz : tyre::plot_loads(loaded.params, plot)) {
    if (const std::string bound = tyre::clamped_load(loaded.params, options, fz); !bound.empty()) {
      std::cerr << "tread mf plot: warning: " << args.tir << ": Fz = " << fz
                << " N lies above the tyre's load range: its curves are drawn at " << bound
                << " (--mode 2xx evaluates beyond it)\n";
    }
    if (fz < 0.01 * loaded.params.fnomin_n) {
      // A load typed in kN (2,4,6) on a tyre whose FZMIN is 0 was plotted at 2, 4 and 6 N.
      std::cerr << "tread mf plot: warning: " << args.tir << ": Fz = " << fz
                << " N is under 1 % of FNOMIN (" << loaded.params.fnomin_n
                << " N): --loads are in N, not kN\n";
    } else if (fz < loaded.params.fzmin_n) {
      // Not clamped (MFeval limits only FZMAX), but outside what the tyre was fitted on: a load
      // typed in kN lands here.
      std::cerr << "tread mf plot: warning: " << args.tir << ": Fz = " << fz
                << " N lies below the tyre's load range (FZMIN " << loaded.params.fzmin_n
                << " N): its curves are an extrapolation\n";
    }
  }
  if (args.vx_mps < loaded.params.vxlow_mps) {
    std::cerr << "tread mf plot: warning: " << args.tir << ": --vx " << args.vx_mps
              << " m/s is below VXLOW (" << loaded.params.vxlow_mps
              << " m/s), where the slips are smoothed toward 0\n";
  }
  plot.vx_mps = args.vx_mps;
  std::ostringstream speed;
  speed << args.vx_mps;
  plot.title = std::filesystem::path(args.tir).filename().string() + " (useMode " +
               std::to_string(args.mode) + ", Vx " + speed.str() + " m/s, ISO-W)";
  for (const auto& out : {png, svg}) {
    host::run_gnuplot(tyre::mf_plot_script(loaded.params, options, plot, out), out.string());
    std::cerr << "tread mf plot: wrote " << out.string() << '\n';
  }
}

void add_mf_command(CLI::App& app) {
  auto* mf_cmd = app.add_subcommand("mf", "Magic Formula tyre model (MF 5.2 / 6.1 / 6.2, PAC2002)");
  mf_cmd->require_subcommand(1);
  mf_cmd->footer(kAxesNote);
  static MfEvalArgs args;
  auto* eval = mf_cmd->add_subcommand("eval", "Evaluate a .tir on a CSV of inputs");
  eval->footer(std::string(kAxesNote) +
               " Outputs are always ISO-W; --convention says in which axes the input file is "
               "written. Rows outside the file's FZMIN/FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, "
               "CAMMIN/CAMMAX, PRESMIN/PRESMAX are counted on stderr (--strict: an error). The "
               "output is written whole or not at all.");
  eval->add_option("--tir", args.tir, "Tyre property file (.tir)")->required();
  eval->add_option("--mode", args.mode, "MFeval useMode: 111 (default) … 222");
  CLI::Option* as_float = eval->add_flag(
      "--float", args.use_float,
      "Evaluate in float instead of double, row by row: the ECU's scalar float path, bit for bit");
  CLI::Option* as_batch = eval->add_flag(
      "--batch", args.use_batch,
      "Evaluate in float instead of double, many rows at once on wide SIMD lanes (8 with AVX2): "
      "faster than --float, with its status and its values within 2e-5 of each column's largest "
      "magnitude (float rounding), not bit for bit");
  as_batch->excludes(as_float);
  eval->add_flag("--fixed", args.use_fixed,
                 "Evaluate in fixed point (Q31.32 integer arithmetic, bit for bit as on an "
                 "FPU-less ECU) instead of double")
      ->excludes(as_float)
      ->excludes(as_batch);
  eval->add_option("--side", args.side,
                   "Mounted side: as-measured (default, like MFeval), left, right")
      ->check(CLI::IsMember({"as-measured", "left", "right"}));
  eval->add_option("--input", args.input, input_help())->required();
  eval->add_option("--output", args.output, "CSV to write (ISO-W, SI); - for standard output")
      ->required();
  eval->add_option("--sep", args.sep,
                   "Input separator: auto (default: ',' unless the header has only ';' or tabs), "
                   "',', ';' or tab; with ';' or tab a decimal comma is accepted")
      ->capture_default_str();
  eval->add_option("--convention", args.convention,
                   "Sign convention of the input file: iso-w (default), sae (SAE J670, e.g. FSAE "
                   "TTC data: Fz and alpha change sign), adapted-iso (positive alpha gives "
                   "positive Fy: alpha changes sign)")
      ->check(CLI::IsMember({"iso-w", "sae", "adapted-iso"}))
      ->capture_default_str();
  std::string column_names;
  for (const tyre::EvalColumn& c : tyre::eval_columns()) {
    column_names += (column_names.empty() ? "" : ", ") + std::string(c.name);
  }
  eval->add_option("--columns", args.columns,
                   "Columns to write, comma-separated (default: the inputs in_Fz_N … in_P_Pa "
                   "and Fx_N, Fy_N, Fz_N, Mx_Nm, My_Nm, Mz_Nm; 'all': every column); status is "
                   "always written, last. Columns: " +
                       column_names);
  eval->add_flag("--strict", args.strict,
                 "A row outside the model's range is an error naming the row (default: counted "
                 "on stderr)");
  eval->callback([] { run_mf_eval(args); });

  static MfPlotArgs plot_args;
  auto* plot = mf_cmd->add_subcommand(
      "plot", "Plot Fx(κ), Fy(α), Mz(α) at several loads and a Fx(κ, Fz) map (PNG + SVG)");
  plot->footer(std::string(kAxesNote) +
               " Warnings on stderr for inverted curves: Fx peak or slip stiffness of the wrong "
               "sign below FZMAX, a cornering stiffness of the wrong sign, friction rising with "
               "load or above 3.");
  plot->add_option("--tir", plot_args.tir, "Tyre property file (.tir)")->required();
  plot->add_option("--mode", plot_args.mode, "MFeval useMode: 111 (default) … 222");
  plot->add_option("--loads", plot_args.loads,
                   "Wheel loads in N, e.g. 2000,4000,6000 (default: 0.5, 1, 1.5, 2 × FNOMIN)")
      ->delimiter(',');
  plot->add_option("--vx", plot_args.vx_mps, "Forward speed in m/s")
      ->check(host::finite_within(0.01, 200.0, "the forward speed in m/s"))
      ->capture_default_str();
  plot->add_option("--output", plot_args.output, "PNG to write; an SVG is written beside it")
      ->required();
  plot->callback([] { run_mf_plot(plot_args); });
}

}  // namespace

TREAD_REGISTER_COMMAND("mf", add_mf_command);

}  // namespace tread::cli
