#include "tir/pac_plot.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"

namespace tread::tir {

namespace {

pac::PacOutput<double> eval(const pac::PacParams<double>& p, PacModel m, bool iso_w,
                            const pac::PacInput<double>& in, pac::Slip s) {
  const auto r = m == PacModel::kPac89 ? pac::pac89_eval(p, in, s) : pac::pac94_eval(p, in, s);
  return iso_w ? pac::to_iso_w(r) : r;
}

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) {
    if (c == '\'')
      out += "''";  // gnuplot single-quote escape
    else
      out += c;
  }
  return out + "'";
}

}  // namespace

std::string pac_plot_script(const pac::PacParams<double>& p, const PacPlotOptions& o,
                            const std::filesystem::path& output) {
  if (o.points < 2 || o.loads_n.empty()) throw std::invalid_argument("pac plot: nothing to plot");
  for (const double fz : o.loads_n) {
    if (!(fz > 0.0 && fz <= 1e7)) {
      throw std::invalid_argument("pac plot: a load of " + std::to_string(fz) +
                                  " N: loads are numbers above 0 (N)");
    }
  }
  // A load above the limit is evaluated at the limit (the core clamps): its legend says so.
  const auto label = [&](double fz) {
    std::string t = "Fz = " + std::to_string(static_cast<long>(std::lround(fz))) + " N";
    if (fz > p.fz_max_n) {
      t += " (at the load limit " + std::to_string(static_cast<long>(std::lround(p.fz_max_n))) +
           " N)";
    }
    return t;
  };
  std::ostringstream s;
  s.precision(10);
  const std::string ext = output.extension().string();
  if (ext == ".svg") {
    s << "set terminal svg size 1200,900 dynamic\n";
  } else if (ext == ".png") {
    s << "set terminal pngcairo size 1200,900\n";
  } else {
    throw std::invalid_argument("pac plot: output must end in .png or .svg: " + output.string());
  }
  s << "set termoption noenhanced\nset output " << quoted(output.string()) << "\n";
  const int n = o.points;
  for (std::size_t l = 0; l < o.loads_n.size(); ++l) {
    s << "$L" << l << " << EOD\n";
    for (int i = 0; i < n; ++i) {
      const double u = -1.0 + 2.0 * i / (n - 1);
      const double kappa = u * 0.5;  // −50 … 50 %
      const double alpha = u * 0.3;  // −0.3 … 0.3 rad
      const auto fx = eval(p, o.model, o.iso_w, {o.loads_n[l], kappa, 0.0, 0.0}, pac::Slip::kPure);
      const auto fy = eval(p, o.model, o.iso_w, {o.loads_n[l], 0.0, alpha, 0.0}, pac::Slip::kPure);
      s << kappa << ' ' << fx.fx_n << ' ' << alpha * 57.29577951308232 << ' ' << fy.fy_n << ' '
        << fy.mz_nm << '\n';
    }
    s << "EOD\n";
  }
  const double alphas_deg[] = {1.0, 2.0, 4.0, 8.0};
  for (std::size_t j = 0; j < 4; ++j) {
    s << "$C" << j << " << EOD\n";
    for (int i = 0; i < n; ++i) {
      const double kappa = -0.5 + 1.0 * i / (n - 1);
      const auto c =
          eval(p, o.model, o.iso_w, {o.loads_n[0], kappa, alphas_deg[j] / 57.29577951308232, 0.0},
               pac::Slip::kCombined);
      s << c.fx_n << ' ' << c.fy_n << '\n';
    }
    s << "EOD\n";
  }
  s << "set multiplot layout 2,2 title "
    << quoted(o.title + (o.iso_w ? " (ISO-W axes" : " (model axes") + ", pure slip unless noted)")
    << "\nset grid\nset key left top\n";
  auto curves = [&](const char* cols, const char* what) {
    s << "plot ";
    for (std::size_t l = 0; l < o.loads_n.size(); ++l) {
      s << (l ? ", " : "") << "$L" << l << " using " << cols << " with lines title "
        << quoted(label(o.loads_n[l]));
    }
    s << "\n";
    (void)what;
  };
  s << "set title 'Fx(κ)'\nset xlabel 'κ [-]'\nset ylabel 'Fx [N]'\n";
  curves("1:2", "fx");
  s << "set title 'Fy(α)'\nset xlabel 'α [deg]'\nset ylabel 'Fy [N]'\n";
  curves("3:4", "fy");
  s << "set title 'Mz(α)'\nset xlabel 'α [deg]'\nset ylabel 'Mz [N m]'\n";
  curves("3:5", "mz");
  s << "set title " << quoted("combined slip, " + label(o.loads_n[0]) + ", κ −0.5…0.5")
    << "\nset xlabel 'Fx [N]'\nset ylabel 'Fy [N]'\nplot ";
  for (std::size_t j = 0; j < 4; ++j) {
    s << (j ? ", " : "") << "$C" << j
      << " using 1:2 with lines title 'α = " << static_cast<int>(alphas_deg[j]) << "°'";
  }
  s << "\nunset multiplot\nset output\n";
  return s.str();
}

}  // namespace tread::tir
