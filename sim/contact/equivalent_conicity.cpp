#include "contact/equivalent_conicity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tread::contact {

namespace {

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

std::string at_amplitude(double amplitude_mm) {
  return "amplitude " + mm(amplitude_mm) + " mm: ";
}

/// delta r (piecewise linear in the table) and its integral V(y) (piecewise quadratic, exact).
class DeltaR {
 public:
  explicit DeltaR(const ContactTable& t)
      : d_(t.delta_r_mm), y0_(t.y_first_mm), h_(t.y_step_mm), v_(t.delta_r_mm.size(), 0.0) {
    if (d_.size() < 2) {
      throw std::domain_error("delta r table has fewer than 2 points");
    }
    if (!(h_ > 0.0)) {
      throw std::domain_error("delta r table has no positive y step");
    }
    for (std::size_t i = 0; i + 1 < d_.size(); ++i) {
      v_[i + 1] = v_[i] + 0.5 * h_ * (d_[i] + d_[i + 1]);
    }
  }
  double lo() const { return y0_; }
  double hi() const { return y0_ + static_cast<double>(d_.size() - 1) * h_; }
  double step() const { return h_; }
  std::size_t size() const { return d_.size(); }
  double node_y(std::size_t i) const { return y0_ + static_cast<double>(i) * h_; }
  double node_d(std::size_t i) const { return d_[i]; }
  double node_v(std::size_t i) const { return v_[i]; }

  double d(double y) const {
    const auto [i, t] = locate(y);
    return d_[i] + t * (d_[i + 1] - d_[i]);
  }
  double v(double y) const {
    const auto [i, t] = locate(y);
    return v_[i] + h_ * t * (d_[i] + 0.5 * t * (d_[i + 1] - d_[i]));
  }

 private:
  std::pair<std::size_t, double> locate(double y) const {
    const double last = static_cast<double>(d_.size() - 1);
    const double u = std::clamp((y - y0_) / h_, 0.0, last);
    const auto i = std::min(static_cast<std::size_t>(u), d_.size() - 2);
    return {i, u - static_cast<double>(i)};
  }

  std::vector<double> d_;
  double y0_;
  double h_;
  std::vector<double> v_;
};

constexpr double kZero = 1e-12;  // |delta r| (mm) treated as exactly zero

/// Stretches [a, b] of the table over which delta r is 0 at every node (so 0 in between).
std::vector<std::pair<double, double>> zero_runs(const DeltaR& f) {
  std::vector<std::pair<double, double>> runs;
  std::size_t i = 0;
  while (i < f.size()) {
    if (std::abs(f.node_d(i)) > kZero) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < f.size() && std::abs(f.node_d(j + 1)) <= kZero) {
      ++j;
    }
    if (j > i) {
      runs.emplace_back(f.node_y(i), f.node_y(j));
    }
    i = j + 1;
  }
  return runs;
}

/// The point of [a, b] nearest to 0.
double nearest_zero(double a, double b) {
  return std::clamp(0.0, a, b);
}

/// Roots y of delta r where it rises through 0 (stable points of the kinematic motion).
std::vector<double> stable_roots(const DeltaR& f) {
  std::vector<double> roots;
  for (std::size_t i = 0; i + 1 < f.size(); ++i) {
    const double a = f.node_d(i);
    const double b = f.node_d(i + 1);
    if (a < 0.0 && b >= 0.0) {
      roots.push_back(f.node_y(i) + f.step() * a / (a - b));
    }
  }
  return roots;
}

/// Why no oscillation was found (called after the search failed).
std::string why_no_oscillation(const DeltaR& f, double amplitude_mm) {
  const std::string range = "[" + mm(f.lo()) + ", " + mm(f.hi()) + "] mm";
  const auto roots = stable_roots(f);
  if (roots.empty() && zero_runs(f).empty()) {
    return at_amplitude(amplitude_mm) + "no oscillation: delta r never rises through 0 in " +
           range + ", it does not restore the wheelset";
  }
  return at_amplitude(amplitude_mm) + "no oscillation of this amplitude stays inside the delta r " +
         "table " + range + " (a wider table or a smaller amplitude is needed)";
}

/// Wavelength of the oscillation between the turning points y1 < y2 (V(y1) = V(y2)).
double period_integral(const DeltaR& f, double y1, double y2, const ConicityOptions& o) {
  const double k = 1.0 / (2.0 * o.e0_mm * o.r0_mm);
  const double c = 0.5 * (y1 + y2);
  const double a = 0.5 * (y2 - y1);
  const double level = 0.5 * (f.v(y1) + f.v(y2));
  const int n = std::max(o.quadrature_points, 100);
  const double dth = std::numbers::pi / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double th = -0.5 * std::numbers::pi + (static_cast<double>(i) + 0.5) * dth;
    const double gap = level - f.v(c + a * std::sin(th));
    if (gap > 0.0) {
      sum += a * std::cos(th) / std::sqrt(2.0 * k * gap);
    }
  }
  return 2.0 * sum * dth;
}

}  // namespace

