#include "contact/rigid_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

namespace tread::contact {

namespace {

/// Piecewise-linear evaluation at non-decreasing abscissae: amortised O(1) per call.
class Cursor {
 public:
  Cursor(std::span<const double> y, std::span<const double> z, double shift)
      : y_(y), z_(z), shift_(shift) {}
  double at(double s) {
    const double x = s - shift_;
    while (k_ + 2 < y_.size() && y_[k_ + 1] < x) {
      ++k_;
    }
    const double t = std::clamp((x - y_[k_]) / (y_[k_ + 1] - y_[k_]), 0.0, 1.0);
    return z_[k_] + t * (z_[k_ + 1] - z_[k_]);
  }

 private:
  std::span<const double> y_;
  std::span<const double> z_;
  double shift_;
  std::size_t k_ = 0;
};

/// Least-squares parabola f = a0 + a1 d + a2 d^2; returns the vertex offset or NaN.
double parabola_vertex(std::span<const double> d, std::span<const double> f) {
  std::array<double, 5> m{};  // sums of d^0..d^4
  std::array<double, 3> r{};  // sums of f d^0..d^2
  for (std::size_t k = 0; k < d.size(); ++k) {
    double p = 1.0;
    for (std::size_t e = 0; e < 5; ++e) {
      m[e] += p;
      if (e < 3) {
        r[e] += p * f[k];
      }
      p *= d[k];
    }
  }
  // Solve the 3x3 normal equations by Cramer's rule.
  const double a00 = m[0], a01 = m[1], a02 = m[2], a11 = m[2], a12 = m[3], a22 = m[4];
  const double det =
      a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22 - a12 * a02) + a02 * (a01 * a12 - a11 * a02);
  if (!(std::abs(det) > 0.0)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double det1 = a00 * (r[1] * a22 - a12 * r[2]) - r[0] * (a01 * a22 - a12 * a02) +
                      a02 * (a01 * r[2] - r[1] * a02);
  const double det2 = a00 * (a11 * r[2] - r[1] * a12) - a01 * (a01 * r[2] - r[1] * a02) +
                      r[0] * (a01 * a12 - a11 * a02);
  const double a1 = det1 / det;
  const double a2 = det2 / det;
  if (!(a2 < 0.0)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return -a1 / (2.0 * a2);
}

}  // namespace

RigidContact::RigidContact(const profile::SampledProfile& wheel_left,
                           const profile::SampledProfile& wheel_right,
                           const profile::SampledProfile& rail_track, const WheelsetSetup& setup,
                           const SearchSettings& settings)
    : wheel_left_(wheel_left),
      wheel_right_(wheel_right),
      rail_(rail_track),
      setup_(setup),
      settings_(settings) {}

WheelContact RigidContact::solve(const ProfileFunction& wheel, double shift_mm,
                                 double r0_mm) const {
  // Rail point s (track frame) meets wheel point y_w = s - shift_mm. The vertical gap is
  // const - (z_wheel + z_rail): its minimum is the maximum of f = z_wheel + z_rail.
  const auto ry = rail_.y_mm();
  const auto wy = wheel.y_mm();
  const double lo = std::max(ry.front(), wy.front() + shift_mm);
  const double hi = std::min(ry.back(), wy.back() + shift_mm);
  if (!(hi > lo)) {
    throw std::domain_error("wheel '" + wheel.name() + "' and rail '" + rail_.name() +
                            "' do not overlap laterally (shift " + std::to_string(shift_mm) +
                            " mm)");
  }
  std::vector<double> s;
  std::vector<double> f;
  s.reserve(ry.size() + wy.size() + 2);
  f.reserve(ry.size() + wy.size() + 2);
  Cursor rail_at(ry, rail_.z_mm(), 0.0);
  Cursor wheel_at(wy, wheel.z_mm(), shift_mm);
  auto push = [&](double sv) {
    if (s.empty() || sv > s.back()) {
      s.push_back(sv);
      f.push_back(rail_at.at(sv) + wheel_at.at(sv));
    }
  };
  std::size_t i = static_cast<std::size_t>(std::upper_bound(ry.begin(), ry.end(), lo) - ry.begin());
  std::size_t j =
      static_cast<std::size_t>(std::upper_bound(wy.begin(), wy.end(), lo - shift_mm) - wy.begin());
  push(lo);
  while (true) {
    const double si = i < ry.size() ? ry[i] : std::numeric_limits<double>::infinity();
    const double sj = j < wy.size() ? wy[j] + shift_mm : std::numeric_limits<double>::infinity();
    const double sn = std::min(si, sj);
    if (!(sn < hi)) {
      break;
    }
    push(sn);
    if (si <= sj) {
      ++i;
    } else {
      ++j;
    }
  }
  push(hi);

  const auto best = static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin());
  const double s_best = s[best];
  const double f_best = f[best];

  // Best other local maximum at a distance: a second (two-point) contact candidate.
  WheelContact out;
  out.second_gap_mm = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (std::abs(s[k] - s_best) < settings_.second_contact_min_distance_mm) {
      continue;
    }
    const bool left_ok = k == 0 || f[k] >= f[k - 1];
    const bool right_ok = k + 1 == s.size() || f[k] >= f[k + 1];
    if (left_ok && right_ok && f_best - f[k] < out.second_gap_mm) {
      out.second_gap_mm = f_best - f[k];
      out.y_rail_second_mm = s[k];
    }
  }

