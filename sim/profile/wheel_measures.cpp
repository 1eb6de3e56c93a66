#include "profile/wheel_measures.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>

namespace tread::profile {

namespace {

/// y on the flange face (tip_y .. -20, z decreasing with y) where z = level.
double face_y(const WheelProfile& wheel, double tip_y, double level) {
  double lo = tip_y;  // z(lo) >= level
  double hi = -20.0;  // z(hi) < level (on the tread)
  if (!(wheel.at(lo).z_mm >= level) || !(wheel.at(hi).z_mm < level)) {
    throw std::runtime_error(wheel.name() +
                             ": the flange face does not cross z = " + std::to_string(level));
  }
  for (int i = 0; i < 200 && hi - lo > 1e-11; ++i) {
    const double mid = 0.5 * (lo + hi);
    (wheel.at(mid).z_mm >= level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

FlangeMeasures measure_flange(const WheelProfile& wheel) {
  // The tip: the highest point of the flange pieces — an arc apex inside its piece or a junction.
  double tip_y = wheel.y_min_mm();
  double tip_z = wheel.at(tip_y).z_mm;
  const auto consider = [&](double y) {
    const double z = wheel.at(y).z_mm;
    if (z > tip_z) {
      tip_z = z;
      tip_y = y;
    }
  };
  for (const auto& j : wheel.junctions()) {
    if (j.y_mm < -30.0) {
      consider(j.y_mm);
    }
  }
  // Golden-section search inside each flange piece for interior maxima.
  for (std::size_t i = 0; i < wheel.piece_count(); ++i) {
    const double y0 = i == 0 ? wheel.y_min_mm() : wheel.junctions()[i - 1].y_mm;
    const double y1 = i + 1 < wheel.piece_count() ? wheel.junctions()[i].y_mm : wheel.y_max_mm();
    if (y0 > -30.0) {
      break;
    }
    double a = y0;
    double b = y1;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int k = 0; k < 200 && b - a > 1e-12; ++k) {
      const double c = b - g * (b - a);
      const double d = a + g * (b - a);
      if (wheel.piece_at(i, c).z_mm > wheel.piece_at(i, d).z_mm) {
        b = d;
      } else {
        a = c;
      }
    }
    consider(0.5 * (a + b));
  }
  FlangeMeasures m{};
  m.tip_y_mm = tip_y;
  m.height_mm = tip_z;
  m.face_y_at_10_mm = face_y(wheel, tip_y, 10.0);
  m.face_y_below_tip_mm = face_y(wheel, tip_y, tip_z - 2.0);
  m.thickness_mm = m.face_y_at_10_mm - wheel.y_min_mm();
  m.qr_mm = m.face_y_at_10_mm - m.face_y_below_tip_mm;
  return m;
}

}  // namespace tread::profile

namespace tread::profile {

double interpolate_z(const SampledProfile& p, double y) {
  if (p.y_mm.empty() || !(y >= p.y_mm.front() && y <= p.y_mm.back())) {
    std::ostringstream msg;
    msg << p.name << ": y = " << y << " mm is outside the profile";
    if (!p.y_mm.empty()) {
      msg << " [" << p.y_mm.front() << ", " << p.y_mm.back() << "]";
    }
    throw std::out_of_range(msg.str());
  }
  const auto it = std::lower_bound(p.y_mm.begin(), p.y_mm.end(), y);
  const auto i = static_cast<std::size_t>(it - p.y_mm.begin());
  if (i == 0) {
    return p.z_mm.front();
  }
  const double t = (y - p.y_mm[i - 1]) / (p.y_mm[i] - p.y_mm[i - 1]);
  return p.z_mm[i - 1] + t * (p.z_mm[i] - p.z_mm[i - 1]);
}

namespace {

/// The first y > y[tip] where the polyline falls below `level` (linear interpolation).
double sampled_face_y(const SampledProfile& p, std::size_t tip, double level) {
  for (std::size_t i = tip; i + 1 < p.y_mm.size(); ++i) {
    if (p.z_mm[i] >= level && p.z_mm[i + 1] < level) {
      const double t = (p.z_mm[i] - level) / (p.z_mm[i] - p.z_mm[i + 1]);
      return p.y_mm[i] + t * (p.y_mm[i + 1] - p.y_mm[i]);
    }
  }
  std::ostringstream msg;
  msg << p.name << ": the flange face does not fall below z = " << level
      << " mm between the tip and the end of the profile";
  throw std::runtime_error(msg.str());
}

/// The tip between samples: the highest point is sample `i`, but a cusp (two flange arcs meeting,
/// as in EN 13715's thin flanges and worn flanges) usually lies between samples. The lines through
/// the two points on each side of the intervals next to `i` are intersected; an intersection
/// inside its interval and above both its ends is the tip (for a smooth apex it lies above the
/// true apex by at most about step² / (2 R), 0.4 µm at 0.1 mm on R12).
struct Tip {
  double y;
  double z;
};

Tip refine_tip(const SampledProfile& p, std::size_t i) {
  Tip best{p.y_mm[i], p.z_mm[i]};
  const std::size_t n = p.y_mm.size();
  // Interval [a, a + 1], left line through (a - 1, a), right line through (a + 1, a + 2).
  for (std::size_t a : {i - 1, i}) {
    if (i == 0 || a < 1 || a + 2 >= n) {
      continue;
    }
    const double sl = (p.z_mm[a] - p.z_mm[a - 1]) / (p.y_mm[a] - p.y_mm[a - 1]);
    const double sr = (p.z_mm[a + 2] - p.z_mm[a + 1]) / (p.y_mm[a + 2] - p.y_mm[a + 1]);
    if (!(sl > 0.0 && sr < 0.0)) {
      continue;
    }
    // z_a + sl (y - y_a) = z_{a+1} + sr (y - y_{a+1})
    const double y = (p.z_mm[a + 1] - p.z_mm[a] + sl * p.y_mm[a] - sr * p.y_mm[a + 1]) / (sl - sr);
    const double z = p.z_mm[a] + sl * (y - p.y_mm[a]);
    if (y >= p.y_mm[a] && y <= p.y_mm[a + 1] && z >= std::max(p.z_mm[a], p.z_mm[a + 1]) &&
        z > best.z) {
      best = {y, z};
    }
  }
  return best;
}

}  // namespace

SampledWheelMeasures measure_wheel(const SampledProfile& p) {
  if (p.y_mm.size() < 2 || p.y_mm.size() != p.z_mm.size()) {
    throw std::runtime_error(p.name + ": a wheel profile needs at least 2 points");
  }
  if (!(p.y_mm.front() <= -30.0 && p.y_mm.back() >= 0.0)) {
    std::ostringstream msg;
    msg << p.name << ": the profile runs from y = " << p.y_mm.front() << " to " << p.y_mm.back()
        << " mm; measuring the flange needs the flange (y < -30) and the taping line (y = 0) in "
           "this project's wheel convention";
    throw std::runtime_error(msg.str());
  }
  SampledWheelMeasures m{};
  m.taping_z_mm = interpolate_z(p, 0.0);
  std::size_t tip = 0;
  for (std::size_t i = 0; i < p.y_mm.size() && p.y_mm[i] < -30.0; ++i) {
    if (p.z_mm[i] > p.z_mm[tip]) {
      tip = i;
    }
  }
  if (tip == 0) {
    std::ostringstream msg;
    msg << p.name << ": the highest flange point is the profile's first point (y = " << p.y_mm[0]
        << " mm): the flange tip is not in the profile";
    throw std::runtime_error(msg.str());
  }
  FlangeMeasures& f = m.flange;
  const Tip t = refine_tip(p, tip);
  f.tip_y_mm = t.y;
  f.height_mm = t.z - m.taping_z_mm;
  f.face_y_at_10_mm = sampled_face_y(p, tip, m.taping_z_mm + 10.0);
  f.face_y_below_tip_mm = sampled_face_y(p, tip, t.z - 2.0);
  f.thickness_mm = f.face_y_at_10_mm + 70.0;
  f.qr_mm = f.face_y_at_10_mm - f.face_y_below_tip_mm;

  // Hollow: the largest z[j] - min(z[i], i < j) on the tread, from the face point on.
  m.hollow_bottom_y_mm = f.face_y_at_10_mm;
  m.false_flange_y_mm = f.face_y_at_10_mm;
  std::size_t lowest = p.y_mm.size();
  for (std::size_t j = 0; j < p.y_mm.size(); ++j) {
    if (p.y_mm[j] < f.face_y_at_10_mm) {
      continue;
    }
    if (lowest == p.y_mm.size() || p.z_mm[j] < p.z_mm[lowest]) {
      lowest = j;
    }
    const double rise = p.z_mm[j] - p.z_mm[lowest];
    if (rise > m.hollow_depth_mm) {
      m.hollow_depth_mm = rise;
      m.hollow_bottom_y_mm = p.y_mm[lowest];
      m.false_flange_y_mm = p.y_mm[j];
    }
  }

  // Outer slope: least squares over y ∈ [38, 58].
  constexpr double kSlopeFrom_mm = 38.0;
  constexpr double kSlopeTo_mm = 58.0;
  if (p.y_mm.front() <= kSlopeFrom_mm && p.y_mm.back() >= kSlopeTo_mm) {
    double n = 0.0, sy = 0.0, sz = 0.0;
    for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
      if (p.y_mm[i] >= kSlopeFrom_mm && p.y_mm[i] <= kSlopeTo_mm) {
        n += 1.0;
        sy += p.y_mm[i];
        sz += p.z_mm[i];
      }
    }
    if (n >= 3.0) {
      const double my = sy / n;
      const double mz = sz / n;
      double syy = 0.0, syz = 0.0;
      for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
        if (p.y_mm[i] >= kSlopeFrom_mm && p.y_mm[i] <= kSlopeTo_mm) {
          syy += (p.y_mm[i] - my) * (p.y_mm[i] - my);
          syz += (p.y_mm[i] - my) * (p.z_mm[i] - mz);
        }
      }
      const double b = syz / syy;
      double ss = 0.0;
      for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
        if (p.y_mm[i] >= kSlopeFrom_mm && p.y_mm[i] <= kSlopeTo_mm) {
          const double r = p.z_mm[i] - (mz + b * (p.y_mm[i] - my));
          ss += r * r;
        }
      }
      m.outer_slope = -b;
      m.outer_slope_rms_mm = std::sqrt(ss / n);
    }
  }
  return m;
}

}  // namespace tread::profile
