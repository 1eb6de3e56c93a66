// `tread pac plot`: draw PAC89/PAC94 curves (Fx(κ), Fy(α), Mz(α) at several loads, combined-slip
// envelope) from a Chrono JSON coefficient file or an Adams .tir file, to PNG or SVG via gnuplot.
// `tread pac eval`: evaluate them on a CSV of inputs. Both in ISO-W axes by default, as `tread mf`.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "io/option_checks.hpp"
#include "io/table_streams.hpp"
#include "io/text_line.hpp"
#include "plot/gnuplot.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/pac_plot.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_model.hpp"
#include "tyre/input_table.hpp"
#include "tyre/pac_csv.hpp"

namespace tread::cli {

namespace {

constexpr const char* kPacAxesNote =
    "Axes: ISO-W (TYDEX W, as tread mf and MFeval) unless --axes model: x forward, y left, z up; "
    "load Fz > 0; alpha > 0 when the contact patch moves towards +y (a normal tyre gives Fy < 0, "
    "Mz > 0); SI units. The PAC89/PAC94 formulae work in their own \"modified SAE\" axes (Fy, My, "
    "Mz of the other sign); --axes model shows those.";

void add_pac_eval(CLI::App* pac);

// A missing entry ("SECTION.KEY") that is a PAC coefficient: its set (A, B, C) and number.
std::optional<std::pair<char, int>> coefficient_of(const std::string& missing_entry) {
  const std::string key = missing_entry.substr(missing_entry.find('.') + 1);
  if (key.size() < 2) return std::nullopt;
  const char set = static_cast<char>(std::toupper(static_cast<unsigned char>(key[0])));
  const std::string digits = key.substr(1);
  if ((set != 'A' && set != 'B' && set != 'C') ||
      digits.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  return std::pair<char, int>{set, std::stoi(digits)};
}

// The coefficients PAC89 needs (PAC94 adds A14…A17, B11…B13, C18…C20).
bool pac89_key(const std::string& missing_entry) {
  const auto c = coefficient_of(missing_entry);
  if (!c) return false;
  const auto [set, n] = *c;
  return (set == 'A' && n <= 13) || (set == 'B' && n <= 10) || (set == 'C' && n <= 17);
}

// Loads the coefficients; a source without any PAC89 coefficient (e.g. an MF file) is an error,
// not a tyre of zeros.
tir::PacCoefficients load_pac(const std::string& json, const std::string& tir_path,
                              const char* command) {
  const std::string source = json.empty() ? tir_path : json;
  // pac_from_tir refuses a Magic Formula file and a file without any PAC coefficient.
  auto coeff = json.empty() ? tir::pac_from_tir(tir::read_tyre_property_file(tir_path))
                            : tir::pac_from_chrono_json(json);
  std::size_t missing89 = 0;
  for (const std::string& m : coeff.missing) missing89 += pac89_key(m) ? 1U : 0U;
  constexpr std::size_t kPac89Count = 14 + 11 + 18;
  if (missing89 == kPac89Count) {
    throw std::runtime_error(source +
                             ": no PAC89/PAC94 coefficients (A0…A13, B0…B10, C0…C17); a Magic "
                             "Formula file goes to tread mf");
  }
  // PAC94's own coefficients missing from a PAC89 file are not a loss (every PAC89 file lacks
  // them): only what the file's model reads is said, the design values (R0, the lateral stiffness
  // behind Mx, ...) among it.
  std::vector<std::string> matter;
  for (const std::string& m : coeff.missing) {
    if (coeff.pac94 || !coefficient_of(m) || pac89_key(m)) matter.push_back(m);
  }
  if (!matter.empty()) {
    std::string list;
    for (std::size_t i = 0; i < matter.size() && i < 6; ++i) {
      list += (i == 0 ? "" : ", ") + matter[i];
    }
    if (matter.size() > 6) list += ", …";
    std::cerr << command << ": warning: " << source << ": " << matter.size()
              << " values missing, taken as 0: " << list << "\n";
  }
  if (!coeff.note.empty())
    std::cerr << command << ": note: " << source << ": " << coeff.note << '\n';
  for (const std::string& w : coeff.warnings) {
    std::cerr << command << ": warning: " << source << ": " << w << '\n';
  }
  return coeff;
}

bool explicit_model(const CLI::App* app) {
  return app->count("--model") > 0;
}

// --model if given, else the model the .tir declares (PAC89 for a Chrono JSON). A .tir that says
// PAC94 evaluated with --model 89 drops its PAC94 terms: said on stderr.
tir::PacModel model_for(const tir::PacCoefficients& coeff, int model, bool given, bool from_tir) {
  if (!given) {
    return from_tir && coeff.pac94 ? tir::PacModel::kPac94 : tir::PacModel::kPac89;
  }
  if (from_tir && coeff.pac94 && model == 89) {
    std::cerr << "tread pac: warning: the file is PAC94; --model 89 ignores its A14…A17, B11…B13, "
                 "C18…C20\n";
  }
  if (from_tir && !coeff.pac94 && model == 94) {
    std::cerr
        << "tread pac: warning: the file is PAC89; --model 94 reads its A8…A13, B8…B10 and "
           "C11…C17 with PAC94's meanings, which differ (the shifts' load and camber terms)\n";
  }
  return model == 94 ? tir::PacModel::kPac94 : tir::PacModel::kPac89;
}

void add_pac_command(CLI::App& app) {
  auto* pac = app.add_subcommand("pac", "PAC89 / PAC94 tyre models");
  pac->require_subcommand(1);
  pac->footer(kPacAxesNote);
  add_pac_eval(pac);
  auto* plot = pac->add_subcommand("plot", "Plot PAC89/PAC94 curves to PNG or SVG (gnuplot)");
  struct Options {
    std::string json;
    std::string tir;
    std::string output = "pac_curves.png";
    int model = 89;
    std::vector<double> loads = {2000.0, 4000.0, 6000.0, 10000.0};
    std::string axes = "iso-w";
  };
  static Options opt;
  plot->footer(kPacAxesNote);
  auto* src = plot->add_option_group("source")->require_option(1);
  src->add_option("--json", opt.json, "Chrono Pac89Tire JSON coefficient file")
      ->check(CLI::ExistingFile);
  src->add_option("--tir", opt.tir, "Adams PAC89/PAC94 .tir file")->check(CLI::ExistingFile);
  plot->add_option("--model", opt.model, "89 or 94 (default: what the .tir declares, else 89)")
      ->check(CLI::IsMember({89, 94}))
      ->capture_default_str();
  plot->add_option("--loads", opt.loads,
                   "wheel loads in N (default: 2000, 4000, 6000, 10000 N, or a quarter, half, "
                   "three quarters and all of the tyre's load limit where that is lower)")
      ->delimiter(',')
      ->check(host::finite_within(1.0, 1e7, "a wheel load in N"));
  plot->add_option("--output,-o", opt.output, ".png or .svg")->capture_default_str();
  plot->add_option("--axes", opt.axes, "iso-w (default, as tread mf plot) or model")
      ->check(CLI::IsMember({"iso-w", "model"}))
      ->capture_default_str();
  plot->callback([plot] {
    const auto coeff = load_pac(opt.json, opt.tir, "tread pac plot");
    const tir::PacModel model = model_for(coeff, opt.model, explicit_model(plot), opt.json.empty());
    tir::PacPlotOptions po;
    po.model = model;
    po.loads_n = opt.loads;
    const double limit = coeff.params.fz_max_n;
    if (plot->count("--loads") == 0 &&
        std::any_of(po.loads_n.begin(), po.loads_n.end(), [&](double f) { return f > limit; })) {
      // The defaults are for a car tyre: a tyre with a lower limit gets its own range.
      po.loads_n.clear();
      for (const double share : {0.25, 0.5, 0.75, 1.0}) {
        po.loads_n.push_back(std::round(share * limit / 10.0) * 10.0);
      }
    }
    for (const double f : po.loads_n) {
      if (f > limit) {
        std::cerr << "tread pac plot: warning: Fz = " << f << " N lies above the tyre's load limit "
                  << limit << " N: its curves are drawn at the limit\n";
      }
    }
    po.iso_w = opt.axes == "iso-w";
    po.title = (model == tir::PacModel::kPac94 ? "PAC94 " : "PAC89 ") +
               std::filesystem::path(opt.json.empty() ? opt.tir : opt.json).filename().string();
    host::run_gnuplot(tir::pac_plot_script(coeff.params, po, opt.output), opt.output);
    std::cout << "wrote " << opt.output << '\n';
  });
}

void add_pac_eval(CLI::App* pac) {
  auto* eval = pac->add_subcommand("eval", "Evaluate PAC89/PAC94 for the rows of a CSV file");
  struct Options {
    std::string json;
    std::string tir;
    std::string input;
    std::string output;
    int model = 89;
    bool pure = false;
    bool use_float = false;
    bool iso_w = false;
    std::string axes = "iso-w";
    std::string convention = "iso-w";
    std::string sep = "auto";
  };
  static Options opt;
  eval->footer(kPacAxesNote);
  auto* src = eval->add_option_group("source")->require_option(1);
  src->add_option("--json", opt.json, "Chrono Pac89Tire JSON coefficient file")
      ->check(CLI::ExistingFile);
  src->add_option("--tir", opt.tir, "Adams PAC89/PAC94 .tir file")->check(CLI::ExistingFile);
  eval->add_option("--model", opt.model, "89 or 94 (default: what the .tir declares, else 89)")
      ->check(CLI::IsMember({89, 94}))
      ->capture_default_str();
  eval->add_flag("--pure", opt.pure, "pure slip (default: combined)");
  eval->add_flag("--float", opt.use_float, "evaluate in float");
  eval->add_flag("--iso-w", opt.iso_w,
                 "outputs in ISO-W axes (the default now; kept for older scripts)");
  eval->add_option("--axes", opt.axes,
                   "axes of the outputs: iso-w (default, as tread mf eval) or model (the "
                   "PAC89/PAC94 formulae's own: Fy, My, Mz of the other sign)")
      ->check(CLI::IsMember({"iso-w", "model"}))
      ->capture_default_str();
  eval->add_option("--convention", opt.convention,
                   "sign convention of the input file: iso-w (default), sae (SAE J670, e.g. FSAE "
                   "TTC data: Fz and alpha change sign), adapted-iso (alpha changes sign)")
      ->check(CLI::IsMember({"iso-w", "sae", "adapted-iso"}))
      ->capture_default_str();
  eval->add_option("--sep", opt.sep, "input separator: auto (default), ',', ';' or tab")
      ->check(CLI::IsMember({"auto", ",", ";", "tab"}))
      ->capture_default_str();
  eval->add_option("--input", opt.input,
                   "CSV with the inputs Fz, kappa, alpha, gamma (other columns ignored; - for "
                   "standard input); names: " +
                       tyre::input_column_help())
      ->required()
      ->check(CLI::ExistingFile | CLI::IsMember({"-"}));
  eval->add_option("--output", opt.output, "CSV to write; - for standard output")->required();
  eval->callback([eval] {
    const auto coeff = load_pac(opt.json, opt.tir, "tread pac eval");
    tyre::PacCsvOptions o;
    o.model = model_for(coeff, opt.model, explicit_model(eval), opt.json.empty());
    o.slip = opt.pure ? pac::Slip::kPure : pac::Slip::kCombined;
    o.use_float = opt.use_float;
    o.iso_w = opt.iso_w || opt.axes == "iso-w";
    o.table.convention = *tyre::parse_sign_convention(opt.convention);
    o.table.separator = opt.sep == "auto" ? '\0' : opt.sep == "tab" ? '\t' : opt.sep.front();
    host::TableInput in(opt.input);     // "-": standard input
    host::TableOutput out(opt.output);  // "-": standard output
    tyre::PacCsvTally tally;
    const auto rows =
        tyre::evaluate_pac_csv(coeff.params, o, in.stream(), in.name(), out.stream(), &tally);
    out.commit();
    (out.is_stdout() ? std::cerr : std::cout)
        << "evaluated " << rows << " rows -> " << opt.output
        << (o.iso_w ? " (ISO-W axes)" : " (model axes)") << '\n';
    // As mf eval: rows the status column marks are also counted here, not left to be found.
    if (!tally.unused_columns.empty()) {
      // Read as inputs by `mf eval`, but PAC89/PAC94 have no such terms: the same forces at any
      // speed (standstill and reversing included) and pressure.
      std::cerr << "tread pac eval: warning: " << in.name() << ": column"
                << (tally.unused_columns.size() == 1 ? "" : "s")
                << host::text::quoted_list(tally.unused_columns)
                << " not used: PAC89/PAC94 have no speed, turn-slip or pressure terms (the "
                   "outputs are the same at any value, 0 and reversing included)\n";
    }
    if (tally.out_of_range > 0) {
      std::cerr << "tread pac eval: warning: " << tally.out_of_range
                << " rows out of range: an input beyond the tyre's limits (load, slip, camber) "
                   "was clamped to them; the first at "
                << in.name() << ":" << tally.first_out_of_range_line << "\n";
    }
    if (tally.other > 0) {
      std::cerr << "tread pac eval: warning: " << tally.other
                << " rows with a non-finite result, written as 0; the first at " << in.name() << ":"
                << tally.first_other_line << "\n";
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("pac", add_pac_command);

}  // namespace tread::cli
