#include "contact/contact_plot.hpp"

#include <filesystem>

#include <fstream>
#include <stdexcept>
#include <string>
#include "plot/gnuplot.hpp"

namespace tread::contact {

void plot_contact_table(const ContactTable& table, const std::string& title,
                        const std::string& png_path) {
  const std::filesystem::path data =
      std::filesystem::path(png_path).replace_extension(".plotdata.tsv");
  {
    std::ofstream out(data);
    for (std::size_t k = 0; k < table.y_mm.size(); ++k) {
      out << table.y_mm[k] << '\t' << table.delta_r_mm[k] << '\t' << table.yc_left_mm[k] << '\t'
          << table.yc_right_mm[k] << '\n';
    }
    if (!out) {
      throw std::runtime_error("cannot write " + data.string());
    }
  }
  const std::string script = host::format_script(
      "set terminal pngcairo size 900,900\n"
      "set output '%s'\n"
      "set multiplot layout 2,1 title '%s'\n"
      "set grid\n"
      "set xlabel 'wheelset displacement y (mm)'\n"
      "set ylabel 'delta r = r_{left} - r_{right} (mm)'\n"
      "plot '%s' using 1:2 with lines lw 2 title 'delta r'\n"
      "set ylabel 'contact position on the wheel (mm)'\n"
      "plot '%s' using 1:3 with lines lw 2 title 'left wheel', "
      "'%s' using 1:4 with lines lw 2 title 'right wheel'\n"
      "unset multiplot\n",
      png_path.c_str(), title.c_str(), data.c_str(), data.c_str(), data.c_str());
  host::run_gnuplot_with_data(script, png_path, data);
}

}  // namespace tread::contact