  // Refinement: parabola through the gap samples around the discrete minimum.
  double s_c = s_best;
  const double w = settings_.refine_half_window_mm;
  if (w > 0.0) {
    std::size_t a = best;
    std::size_t b = best;
    while (a > 0 && s[a - 1] >= s_best - w) {
      --a;
    }
    while (b + 1 < s.size() && s[b + 1] <= s_best + w) {
      ++b;
    }
    if (b - a + 1 >= 5) {
      std::vector<double> d(b - a + 1);
      for (std::size_t k = a; k <= b; ++k) {
        d[k - a] = s[k] - s_best;
      }
      const double v = parabola_vertex(d, std::span<const double>(f).subspan(a, b - a + 1));
      if (std::isfinite(v) && std::abs(v) <= 0.5 * w) {
        s_c = s_best + v;
      }
    }
  }
  out.y_rail_mm = s_c;
  out.at_profile_end = s_c <= lo + 1e-9 || s_c >= hi - 1e-9;
  const ContactPoint main = describe(wheel, s_c, shift_mm, r0_mm);
  out.y_wheel_mm = main.y_wheel_mm;
  out.r_mm = main.r_mm;
  out.gamma_rad = main.gamma_rad;
  out.lateral_relative_curvature_per_mm = main.lateral_relative_curvature_per_mm;
  if (std::isfinite(out.second_gap_mm)) {
    out.second = describe(wheel, out.y_rail_second_mm, shift_mm, r0_mm);
  }
  return out;
}

ContactPoint RigidContact::describe(const ProfileFunction& wheel, double y_rail_mm, double shift_mm,
                                    double r0_mm) const {
  ContactPoint p;
  p.y_wheel_mm = y_rail_mm - shift_mm;
  p.r_mm = r0_mm + wheel.z_at(p.y_wheel_mm);
  p.gamma_rad = std::atan(-wheel.slope_at(p.y_wheel_mm, settings_.slope_half_window_mm));
  const double c = std::cos(p.gamma_rad);
  p.lateral_relative_curvature_per_mm =
      -(wheel.curvature_at(p.y_wheel_mm, settings_.curvature_half_window_mm) +
        rail_.curvature_at(y_rail_mm, settings_.curvature_half_window_mm)) *
      c * c * c;
  return p;
}

ContactState RigidContact::at(double y_mm) const {
  // Wheel taping lines sit at +-(b2b/2 + 70) from the track centre; the rail frame origin at +-750.
  const double d = 0.5 * setup_.back_to_back_mm + kTapingLineFromBack_mm - kTrackFrameOrigin_mm;
  ContactState out;
  out.y_mm = y_mm;
  out.left = solve(wheel_left_, d + y_mm, setup_.r0_left_mm);
  out.right = solve(wheel_right_, d - y_mm, setup_.r0_right_mm);
  return out;
}

ContactTable RigidContact::table(double y_min_mm, double y_max_mm, double step_mm) const {
  if (!(step_mm > 0.0) || !(y_max_mm >= y_min_mm)) {
    throw std::invalid_argument("contact table: need step > 0 and y_max >= y_min");
  }
  const auto n = static_cast<std::size_t>(std::floor((y_max_mm - y_min_mm) / step_mm + 1e-3)) + 1;
  ContactTable t;
  t.y_first_mm = y_min_mm;
  t.y_step_mm = step_mm;
  for (std::size_t k = 0; k < n; ++k) {
    const double y = y_min_mm + static_cast<double>(k) * step_mm;
    const ContactState c = at(y);
    t.y_mm.push_back(y);
    t.r_left_mm.push_back(c.left.r_mm);
    t.r_right_mm.push_back(c.right.r_mm);
    t.delta_r_mm.push_back(c.delta_r_mm());
    t.gamma_left_rad.push_back(c.left.gamma_rad);
    t.gamma_right_rad.push_back(c.right.gamma_rad);
    t.yc_left_mm.push_back(c.left.y_wheel_mm);
    t.yc_right_mm.push_back(c.right.y_wheel_mm);
    t.yr_left_mm.push_back(c.left.y_rail_mm);
    t.yr_right_mm.push_back(c.right.y_rail_mm);
    t.second_gap_left_mm.push_back(c.left.second_gap_mm);
    t.second_gap_right_mm.push_back(c.right.second_gap_mm);
    t.at_profile_end.push_back(c.left.at_profile_end || c.right.at_profile_end);
  }
  return t;
}

ContactTable contact_table(const profile::SampledProfile& wheel_left,
                           const profile::SampledProfile& wheel_right,
                           const profile::SampledProfile& rail_track, const WheelsetSetup& setup,
                           double y_min_mm, double y_max_mm, double step_mm) {
  return RigidContact(wheel_left, wheel_right, rail_track, setup)
      .table(y_min_mm, y_max_mm, step_mm);
}

}  // namespace tread::contact
