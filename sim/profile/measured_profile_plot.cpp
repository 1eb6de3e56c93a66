#include "profile/measured_profile_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "plot/gnuplot.hpp"

namespace tread::profile {

namespace {

constexpr double kSlopeClip = 5.0;

void write_data(const std::filesystem::path& path, const SampledProfile& measured,
                const std::vector<double>& slopes, const WheelProfile* nominal) {
  std::ofstream out(path);
  out.precision(10);
  for (std::size_t i = 0; i < measured.y_mm.size(); ++i) {
    const double y = measured.y_mm[i];
    out << y << '\t' << measured.z_mm[i] << '\t' << std::clamp(slopes[i], -kSlopeClip, kSlopeClip);
    if (nominal != nullptr && y >= nominal->y_min_mm() && y <= nominal->y_max_mm()) {
      const ProfileValue v = nominal->at(y);
      out << '\t' << v.z_mm << '\t' << std::clamp(v.tan, -kSlopeClip, kSlopeClip) << '\t'
          << measured.z_mm[i] - v.z_mm;
    } else {
      out << "\t?\t?\t?";
    }
    out << '\n';
  }
  if (!out) {
    throw std::runtime_error("cannot write " + path.string());
  }
}

}  // namespace

void plot_measured_profile(const SampledProfile& measured, const std::vector<double>& slopes,
                           const WheelProfile* nominal, const std::string& title,
                           const std::string& png_path) {
  if (slopes.size() != measured.y_mm.size()) {
    throw std::invalid_argument("plot_measured_profile: one slope per point");
  }
  const std::filesystem::path data =
      std::filesystem::path(png_path).replace_extension(".plotdata.tsv");
  write_data(data, measured, slopes, nominal);
  const std::string d = host::gnuplot_quote(data.string());
  const std::string nominal_title =
      nominal != nullptr ? host::gnuplot_quote("nominal " + nominal->name()) : "''";
  std::string script = host::gnuplot_terminal(png_path, 1000, nominal != nullptr ? 1500 : 800);
  script += "set termoption noenhanced\n";  // file names keep their underscores
  script += "set output " + host::gnuplot_quote(png_path) + "\n";
  script += "set datafile missing '?'\n";
  script += "set multiplot layout " + std::string(nominal != nullptr ? "4" : "2") + ",1 title " +
            host::gnuplot_quote(title) + "\n";
  script += "set grid\nset key right top\n";
  script += "set xlabel 'y (mm), + toward the field side'\n";
  script += "set ylabel 'z (mm)'\n";
  if (nominal != nullptr) {
    script += "set title 'profile (wheel: z = radius increase from the taping line)'\n";
    script += "plot " + d + " using 1:4 with lines lw 2 dt 2 lc rgb '#777777' title " +
              nominal_title + ", " + d +
              " using 1:2 with lines lw 2 lc rgb '#c03020' title 'measured'\n";
  } else {
    script += "set title 'profile'\n";
    script += "plot " + d + " using 1:2 with lines lw 2 lc rgb '#c03020' title 'measured'\n";
  }
  script += "set ylabel 'dz/dy'\nset yrange [-2.5:5.5]\n";
  script += "set title 'slope (local least squares; clipped at +-5)'\n";
  if (nominal != nullptr) {
    script += "plot " + d + " using 1:5 with lines lw 2 dt 2 lc rgb '#777777' title 'nominal', " +
              d + " using 1:3 with lines lw 2 lc rgb '#c03020' title 'measured'\n";
    script += "set yrange [-0.6:0.4]\nset xrange [-40:*]\n";
    script += "set title 'slope on the tread'\n";
    script += "plot " + d + " using 1:5 with lines lw 2 dt 2 lc rgb '#777777' title 'nominal', " +
              d + " using 1:3 with lines lw 2 lc rgb '#c03020' title 'measured'\n";
    script += "set autoscale y\nset autoscale x\n";
    script += "set ylabel 'measured - nominal (mm)'\n";
    script +=
        "set title 'vertical difference in the file''s frame (wear where negative; a lateral "
        "shift of the steep flange face shows large)'\n";
    script +=
        "plot " + d + " using 1:6 with lines lw 2 lc rgb '#2050b0' title 'measured - nominal'\n";
  } else {
    script += "plot " + d + " using 1:3 with lines lw 2 lc rgb '#c03020' title 'measured'\n";
  }
  script += "unset multiplot\n";
  host::run_gnuplot_with_data(script, png_path, data);
}

}  // namespace tread::profile