double delta_r_at(const ContactTable& table, double y_mm) {
  const std::size_t n = table.delta_r_mm.size();
  if (n < 2) {
    throw std::domain_error("delta r table has fewer than 2 points");
  }
  const double u = (y_mm - table.y_first_mm) / table.y_step_mm;
  const double last = static_cast<double>(n - 1);
  if (u < -1e-9 || u > last + 1e-9) {
    throw std::domain_error("y = " + mm(y_mm) + " mm is outside the delta r table [" +
                            mm(table.y_first_mm) + ", " +
                            mm(table.y_first_mm + last * table.y_step_mm) + "]");
  }
  const double uc = std::min(std::max(u, 0.0), last);
  const auto i = std::min(static_cast<std::size_t>(uc), n - 2);
  const double t = uc - static_cast<double>(i);
  return table.delta_r_mm[i] + t * (table.delta_r_mm[i + 1] - table.delta_r_mm[i]);
}

ContactTable delta_r_table(double y_first_mm, double y_step_mm,
                           const std::vector<double>& delta_r) {
  if (delta_r.size() < 2 || !(y_step_mm > 0.0)) {
    throw std::invalid_argument("a delta r table needs 2 or more points and a step > 0");
  }
  ContactTable t;
  t.y_first_mm = y_first_mm;
  t.y_step_mm = y_step_mm;
  t.delta_r_mm = delta_r;
  for (std::size_t i = 0; i < delta_r.size(); ++i) {
    t.y_mm.push_back(y_first_mm + static_cast<double>(i) * y_step_mm);
  }
  return t;
}

ConicityResult equivalent_conicity(const ContactTable& table, double amplitude_mm,
                                   const ConicityOptions& options) {
  if (!(amplitude_mm > 0.0)) {
    throw std::domain_error("amplitude must be > 0");
  }
  const DeltaR f(table);
  const double span = 2.0 * amplitude_mm;
  if (f.hi() - f.lo() < span) {
    throw std::domain_error(at_amplitude(amplitude_mm) + "the motion (" + mm(span) +
                            " mm wide) is wider than the delta r table [" + mm(f.lo()) + ", " +
                            mm(f.hi()) + "] mm");
  }
  std::optional<ConicityResult> best;
  auto offer = [&](const ConicityResult& r) {
    if (!best || std::abs(r.centre_y_mm) < std::abs(best->centre_y_mm)) {
      best = r;
    }
  };
  // Neutral equilibrium: delta r = 0 over a whole stretch of 2 * amplitude.
  for (const auto& [a, b] : zero_runs(f)) {
    if (b - a >= span - 1e-9) {
      ConicityResult r;
      r.neutral = true;
      r.centre_y_mm = nearest_zero(a + amplitude_mm, b - amplitude_mm);
      r.y_min_mm = r.centre_y_mm - amplitude_mm;
      r.y_max_mm = r.centre_y_mm + amplitude_mm;
      r.wavelength_mm = std::numeric_limits<double>::infinity();
      r.tan_gamma_e = 0.0;
      offer(r);
    }
  }
  // Oscillations: roots y1 of g(y1) = V(y1 + 2a) - V(y1) with V below that level in between.
  auto g = [&](double y1) { return f.v(y1 + span) - f.v(y1); };
  const double y1_hi = f.hi() - span;
  const double dy = 0.25 * f.step();
  const auto steps = static_cast<long>(std::ceil((y1_hi - f.lo()) / dy));
  auto is_orbit = [&](double y1, double y2) {
    const double level = 0.5 * (f.v(y1) + f.v(y2));
    const double tol = 1e-12 * (1.0 + std::abs(level));
    const double probe = 1e-6 * amplitude_mm;
    if (!(f.v(y1 + probe) < level) || !(f.v(y2 - probe) < level)) {
      return false;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      const double y = f.node_y(i);
      if (y > y1 + probe && y < y2 - probe && !(f.node_v(i) < level - tol)) {
        return false;
      }
    }
    // Between nodes V is quadratic: check the midpoints too (a maximum between two nodes).
    for (int i = 1; i < 64; ++i) {
      const double y = y1 + span * i / 64.0;
      if (!(f.v(y) < level - tol)) {
        return false;
      }
    }
    return true;
  };
  double prev_y = f.lo();
  double prev_g = g(prev_y);
  for (long s = 1; s <= steps; ++s) {
    const double y = std::min(f.lo() + static_cast<double>(s) * dy, y1_hi);
    const double gy = g(y);
    if ((prev_g < 0.0 && gy >= 0.0) || (prev_g > 0.0 && gy <= 0.0)) {
      double a = prev_y;
      double b = y;
      double ga = prev_g;
      for (int it = 0; it < 100 && b - a > 1e-13; ++it) {
        const double m = 0.5 * (a + b);
        const double gm = g(m);
        if ((ga < 0.0) == (gm < 0.0)) {
          a = m;
          ga = gm;
        } else {
          b = m;
        }
      }
      const double y1 = 0.5 * (a + b);
      const double y2 = y1 + span;
      if (is_orbit(y1, y2)) {
        ConicityResult r;
        r.y_min_mm = y1;
        r.y_max_mm = y2;
        r.centre_y_mm = 0.5 * (y1 + y2);
        r.wavelength_mm = period_integral(f, y1, y2, options);
        const double w = 2.0 * std::numbers::pi / r.wavelength_mm;
        r.tan_gamma_e = options.e0_mm * options.r0_mm * w * w;
        offer(r);
      }
    }
    prev_y = y;
    prev_g = gy;
  }
  if (!best) {
    throw std::domain_error(why_no_oscillation(f, amplitude_mm));
  }
  return *best;
}

