#include "tyre/mf_curve_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/text_line.hpp"
#include "mf/mf_evaluate.hpp"

namespace tread::tyre {

namespace {

using host::text::format_significant;

struct Pure {
  double kx = 0.0;       // dFx/dκ at κ = 0, N
  double ky = 0.0;       // dFy/dα at α = 0, N/rad
  double drive = 0.0;    // max Fx, 0 < κ ≤ 1
  double brake = 0.0;    // min Fx, -1 ≤ κ < 0
  double fy_peak = 0.0;  // max |Fy|, |α| ≤ 0.5 rad
};

Pure pure_at(const mf::MfParameters<double>& p, const mf::MfOptions& o, double fz, double vx) {
  auto eval = [&](double kappa, double alpha) {
    mf::MfInput<double> in;
    in.fz_n = fz;
    in.kappa = kappa;
    in.alpha_rad = alpha;
    in.vx_mps = vx;
    return evaluate(p, in, o);
  };
  Pure r;
  constexpr double h = 1e-3;
  r.kx = (eval(h, 0.0).fx_n - eval(-h, 0.0).fx_n) / (2.0 * h);
  r.ky = (eval(0.0, h).fy_n - eval(0.0, -h).fy_n) / (2.0 * h);
  r.drive = -1e300;
  r.brake = 1e300;
  for (int i = 1; i <= 100; ++i) {
    const double kappa = 0.01 * i;
    r.drive = std::max(r.drive, eval(kappa, 0.0).fx_n);
    r.brake = std::min(r.brake, eval(-kappa, 0.0).fx_n);
    const double alpha = 0.005 * i;
    r.fy_peak =
        std::max({r.fy_peak, std::fabs(eval(0.0, alpha).fy_n), std::fabs(eval(0.0, -alpha).fy_n)});
  }
  return r;
}

}  // namespace

std::vector<std::string> curve_warnings(const mf::MfParameters<double>& p,
                                        const mf::MfOptions& options,
                                        const std::vector<double>& loads_n, double vx_mps) {
  mf::MfOptions o = options;
  o.extras = false;
  const double lo = std::max(p.fzmin_n, 0.1 * p.fnomin_n);
  const double hi = p.fzmax_n > lo ? p.fzmax_n : 2.0 * p.fnomin_n;
  std::vector<double> loads;
  for (int i = 0; i <= 40; ++i) loads.push_back(lo + (hi - lo) * i / 40.0);
  for (double fz : loads_n) {
    if (fz > 0.0) loads.push_back(fz);
  }
  std::sort(loads.begin(), loads.end());
  loads.erase(std::unique(loads.begin(), loads.end()), loads.end());

  std::vector<std::string> warnings;
  bool kx_bad = false, drive_bad = false, brake_bad = false, ky_bad = false, mu_big = false;
  double mux_first = 0.0, muy_first = 0.0;
  const std::string at = " at Fz = ";
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const double fz = loads[i];
    const Pure r = pure_at(p, o, fz, vx_mps);
    const std::string where = at + format_significant(fz, 6) + " N";
    if (!kx_bad && !(r.kx > 0.0)) {
      kx_bad = true;
      warnings.push_back("Fx(kappa): slip stiffness dFx/dkappa = " + format_significant(r.kx, 4) +
                         " N" + where + " (expected > 0)");
    }
    if (!drive_bad && !(r.drive > 0.0)) {
      drive_bad = true;
      warnings.push_back("Fx peak changes sign below FZMAX: max Fx(0 < kappa <= 1) = " +
                         format_significant(r.drive, 4) + " N" + where);
    }
    if (!brake_bad && !(r.brake < 0.0)) {
      brake_bad = true;
      warnings.push_back("Fx peak changes sign below FZMAX: min Fx(-1 <= kappa < 0) = " +
                         format_significant(r.brake, 4) + " N" + where);
    }
    if (!ky_bad && !(r.ky < 0.0)) {
      ky_bad = true;
      warnings.push_back("Fy(alpha) has the wrong sign of cornering stiffness: dFy/dalpha = " +
                         format_significant(r.ky, 4) + " N/rad" + where +
                         " (ISO-W: alpha > 0 gives Fy < 0, so expected < 0)");
    }
    const double mux = std::max(std::fabs(r.drive), std::fabs(r.brake)) / fz;
    const double muy = r.fy_peak / fz;
    if (!mu_big && (mux > 3.0 || muy > 3.0)) {
      mu_big = true;
      warnings.push_back("friction beyond reason: mux = " + format_significant(mux, 3) +
                         ", muy = " + format_significant(muy, 3) + where);
    }
    if (i == 0) {
      mux_first = mux;
      muy_first = muy;
    }
    if (i + 1 == loads.size() && loads.size() > 1) {
      const std::string span = " from Fz = " + format_significant(loads.front(), 6) + " N to " +
                               format_significant(fz, 6) + " N";
      if (mux > 1.1 * mux_first && mux_first > 0.0) {
        warnings.push_back("mux rises with load: " + format_significant(mux_first, 3) + " → " +
                           format_significant(mux, 3) + span);
      }
      if (muy > 1.1 * muy_first && muy_first > 0.0) {
        warnings.push_back("muy rises with load: " + format_significant(muy_first, 3) + " → " +
                           format_significant(muy, 3) + span);
      }
    }
  }
  return warnings;
}

}  // namespace tread::tyre
