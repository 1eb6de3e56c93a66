#pragma once
// Curves of a Magic Formula tyre as a self-contained gnuplot script (data inline as datablocks):
// Fx(κ), Fy(α) and Mz(α) at several loads (pure slip in the other quantity, γ = 0) and a
// Fx(κ, Fz) map. The terminal follows the output's extension (.png → pngcairo, .svg → svg).
// Debian packages no C++ sciplot library (libsciplot-dev is an unrelated Motif widget), so this
// drives gnuplot (gnuplot-nox) directly, as sciplot itself does.

#include <filesystem>
#include <string>
#include <vector>

#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::tyre {

struct MfPlotOptions {
  std::vector<double> load_factors = {0.5, 1.0, 1.5, 2.0};  ///< × FNOMIN
  std::vector<double> loads_n;  ///< loads in N; when not empty, used instead of load_factors
  double vx_mps = 16.7;
  std::string title = "Magic Formula";
  int points = 301;
};

/// The loads drawn: `loads_n`, or `load_factors` × FNOMIN.
std::vector<double> plot_loads(const mf::MfParameters<double>& params, const MfPlotOptions& plot);

/// For a load above FZMAX with the limits on (where the model evaluates FZMAX instead): "FZMAX"
/// and its value, e.g. "FZMAX 30578 N"; empty otherwise (below FZMIN the forces are not clamped).
/// The legend names it beside the load, and `tread mf plot` warns.
std::string clamped_load(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                         double fz_n);

/// The gnuplot script that writes `output` (PNG or SVG by extension).
std::string mf_plot_script(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                           const MfPlotOptions& plot, const std::filesystem::path& output);

}  // namespace tread::tyre
