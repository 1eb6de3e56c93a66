#include "profile/profile_plot.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>
#include "plot/gnuplot.hpp"

namespace tread::profile {

namespace {

void write_data(const std::filesystem::path& path, const std::vector<const WheelProfile*>& wheels,
                double step_mm) {
  std::ofstream out(path);
  const WheelProfile& first = *wheels.front();
  const auto n =
      static_cast<std::size_t>(std::floor((first.y_max_mm() - first.y_min_mm()) / step_mm + 1e-9));
  for (std::size_t i = 0; i <= n; ++i) {
    const double y = first.y_min_mm() + static_cast<double>(i) * step_mm;
    out << y;
    for (const WheelProfile* w : wheels) {
      const ProfileValue v = w->at(y);
      // The wheel back is vertical (tan = inf): clip the slope for the plot.
      out << '\t' << v.z_mm << '\t' << std::clamp(v.tan, -5.0, 5.0);
    }
    out << '\n';
  }
  if (!out) {
    throw std::runtime_error("cannot write " + path.string());
  }
}

}  // namespace

void plot_wheel_profile(const WheelProfile& wheel, double step_mm, const std::string& png_path) {
  WheelParameters p = wheel.parameters();
  p.family = WheelFamily::kS1002;
  const WheelProfile s1002(p);
  p.family = WheelFamily::kEps;
  const WheelProfile eps(p);
  p.family = WheelFamily::k1in40;
  const WheelProfile one40(p);
  const std::filesystem::path data =
      std::filesystem::path(png_path).replace_extension(".plotdata.tsv");
  write_data(data, {&wheel, &s1002, &eps, &one40}, std::min(step_mm, 0.1));
  const std::string d = data.string();
  const std::string script = host::format_script(
      "set terminal pngcairo size 1000,1200\n"
      "set output '%s'\n"
      "set multiplot layout 3,1 title '%s'\n"
      "set grid\n"
      "set xlabel 'y from the taping line D0, + toward the field side (mm)'\n"
      "set ylabel 'z = radius increase (mm)'\n"
      "plot '%s' using 1:2 with lines lw 2 title 'profile z(y)'\n"
      "set ylabel 'tan = dz/dy'\n"
      "set yrange [-2:5]\n"
      "plot '%s' using 1:3 with lines lw 2 title 'slope (clipped at the vertical wheel back)'\n"
      "set yrange [-0.6:0.2]\n"
      "set xrange [-40:%g]\n"
      "set ylabel 'tan = dz/dy'\n"
      "set title 'slopes of the three families (h %g, e %g, outer slope %s)'\n"
      "plot '%s' using 1:5 with lines lw 2 title 'S1002', "
      "'%s' using 1:7 with lines lw 2 title 'EPS', "
      "'%s' using 1:9 with lines lw 2 title '1/40'\n"
      "unset multiplot\n",
      png_path.c_str(), wheel.name().c_str(), d.c_str(), d.c_str(), wheel.y_max_mm(),
      wheel.parameters().flange_height_mm, wheel.parameters().flange_thickness_mm,
      to_string(wheel.parameters().outer_slope).c_str(), d.c_str(), d.c_str(), d.c_str());
  host::run_gnuplot_with_data(script, png_path, data);
}

}  // namespace tread::profile
