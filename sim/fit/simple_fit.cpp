#include "fit/simple_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "io/text_line.hpp"
#include "pac/pac_math.hpp"
#include "plot/gnuplot.hpp"

namespace tread::fit {
namespace {

using host::text::format_significant;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kCMin = 1.0 + 1e-6, kCMax = 3.0 - 1e-6;  // the seed's 1 < C < 3
constexpr double kEMax = 1.0 - 1e-6, kEMin = -20.0;       // E < 1; the lower bound keeps E sane
constexpr double kEAsymMax = 0.99;                        // |EA| < 1

/// All points of one sweep in one cost function (one Jet pass per point, little overhead).
struct CurveResidual {
  const std::vector<double>* x;
  const std::vector<double>* y;
  double inv_scale;
  template <typename T>
  bool operator()(const T* const k, T* residual) const {
    for (std::size_t i = 0; i < x->size(); ++i) {
      residual[i] = point((*x)[i], (*y)[i], k);
    }
    return true;
  }
  template <typename T>
  T point(double xi, double yi, const T* const k) const {
    const T e = k[3] * (T(1) - k[6] * pac::detail::sgn(T(xi) + k[4]));
    return (pac::detail::magic_formula(k[0], k[1], k[2], e, k[4], k[5], T(xi)) - T(yi)) *
           T(inv_scale);
  }
};

void add_residuals(ceres::Problem& problem, double* k, const std::vector<double>& x,
                   const std::vector<double>& y, double inv_scale, bool asymmetric_e) {
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<CurveResidual, ceres::DYNAMIC, 7>(
                               new CurveResidual{&x, &y, inv_scale}, static_cast<int>(x.size())),
                           nullptr, k);
  problem.SetParameterLowerBound(k, 1, kCMin);
  problem.SetParameterUpperBound(k, 1, kCMax);
  problem.SetParameterLowerBound(k, 3, kEMin);
  problem.SetParameterUpperBound(k, 3, kEMax);
  if (asymmetric_e) {
    problem.SetParameterLowerBound(k, 6, -kEAsymMax);
    problem.SetParameterUpperBound(k, 6, kEAsymMax);
  } else {
    problem.SetManifold(k, new ceres::SubsetManifold(7, {6}));  // EA held at 0
  }
}

double solve(std::array<double, 7>& k, const std::vector<double>& x, const std::vector<double>& y,
             double inv_scale, bool asymmetric_e) {
  ceres::Problem problem;
  add_residuals(problem, k.data(), x, y, inv_scale, asymmetric_e);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return summary.final_cost;
}

std::array<double, 7> standard_deviations(std::array<double, 7>& k, const std::vector<double>& x,
                                          const std::vector<double>& y, double inv_scale,
                                          double cost, bool asymmetric_e) {
  std::array<double, 7> sd;
  sd.fill(kNaN);
  const std::size_t free = asymmetric_e ? 7 : 6;
  if (x.size() <= free) return sd;
  ceres::Problem problem;
  add_residuals(problem, k.data(), x, y, inv_scale, asymmetric_e);
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.num_threads = 1;
  ceres::Covariance covariance(options);
  const std::vector<std::pair<const double*, const double*>> blocks = {{k.data(), k.data()}};
  if (!covariance.Compute(blocks, &problem)) return sd;
  std::array<double, 49> c{};
  if (!covariance.GetCovarianceBlock(k.data(), k.data(), c.data())) return sd;
  const double s2 = 2.0 * cost / static_cast<double>(x.size() - free);  // residual variance
  for (std::size_t i = 0; i < free; ++i) sd[i] = std::sqrt(std::max(0.0, c[i * 7 + i] * s2));
  return sd;
}

SimpleConstants to_constants(const std::array<double, 7>& k) {
  return {k[0], k[1], k[2], k[3], k[4], k[5], k[6]};
}

/// Starting values: a line through the points nearest the origin gives BCD and SV; D the peak.
ChannelFit fit_channel(Channel channel, double fz_n, std::vector<double> x, std::vector<double> y,
                       bool asymmetric_e) {
  // sort by x (deterministic order, and plots)
  std::vector<std::size_t> order(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  ChannelFit fit;
  fit.channel = channel;
  fit.fz_n = fz_n;
  fit.points = x.size();
  for (std::size_t i : order) {
    fit.x.push_back(x[i]);
    fit.y.push_back(y[i]);
  }
  x = fit.x;
  y = fit.y;

  std::vector<std::size_t> near(x.size());
  for (std::size_t i = 0; i < near.size(); ++i) near[i] = i;
  std::stable_sort(near.begin(), near.end(),
                   [&](std::size_t a, std::size_t b) { return std::fabs(x[a]) < std::fabs(x[b]); });
  const std::size_t n_lin = std::max<std::size_t>(5, x.size() / 10);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t j = 0; j < n_lin; ++j) {
    const std::size_t i = near[j];
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double n = static_cast<double>(n_lin);
  const double den = n * sxx - sx * sx;
  double slope = std::fabs(den) > 0.0 ? (n * sxy - sx * sy) / den : 0.0;
  const double intercept = (sy - slope * sx) / n;
  double peak = 0.0, scale = 0.0;
  for (double v : y) {
    peak = std::max(peak, std::fabs(v - intercept));
    scale = std::max(scale, std::fabs(v));
  }
  if (!(peak > 0.0)) peak = 1.0;
  if (!(scale > 0.0)) scale = 1.0;
  if (!(std::fabs(slope) > 0.0)) slope = peak;  // a flat start still has to move
  const double d0 = slope < 0.0 ? -peak : peak;
  const double inv_scale = 1.0 / scale;

  double best_cost = std::numeric_limits<double>::infinity();
  std::array<double, 7> best{};
  for (double c0 : {1.3, 1.9, 2.5}) {
    for (double e0 : {-0.5, 0.5}) {
      std::array<double, 7> k = {slope / (c0 * d0), c0, d0, e0, 0.0, intercept, 0.0};
      const double cost = solve(k, x, y, inv_scale, asymmetric_e);
      if (std::isfinite(cost) && cost < best_cost) {
        best_cost = cost;
        best = k;
      }
    }
  }
  fit.constants = to_constants(best);
  fit.stddev = standard_deviations(best, x, y, inv_scale, best_cost, asymmetric_e);
  double ss_res = 0.0, mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  double ss_tot = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = simple_curve(fit.constants, x[i]) - y[i];
    ss_res += r * r;
    ss_tot += (y[i] - mean) * (y[i] - mean);
  }
  fit.rms = std::sqrt(ss_res / static_cast<double>(x.size()));
  fit.r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : kNaN;
  return fit;
}

std::vector<double> cluster_loads(const MeasurementSet& data, double gap_rel) {
  std::vector<double> fz;
  for (const auto& p : data.points) fz.push_back(p.fz_n);
  std::sort(fz.begin(), fz.end());
  std::vector<double> loads;
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < fz.size(); ++i) {
    if (count > 0 && fz[i] - fz[i - 1] > gap_rel * std::max(std::fabs(fz[i]), 1.0)) {
      loads.push_back(sum / static_cast<double>(count));
      sum = 0.0;
      count = 0;
    }
    sum += fz[i];
    ++count;
  }
  if (count > 0) loads.push_back(sum / static_cast<double>(count));
  return loads;
}