RegressionResult linearised_conicity(const ContactTable& table, double amplitude_mm) {
  if (!(amplitude_mm > 0.0)) {
    throw std::domain_error("amplitude must be > 0");
  }
  const DeltaR f(table);
  const double c_lo = f.lo() + amplitude_mm;
  const double c_hi = f.hi() - amplitude_mm;
  if (!(c_hi >= c_lo)) {
    throw std::domain_error(at_amplitude(amplitude_mm) + "the motion (" + mm(2.0 * amplitude_mm) +
                            " mm wide) is wider than the delta r table [" + mm(f.lo()) + ", " +
                            mm(f.hi()) + "] mm");
  }
  // Mean of delta r over the cycle about c, with n phase samples.
  auto mean_at = [&](double c, int n) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
      const double phi = 2.0 * std::numbers::pi * (static_cast<double>(i) + 0.5) / n;
      s += f.d(c + amplitude_mm * std::sin(phi));
    }
    return s / n;
  };
  constexpr int kCoarse = 360;
  constexpr int kFine = 3600;
  std::optional<double> centre;
  auto offer = [&](double c) {
    if (!centre || std::abs(c) < std::abs(*centre)) {
      centre = c;
    }
  };
  const double dc = f.step();
  const auto steps = static_cast<long>(std::ceil((c_hi - c_lo) / dc));
  double prev_c = c_lo;
  double prev_m = mean_at(prev_c, kCoarse);
  if (std::abs(prev_m) <= kZero) {
    offer(prev_c);
  }
  for (long s = 1; s <= steps; ++s) {
    const double c = std::min(c_lo + static_cast<double>(s) * dc, c_hi);
    const double m = mean_at(c, kCoarse);
    if (std::abs(m) <= kZero) {
      offer(c);  // neutral stretch: delta r = 0 over the whole cycle
    } else if (prev_m < 0.0 && m > 0.0) {
      // The mean rises through 0 (a stable centre): refine with the fine sampling.
      double a = prev_c;
      double b = c;
      for (int it = 0; it < 60 && b - a > 1e-12; ++it) {
        const double mid = 0.5 * (a + b);
        (mean_at(mid, kFine) < 0.0 ? a : b) = mid;
      }
      offer(0.5 * (a + b));
    }
    prev_c = c;
    prev_m = m;
  }
  if (!centre) {
    const auto roots = stable_roots(f);
    const std::string range = "[" + mm(f.lo()) + ", " + mm(f.hi()) + "] mm";
    throw std::domain_error(
        at_amplitude(amplitude_mm) +
        (roots.empty() && zero_runs(f).empty()
             ? "no centre: delta r never rises through 0 in " + range +
                   ", it does not restore the wheelset"
             : "no centre at which the mean of delta r over the cycle is 0 keeps the motion "
               "inside the delta r table " +
                   range));
  }
  // Least-squares line through (y - y_c, delta r) over the cycle.
  double sy = 0.0;
  double sd = 0.0;
  double syy = 0.0;
  double syd = 0.0;
  for (int i = 0; i < kFine; ++i) {
    const double phi = 2.0 * std::numbers::pi * (static_cast<double>(i) + 0.5) / kFine;
    const double y = amplitude_mm * std::sin(phi);
    const double d = f.d(*centre + y);
    sy += y;
    sd += d;
    syy += y * y;
    syd += y * d;
  }
  const double n = kFine;
  RegressionResult r;
  r.centre_y_mm = *centre;
  r.tan_gamma_e = 0.5 * (syd - sy * sd / n) / (syy - sy * sy / n);
  return r;
}

}  // namespace tread::contact
