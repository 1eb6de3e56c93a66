#include "contact/equivalent_conicity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tread::contact {

double delta_r_at(const ContactTable& table, double y_mm) {
  const std::size_t n = table.delta_r_mm.size();
  if (n < 2) {
    throw std::domain_error("delta r table has fewer than 2 points");
  }
  const double u = (y_mm - table.y_first_mm) / table.y_step_mm;
  const double last = static_cast<double>(n - 1);
  if (u < -1e-9 || u > last + 1e-9) {
    throw std::domain_error("y = " + std::to_string(y_mm) + " mm is outside the delta r table [" +
                            std::to_string(table.y_first_mm) + ", " +
                            std::to_string(table.y_first_mm + last * table.y_step_mm) + "]");
  }
  const double uc = std::min(std::max(u, 0.0), last);
  const auto i = std::min(static_cast<std::size_t>(uc), n - 2);
  const double t = uc - static_cast<double>(i);
  return table.delta_r_mm[i] + t * (table.delta_r_mm[i + 1] - table.delta_r_mm[i]);
}

namespace {

/// Root of delta r nearest to y = 0 (linear interpolation between table points).
double centre_of(const ContactTable& table) {
  const auto& y = table.y_mm;
  const auto& d = table.delta_r_mm;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < d.size(); ++i) {
    if ((d[i] <= 0.0 && d[i + 1] >= 0.0) || (d[i] >= 0.0 && d[i + 1] <= 0.0)) {
      const double span = d[i + 1] - d[i];
      const double root = std::abs(span) > 0.0 ? y[i] - d[i] * (y[i + 1] - y[i]) / span : y[i];
      if (std::abs(root) < std::abs(best)) {
        best = root;
      }
    }
  }
  if (!std::isfinite(best)) {
    throw std::domain_error("delta r has no root in the table: no centred motion");
  }
  return best;
}

}  // namespace

ConicityResult equivalent_conicity(const ContactTable& table, double amplitude_mm,
                                   const ConicityOptions& options) {
  if (!(amplitude_mm > 0.0)) {
    throw std::domain_error("amplitude must be > 0");
  }
  const double yc = centre_of(table);
  const double k = 1.0 / (2.0 * options.e0_mm * options.r0_mm);
  auto accel = [&](double y) { return -k * delta_r_at(table, y); };
  double x = 0.0;
  double y = yc + amplitude_mm;
  double v = 0.0;
  const double h = options.step_mm;
  double crossings[3] = {0.0, 0.0, 0.0};
  int found = 0;
  // Give up after 50 linear wavelengths of the smallest plausible conicity (0.001).
  const double x_max = 50.0 * 2.0 * std::numbers::pi * std::sqrt(1.0 / (k * 2.0 * 0.001));
  while (found < 3) {
    if (x > x_max) {
      throw std::domain_error("no oscillation at amplitude " + std::to_string(amplitude_mm) +
                              " mm (delta r does not restore the wheelset)");
    }
    // Classical RK4 on (y, v).
    const double k1y = v;
    const double k1v = accel(y);
    const double k2y = v + 0.5 * h * k1v;
    const double k2v = accel(y + 0.5 * h * k1y);
    const double k3y = v + 0.5 * h * k2v;
    const double k3v = accel(y + 0.5 * h * k2y);
    const double k4y = v + h * k3v;
    const double k4v = accel(y + h * k3y);
    const double y_next = y + h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
    const double v_next = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    const double a = y - yc;
    const double b = y_next - yc;
    if ((a > 0.0 && b <= 0.0) || (a < 0.0 && b >= 0.0)) {
      crossings[found++] = x + h * a / (a - b);
    }
    x += h;
    y = y_next;
    v = v_next;
  }
  ConicityResult out;
  out.centre_y_mm = yc;
  out.wavelength_mm = crossings[2] - crossings[0];
  const double w = 2.0 * std::numbers::pi / out.wavelength_mm;
  out.tan_gamma_e = options.e0_mm * options.r0_mm * w * w;
  return out;
}

double linearised_conicity(const ContactTable& table, double amplitude_mm) {
  if (!(amplitude_mm > 0.0)) {
    throw std::domain_error("amplitude must be > 0");
  }
  const double yc = centre_of(table);
  constexpr int kSamples = 3600;
  double sy = 0.0;
  double sd = 0.0;
  double syy = 0.0;
  double syd = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double phi = 2.0 * std::numbers::pi * (static_cast<double>(i) + 0.5) / kSamples;
    const double y = amplitude_mm * std::sin(phi);
    const double d = delta_r_at(table, yc + y);
    sy += y;
    sd += d;
    syy += y * y;
    syd += y * d;
  }
  const double n = kSamples;
  const double slope = (syd - sy * sd / n) / (syy - sy * sy / n);
  return 0.5 * slope;
}

}  // namespace tread::contact