std::size_t nearest(const std::vector<double>& loads, double fz) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < loads.size(); ++i) {
    if (std::fabs(loads[i] - fz) < std::fabs(loads[best] - fz)) best = i;
  }
  return best;
}

}  // namespace

const char* channel_name(Channel c) {
  switch (c) {
    case Channel::fx_kappa:
      return "Fx(kappa)";
    case Channel::fy_alpha:
      return "Fy(alpha)";
    case Channel::mz_alpha:
      return "Mz(alpha)";
  }
  return "?";
}

const char* channel_column(Channel c) {
  switch (c) {
    case Channel::fx_kappa:
      return "Fx_N";
    case Channel::fy_alpha:
      return "Fy_N";
    case Channel::mz_alpha:
      return "Mz_Nm";
  }
  return "?";
}

double simple_curve(const SimpleConstants& k, double x) {
  const double e = k.e * (1.0 - k.ea * pac::detail::sgn(x + k.sh));
  return pac::detail::magic_formula(k.b, k.c, k.d, e, k.sh, k.sv, x);
}

SimpleFit fit_simple(const MeasurementSet& data, const SimpleFitSettings& settings,
                     const std::function<void(const std::string&)>& progress) {
  SimpleFit result;
  result.loads_n = cluster_loads(data, settings.fz_gap_rel);
  for (Channel channel : kChannels) {
    for (std::size_t level = 0; level < result.loads_n.size(); ++level) {
      std::vector<double> x, y;
      for (const auto& p : data.points) {
        if (nearest(result.loads_n, p.fz_n) != level) continue;
        if (std::fabs(p.gamma_rad) > settings.pure_slip_tol) continue;
        double value = kNaN, slip = 0.0;
        if (channel == Channel::fx_kappa) {
          if (std::fabs(p.alpha_rad) > settings.pure_slip_tol) continue;
          value = p.fx_n;
          slip = p.kappa;
        } else {
          if (std::fabs(p.kappa) > settings.pure_slip_tol) continue;
          value = channel == Channel::fy_alpha ? p.fy_n : p.mz_nm;
          slip = p.alpha_rad;
        }
        if (!std::isfinite(value)) continue;
        x.push_back(slip);
        y.push_back(value);
      }
      if (x.size() < settings.min_points) continue;
      const std::size_t count = x.size();
      result.fits.push_back(fit_channel(channel, result.loads_n[level], std::move(x), std::move(y),
                                        settings.asymmetric_e));
      const ChannelFit& f = result.fits.back();
      if (progress) {
        progress(std::string(channel_name(channel)) + " at Fz " + format_significant(f.fz_n, 5) +
                 " N: " + std::to_string(count) + " points, RMS " + format_significant(f.rms, 4) +
                 ", R2 " + format_significant(f.r2, 6));
      }
    }
  }
  return result;
}

