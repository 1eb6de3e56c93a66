#include "tyre/mf_plot.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "mf/mf_evaluate.hpp"

namespace tread::tyre {

namespace {

mf::MfInput<double> at(double fz, double kappa, double alpha, double vx) {
  mf::MfInput<double> in;
  in.fz_n = fz;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.vx_mps = vx;
  return in;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::vector<double> plot_loads(const mf::MfParameters<double>& params, const MfPlotOptions& plot) {
  if (!plot.loads_n.empty()) return plot.loads_n;
  std::vector<double> loads;
  for (double f : plot.load_factors) loads.push_back(f * params.fnomin_n);
  return loads;
}

std::string clamped_load(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                         double fz_n) {
  if (!options.use_limits) return {};
  char text[64];
  if (fz_n > params.fzmax_n) {
    std::snprintf(text, sizeof text, "FZMAX %.0f N", params.fzmax_n);
    return text;
  }
  return {};  // below FZMIN the forces are not clamped (only Mz's trail takes FZMIN)
}

std::string mf_plot_script(const mf::MfParameters<double>& p, const mf::MfOptions& options,
                           const MfPlotOptions& plot, const std::filesystem::path& output) {
  mf::MfOptions o = options;
  o.extras = false;
  std::ostringstream s;
  s.precision(9);
  const int n = plot.points < 3 ? 3 : plot.points;
  const std::vector<double> loads = plot_loads(p, plot);

  // Fx(κ), Fy(α), Mz(α): one datablock per load, columns: slip, value.
  for (std::size_t l = 0; l < loads.size(); ++l) {
    s << "$fx" << l << " << EOD\n";
    for (int i = 0; i < n; ++i) {
      const double kappa = -1.0 + 2.0 * i / (n - 1);
      s << kappa << ' ' << evaluate(p, at(loads[l], kappa, 0.0, plot.vx_mps), o).fx_n << '\n';
    }
    s << "EOD\n$fy" << l << " << EOD\n";
    for (int i = 0; i < n; ++i) {
      const double alpha = -0.3 + 0.6 * i / (n - 1);
      const mf::MfOutput<double> r = evaluate(p, at(loads[l], 0.0, alpha, plot.vx_mps), o);
      s << alpha * 180.0 / 3.14159265358979 << ' ' << r.fy_n << ' ' << r.mz_nm << '\n';
    }
    s << "EOD\n";
  }
  // Fx(κ, Fz) map. In double, like the curves, not on mf::evaluate_batch's float lanes: its
  // 81 × 41 points and the curves' 2 × 301 per load, at under 0.7 µs each in double (≈ 4 ms),
  // are ~1 % of a `tread mf plot` that runs gnuplot twice (≈ 0.35 s); lanes would save little and
  // make the data written (9 digits) differ from `tread mf eval`'s double values.
  double fz_max = 2.0 * p.fnomin_n;
  for (double fz : loads) fz_max = fz > fz_max ? fz : fz_max;
  s << "$map << EOD\n";
  const int nk = 81;
  const int nf = 41;
  for (int j = 0; j < nf; ++j) {
    const double fz = fz_max * j / (nf - 1);
    for (int i = 0; i < nk; ++i) {
      const double kappa = -0.5 + 1.0 * i / (nk - 1);
      s << kappa << ' ' << fz << ' ' << evaluate(p, at(fz, kappa, 0.0, plot.vx_mps), o).fx_n
        << '\n';
    }
    s << '\n';
  }
  s << "EOD\n";

  const std::string ext = output.extension().string();
  if (ext == ".svg") {
    s << "set terminal svg size 1200,900 dynamic enhanced font 'Sans,11'\n";
  } else if (ext == ".png") {
    s << "set terminal pngcairo size 1400,1000 enhanced font 'Sans,10'\n";
  } else {
    throw std::runtime_error(output.string() + ": output must end in .png or .svg");
  }
  s << "set output " << quoted(output.string()) << "\n";
  s << "set multiplot layout 2,2 title " << quoted(plot.title) << " noenhanced\n";
  s << "set grid\nset key top left box opaque\n";
  auto curves = [&](const std::string& block, const std::string& using_cols) {
    std::string line = "plot ";
    for (std::size_t l = 0; l < loads.size(); ++l) {
      char text[64];
      std::snprintf(text, sizeof text, "Fz = %.0f N", loads[l]);
      std::string title = text;
      if (const std::string bound = clamped_load(p, options, loads[l]); !bound.empty()) {
        title += " (at " + bound + ")";
      }
      line += "$" + block + std::to_string(l) + " using " + using_cols + " with lines lw 2 title " +
              tyre::quoted(title) + (l + 1 < loads.size() ? ", " : "\n");
    }
    return line;
  };
  s << "set title 'Longitudinal force, pure slip'\nset xlabel 'slip ratio {/Symbol k} [-]'\n"
       "set ylabel 'F_x [N]'\n"
    << curves("fx", "1:2");
  s << "set title 'Lateral force, pure slip'\nset xlabel 'slip angle {/Symbol a} [deg]'\n"
       "set ylabel 'F_y [N]'\n"
    << curves("fy", "1:2");
  s << "set title 'Aligning moment, pure slip'\nset xlabel 'slip angle {/Symbol a} [deg]'\n"
       "set ylabel 'M_z [N m]'\n"
    << curves("fy", "1:3");
  s << "set title 'F_x({/Symbol k}, F_z) [N]'\nset xlabel 'slip ratio {/Symbol k} [-]'\n"
       "set ylabel 'F_z [N]'\nset xrange [-0.5:0.5]\nset yrange [0:*]\nset view map\n"
       "unset key\nset palette rgb 33,13,10\nset colorbox\n"
       "splot $map using 1:2:3 with pm3d notitle\n";
  s << "unset multiplot\nset output\n";
  return s.str();
}

}  // namespace tread::tyre
