#pragma once
// Curves of a PAC89/PAC94 coefficient set as a self-contained gnuplot script (data inline as
// datablocks): Fx(κ), Fy(α), Mz(α) at several loads (pure slip; ISO-W axes by default, as
// `tread mf plot`, or the model's own) and the combined-slip
// Fy(Fx) envelope at the first load for fixed α while κ sweeps. The terminal follows the output
// file's extension (.png → pngcairo, .svg → svg).
//
// Debian's `libsciplot-dev` is the Motif SciPlot widget, not the C++ sciplot library, so we drive
// gnuplot (gnuplot-nox) directly, which is what sciplot does underneath.

#include <filesystem>
#include <string>
#include <vector>

#include "pac/pac_params.hpp"

namespace tread::tir {

enum class PacModel { kPac89, kPac94 };

struct PacPlotOptions {
  PacModel model = PacModel::kPac89;
  std::vector<double> loads_n = {2000.0, 4000.0, 6000.0, 10000.0};
  std::string title = "PAC89";
  int points = 401;   ///< samples per curve
  bool iso_w = true;  ///< ISO-W axes as `tread mf plot` (false: the model's own axes)
};

/// The gnuplot script writing `output` (PNG or SVG by extension).
std::string pac_plot_script(const pac::PacParams<double>& params, const PacPlotOptions& options,
                            const std::filesystem::path& output);

}  // namespace tread::tir