SimpleConstants interpolate_constants(const SimpleFit& fit, Channel channel, double fz_n) {
  std::vector<const ChannelFit*> fits;
  for (const auto& f : fit.fits) {
    if (f.channel == channel) fits.push_back(&f);
  }
  if (fits.empty()) throw std::runtime_error(std::string("no fit of ") + channel_name(channel));
  if (fz_n <= fits.front()->fz_n) return fits.front()->constants;
  if (fz_n >= fits.back()->fz_n) return fits.back()->constants;
  std::size_t i = 1;
  while (fits[i]->fz_n < fz_n) ++i;
  const SimpleConstants& a = fits[i - 1]->constants;
  const SimpleConstants& b = fits[i]->constants;
  const double t = (fz_n - fits[i - 1]->fz_n) / (fits[i]->fz_n - fits[i - 1]->fz_n);
  auto lerp = [t](double u, double v) { return u + t * (v - u); };
  return {lerp(a.b, b.b),   lerp(a.c, b.c),   lerp(a.d, b.d),  lerp(a.e, b.e),
          lerp(a.sh, b.sh), lerp(a.sv, b.sv), lerp(a.ea, b.ea)};
}

double slope_at_origin(const SimpleConstants& k) {
  const double h = 1e-6;
  return (simple_curve(k, h) - simple_curve(k, -h)) / (2.0 * h);
}

double peak_abs(const SimpleConstants& k, double x_min, double x_max) {
  double peak = 0.0;
  const int n = 4000;
  for (int i = 0; i <= n; ++i) {
    const double x = x_min + (x_max - x_min) * i / n;
    peak = std::max(peak, std::fabs(simple_curve(k, x)));
  }
  return peak;
}

void write_simple_fit_csv(const SimpleFit& fit, std::ostream& out) {
  out << "channel,fz_N,points";
  for (const char* n : kConstantNames) out << ',' << n;
  for (const char* n : kConstantNames) out << ",sd_" << n;
  out << ",slope_at_origin,rms,r2\n";
  out << std::setprecision(10);
  for (const auto& f : fit.fits) {
    const SimpleConstants& k = f.constants;
    out << channel_column(f.channel) << ',' << f.fz_n << ',' << f.points << ',' << k.b << ',' << k.c
        << ',' << k.d << ',' << k.e << ',' << k.sh << ',' << k.sv << ',' << k.ea;
    for (double s : f.stddev) out << ',' << s;
    out << ',' << slope_at_origin(k) << ',' << f.rms << ',' << f.r2 << '\n';
  }
}

