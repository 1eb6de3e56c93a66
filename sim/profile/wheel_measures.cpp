#include "profile/wheel_measures.hpp"

#include <cmath>
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
