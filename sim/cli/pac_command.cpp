// `tread pac plot`: draw PAC89/PAC94 curves (Fx(κ), Fy(α), Mz(α) at several loads, combined-slip
// envelope) from a Chrono JSON coefficient file or an Adams .tir file, to PNG or SVG via gnuplot.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "plot/gnuplot.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/pac_csv.hpp"
#include "tir/pac_plot.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_model.hpp"

namespace tread::cli {

namespace {

void add_pac_eval(CLI::App* pac);

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
  return model == 94 ? tir::PacModel::kPac94 : tir::PacModel::kPac89;
}

void add_pac_command(CLI::App& app) {
  auto* pac = app.add_subcommand("pac", "PAC89 / PAC94 tyre models");
  pac->require_subcommand(1);
  add_pac_eval(pac);
  auto* plot = pac->add_subcommand("plot", "Plot PAC89/PAC94 curves to PNG or SVG (gnuplot)");
  struct Options {
    std::string json;
    std::string tir;
    std::string output = "pac_curves.png";
    int model = 89;
    std::vector<double> loads = {2000.0, 4000.0, 6000.0, 10000.0};
  };
  static Options opt;
  auto* src = plot->add_option_group("source")->require_option(1);
  src->add_option("--json", opt.json, "Chrono Pac89Tire JSON coefficient file")
      ->check(CLI::ExistingFile);
  src->add_option("--tir", opt.tir, "Adams PAC89/PAC94 .tir file")->check(CLI::ExistingFile);
  plot->add_option("--model", opt.model, "89 or 94 (default: what the .tir declares, else 89)")
      ->check(CLI::IsMember({89, 94}))
      ->capture_default_str();
  plot->add_option("--loads", opt.loads, "wheel loads in N")->capture_default_str();
  plot->add_option("--output,-o", opt.output, ".png or .svg")->capture_default_str();
  plot->callback([plot] {
    const auto coeff = opt.json.empty() ? tir::pac_from_tir(tir::read_tyre_property_file(opt.tir))
                                        : tir::pac_from_chrono_json(opt.json);
    const tir::PacModel model = model_for(coeff, opt.model, explicit_model(plot), opt.json.empty());
    if (!coeff.missing.empty()) {
      std::cerr << "tread pac plot: " << coeff.missing.size()
                << " coefficients missing, taken as 0 (first: " << coeff.missing.front() << ")\n";
    }
    tir::PacPlotOptions po;
    po.model = model;
    po.loads_n = opt.loads;
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
  };
  static Options opt;
  auto* src = eval->add_option_group("source")->require_option(1);
  src->add_option("--json", opt.json, "Chrono Pac89Tire JSON coefficient file")
      ->check(CLI::ExistingFile);
  src->add_option("--tir", opt.tir, "Adams PAC89/PAC94 .tir file")->check(CLI::ExistingFile);
  eval->add_option("--model", opt.model, "89 or 94 (default: what the .tir declares, else 89)")
      ->check(CLI::IsMember({89, 94}))
      ->capture_default_str();
  eval->add_flag("--pure", opt.pure, "pure slip (default: combined)");
  eval->add_flag("--float", opt.use_float, "evaluate in float");
  eval->add_flag("--iso-w", opt.iso_w, "outputs in ISO-W axes (Fy, My, Mz sign-flipped)");
  eval->add_option("--input", opt.input, "CSV with Fz_N,kappa,alpha_rad,gamma_rad")
      ->required()
      ->check(CLI::ExistingFile);
  eval->add_option("--output", opt.output, "CSV to write")->required();
  eval->callback([eval] {
    const auto coeff = opt.json.empty() ? tir::pac_from_tir(tir::read_tyre_property_file(opt.tir))
                                        : tir::pac_from_chrono_json(opt.json);
    tir::PacCsvOptions o;
    o.model = model_for(coeff, opt.model, explicit_model(eval), opt.json.empty());
    o.slip = opt.pure ? pac::Slip::kPure : pac::Slip::kCombined;
    o.use_float = opt.use_float;
    o.iso_w = opt.iso_w;
    std::ifstream in(opt.input);
    std::ofstream out(opt.output);
    if (!out) throw std::runtime_error(opt.output + ": cannot write");
    const auto rows = tir::evaluate_pac_csv(coeff.params, o, in, opt.input, out);
    std::cout << "evaluated " << rows << " rows -> " << opt.output << '\n';
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("pac", add_pac_command);

}  // namespace tread::cli