void write_simple_fit_report(const SimpleFit& fit, const std::string& source, std::ostream& out) {
  out << "# tread fit --model simple\n\n"
      << "Input: `" << source << "`. Basic Magic Formula y = D sin(C atan(B x - E (B x - atan(B "
      << "x)))) + SV, x = X + SH, per load; 1 < C < 3, E < 1. Standard deviations from the Ceres "
      << "covariance scaled by the residual variance.\n\nLoad levels (N):";
  for (double fz : fit.loads_n) out << ' ' << format_significant(fz, 6);
  out << "\n";
  for (Channel channel : kChannels) {
    bool any = false;
    for (const auto& f : fit.fits) {
      if (f.channel != channel) continue;
      if (!any) {
        out << "\n## " << channel_name(channel) << "\n\n"
            << "| Fz (N) | points | B | C | D | E | SH | SV | EA | slope at 0 | RMS | R² |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        any = true;
      }
      const std::array<double, 7> k = {f.constants.b,  f.constants.c,  f.constants.d, f.constants.e,
                                       f.constants.sh, f.constants.sv, f.constants.ea};
      out << "| " << format_significant(f.fz_n, 6) << " | " << f.points;
      for (std::size_t i = 0; i < 7; ++i) {
        out << " | " << format_significant(k[i], 5) << " ± " << format_significant(f.stddev[i], 2);
      }
      out << " | " << format_significant(slope_at_origin(f.constants), 6) << " | "
          << format_significant(f.rms, 4) << " | " << format_significant(f.r2, 6) << " |\n";
    }
  }
}

void plot_simple_fit(const SimpleFit& fit, const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (const auto& f : fit.fits) {
    const std::string stem = std::string(channel_column(f.channel)) + "_Fz" +
                             std::to_string(static_cast<long>(std::lround(f.fz_n))) + "N";
    const std::filesystem::path png = std::filesystem::path(dir) / (stem + ".png");
    const std::filesystem::path dat = std::filesystem::path(dir) / (stem + ".dat");
    {
      std::ofstream d(dat);
      d << std::setprecision(10);
      for (std::size_t i = 0; i < f.x.size(); ++i) d << f.x[i] << ' ' << f.y[i] << '\n';
      d << "\n\n";
      const double lo = f.x.front(), hi = f.x.back();
      for (int i = 0; i <= 400; ++i) {
        const double x = lo + (hi - lo) * i / 400.0;
        d << x << ' ' << simple_curve(f.constants, x) << '\n';
      }
      if (!d) throw std::runtime_error(dat.string() + ": cannot write");
    }
    const bool fx = f.channel == Channel::fx_kappa;
    std::string script = host::gnuplot_terminal(png.string(), 900, 650);
    script += "set output " + host::gnuplot_quote(png.string()) + "\n";
    script += "set termoption noenhanced\nset grid\nset key outside bottom center horizontal\n";
    script += "set title " +
              host::gnuplot_quote(std::string(channel_name(f.channel)) +
                                  " at Fz = " + format_significant(f.fz_n, 5) + " N (RMS " +
                                  format_significant(f.rms, 3) + ")") +
              "\n";
    script += std::string("set xlabel ") + (fx ? "'kappa (-)'" : "'alpha (rad)'") + "\n";
    script += std::string("set ylabel ") +
              (fx ? "'Fx (N)'" : (f.channel == Channel::fy_alpha ? "'Fy (N)'" : "'Mz (Nm)'")) +
              "\n";
    script += "plot " + host::gnuplot_quote(dat.string()) +
              " index 0 with points pt 7 ps 0.6 title 'measured', '' index 1 with lines lw 2 "
              "title 'fit'\n";
    host::run_gnuplot_with_data(script, "plot " + png.string(), dat);
  }
}

}  // namespace tread::fit
