#include "profile/wheel_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "io/text_line.hpp"
#include "profile/eps_table_d1.hpp"
#include "profile/s1002_uic.hpp"

namespace tread::profile {

namespace {

struct Point {
  double y;
  double z;
};

constexpr double kBackY_mm = -70.0;
constexpr double kFlankAngle_rad = 70.0 * std::numbers::pi / 180.0;
constexpr double kRootRadius_mm = 13.0;
constexpr double kTipRadius_mm = 12.0;
constexpr double kBackRadius_mm = 20.5;
constexpr double kChamfer_mm = 5.0;

bool near(double a, double b) {
  return std::fabs(a - b) < 1e-9;
}

}  // namespace

double outer_slope_gradient(OuterSlope slope) {
  return slope.gradient;
}

const char* to_string(WheelFamily family) {
  switch (family) {
    case WheelFamily::kS1002:
      return "S1002";
    case WheelFamily::kEps:
      return "EPS";
    case WheelFamily::k1in40:
      return "1/40";
  }
  return "?";
}

std::string to_string(OuterSlope slope) {
  if (slope.uic_1in15) {
    return "1:15";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", 100.0 * slope.gradient);
  return buffer;
}

WheelFamily parse_wheel_family(const std::string& text) {
  if (text == "S1002" || text == "s1002") {
    return WheelFamily::kS1002;
  }
  if (text == "EPS" || text == "eps") {
    return WheelFamily::kEps;
  }
  if (text == "1/40" || text == "1:40") {
    return WheelFamily::k1in40;
  }
  throw std::invalid_argument("unknown wheel profile family '" + text +
                              "' (expected S1002, EPS or 1/40)");
}

namespace {

/// A plain decimal number "12", "8.5", ".5" (no sign, no exponent).
bool plain_decimal(const std::string& text) {
  bool digit = false;
  bool point = false;
  for (const char c : text) {
    if (c >= '0' && c <= '9') {
      digit = true;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      return false;
    }
  }
  return digit;
}

}  // namespace

OuterSlope parse_outer_slope(const std::string& text) {
  const std::string range = "expected 1:15 (UIC S1002) or a slope from " +
                            std::string("6.7 % to 15 % (a percentage such as 8.5 or 8.5%, or a ") +
                            "ratio 1:N with N from 6.667 to 14.925)";
  if (text == "1:15" || text == "1/15") {
    return OuterSlope::k1in15;
  }
  double gradient = 0.0;
  std::string number = text;
  if (!number.empty() && number.back() == '%') {
    number.pop_back();
    if (!number.empty() && number.back() == ' ') {
      number.pop_back();
    }
  }
  if ((text.rfind("1:", 0) == 0 || text.rfind("1/", 0) == 0) && plain_decimal(text.substr(2))) {
    double n = 0.0;
    if (!host::text::parse_number_text(text.substr(2), n) || !(n > 0.0) || !std::isfinite(n)) {
      throw std::invalid_argument("outer slope '" + text + "': " + range);
    }
    if (std::fabs(n - 15.0) < 1e-12) {
      return OuterSlope::k1in15;
    }
    gradient = 1.0 / n;
  } else if (plain_decimal(number)) {
    // The decimal as written, scaled by 10^-2 in the conversion itself: "6.7" -> 0.067 exactly.
    if (!host::text::parse_number_text(number + "e-2",
                                       gradient)) {  // beyond double: out of range below
      gradient = std::numeric_limits<double>::infinity();
    }
  } else {
    throw std::invalid_argument("outer slope '" + text + "': " + range);
  }
  const double percent = 100.0 * gradient;
  if (!(percent >= OuterSlope::kMinPercent - 1e-9 && percent <= OuterSlope::kMaxPercent + 1e-9)) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.4g %%", percent);
    throw std::invalid_argument("outer slope '" + text + "' is " + buffer + ": " + range);
  }
  return OuterSlope{gradient, false};
}

WheelParameters parse_wheel_spec(const std::string& spec, const std::string& option,
                                 std::set<std::string>* given) {
  WheelParameters p;
  const auto colon = spec.find(':');
  p.family = parse_wheel_family(spec.substr(0, colon));
  if (colon == std::string::npos) {
    return p;
  }
  std::stringstream rest(spec.substr(colon + 1));
  std::string item;
  std::set<std::string> seen;
  while (std::getline(rest, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) {
      throw std::invalid_argument(option + " " + spec + ": expected key=value, got '" + item + "'");
    }
    const std::string key = item.substr(0, eq);
    const std::string value = item.substr(eq + 1);
    if (!seen.insert(key).second) {
      throw std::invalid_argument(option + " " + spec + ": " + key + " given twice");
    }
    try {
      if (key == "h") {
        p.flange_height_mm = host::text::finite_number(value);
      } else if (key == "e") {
        p.flange_thickness_mm = host::text::finite_number(value);
      } else if (key == "slope") {
        p.outer_slope = parse_outer_slope(value);
      } else if (key == "width") {
        p.width_mm = host::text::finite_number(value);
      } else if (key == "chamfer") {
        if (value == "1" || value == "yes" || value == "true") {
          p.chamfer = true;
        } else if (value == "0" || value == "no" || value == "false") {
          p.chamfer = false;
        } else {
          throw std::invalid_argument("'" + value + "' is none of 1, yes, true, 0, no, false");
        }
      } else {
        throw std::invalid_argument("unknown key '" + key + "' (h, e, slope, width, chamfer)");
      }
    } catch (const std::logic_error& e) {
      throw std::invalid_argument(option + " " + spec + ": " + key + ": " + e.what());
    }
    if (given != nullptr) {
      given->insert(key);
    }
  }
  return p;
}

void WheelProfile::add(Piece piece, const std::string& junction_name, bool tangent) {
  if (!pieces_.empty()) {
    piece.y0 = pieces_.back().y1;  // contiguous by construction
    junctions_.push_back({junction_name, piece.y0, tangent, pieces_.size() - 1});
  }
  if (!(piece.y1 > piece.y0)) {
    std::ostringstream msg;
    msg << "WheelProfile: piece " << piece.name << " is empty (" << piece.y0 << " .. " << piece.y1
        << ")";
    throw std::logic_error(msg.str());
  }
  pieces_.push_back(std::move(piece));
}

namespace {

WheelProfile::Piece line_piece(const std::string& name, Point from, double slope, double y1) {
  WheelProfile::Piece p;
  p.name = name;
  p.kind = WheelProfile::Kind::kLine;
  p.y0 = from.y;
  p.y1 = y1;
  p.a = from.z;
  p.b = slope;
  return p;
}

WheelProfile::Piece arc_piece(const std::string& name, Point centre, double radius, double side,
                              double y0, double y1) {
  WheelProfile::Piece p;
  p.name = name;
  p.kind = WheelProfile::Kind::kArc;
  p.y0 = y0;
  p.y1 = y1;
  p.cy = centre.y;
  p.cz = centre.z;
  p.r = radius;
  p.side = side;
  return p;
}

template <std::size_t N>
WheelProfile::Piece polynomial_piece(const std::string& name, const std::array<double, N>& c,
                                     double shift, double y0, double y1) {
  WheelProfile::Piece p;
  p.name = name;
  p.kind = WheelProfile::Kind::kPolynomial;
  p.y0 = y0;
  p.y1 = y1;
  p.c.assign(c.begin(), c.end());
  p.shift = shift;
  return p;
}

double arc_tan(Point centre, double radius, double side, double y) {
  const double dy = y - centre.y;
  return -side * dy / std::sqrt(std::max(0.0, radius * radius - dy * dy));
}

template <std::size_t N>
double polynomial(const std::array<double, N>& c, double s) {
  double v = 0.0;
  for (std::size_t i = N; i-- > 0;) {
    v = v * s + c[i];
  }
  return v;
}

}  // namespace

namespace {

// A value as the user would write it (std::to_string printed 1e308 as 309 digits).
std::string value_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

void check_parameters(const WheelParameters& parameters) {
  const double h = parameters.flange_height_mm;
  const double e = parameters.flange_thickness_mm;
  if (!(near(h, 28.0) || near(h, 30.0) || near(h, 32.0))) {
    throw std::invalid_argument("flange height must be 28, 30 or 32 mm (EN 13715), got " +
                                value_text(h));
  }
  if (!(e >= 28.5 - 1e-9 && e <= 32.5 + 1e-9)) {
    throw std::invalid_argument("flange thickness must be within 28.5 … 32.5 mm, got " +
                                value_text(e));
  }
  if (!(near(parameters.width_mm, 135.0) || near(parameters.width_mm, 140.0))) {
    throw std::invalid_argument("wheel width must be 135 or 140 mm, got " +
                                value_text(parameters.width_mm));
  }
}

}  // namespace

/// The construction of one profile, part by part as the standard draws it: the flange (the same
/// for the three families but for h and e), each family's root, throat and tread, then the outer
/// slope and the chamfer. Each part appends its pieces and named points to the profile and hands
/// the next part the point where it ends.
class WheelProfileBuilder {
 public:
  explicit WheelProfileBuilder(WheelProfile& profile)
      : w_(profile),
        s_(std::max(0.0, 32.5 - profile.parameters_.flange_thickness_mm)),
        dh_(profile.parameters_.flange_height_mm - 28.0),
        root_centre_{-uic_s1002::kCD - s_, uic_s1002::kAD},  // Dm
        d1_y_(-35.0 - s_) {}

  void build() {
    flange();
    Point b1{0.0, 0.0};
    switch (w_.parameters_.family) {
      case WheelFamily::kS1002:
        b1 = s1002_throat_and_tread();
        break;
      case WheelFamily::k1in40:
        b1 = throat_and_tread_1in40();
        break;
      case WheelFamily::kEps:
        b1 = eps_throat_and_tread();
        break;
    }
    outer_slope_and_chamfer(b1);
  }

 private:
  void mark(const char* name, Point pt) { w_.points_.push_back({name, pt.y, pt.z}); }
  void add(WheelProfile::Piece piece, const std::string& junction_name, bool tangent) {
    w_.add(std::move(piece), junction_name, tangent);
  }

  /// Flange (Annex A): back R20.5, tip R12 (two arcs apart by s = 32.5 - e), outer arc, 70° flank
  /// down to E1 on the R13 root.
  void flange() {
    const double s = s_;
    const double dh = dh_;
    const Point& root_centre = root_centre_;
    const Point tip_back{-55.0, 16.0 + dh};      // RIm
    const Point tip_face{-55.0 - s, 16.0 + dh};  // REm
    // R20.5 flange back: centre (-49.5, AH + dh), internally tangent to the R12 tip arc.
    const double ah =
        16.0 -
        std::sqrt((kBackRadius_mm - kTipRadius_mm) * (kBackRadius_mm - kTipRadius_mm) - 5.5 * 5.5);
    const Point back_centre{-49.5, ah + dh};  // Hm
    const double k_back = kBackRadius_mm / (kBackRadius_mm - kTipRadius_mm);
    const Point h1{back_centre.y + k_back * (tip_back.y - back_centre.y),
                   back_centre.z + k_back * (tip_back.z - back_centre.z)};
    const Point s_point{-55.0 - 0.5 * s,
                        tip_back.z + std::sqrt(kTipRadius_mm * kTipRadius_mm - 0.25 * s * s)};
    // R13 root and the 70° flank tangent to it.
    const double sin_f = std::sin(kFlankAngle_rad);
    const double cos_f = std::cos(kFlankAngle_rad);
    const Point e1{root_centre.y - kRootRadius_mm * sin_f, root_centre.z - kRootRadius_mm * cos_f};
    // Flange outer arc: radius 20 + 0.75 dh, tangent to the flank (centre on the parallel at that
    // distance, on the flange side) and internally tangent to the face-side R12 arc.
    const double rf = 20.0 + 0.75 * dh;
    const Point dir{-cos_f, sin_f};   // along the flank, upward
    const Point nrm{-sin_f, -cos_f};  // from the flank toward the arc centre
    const double by = e1.y + rf * nrm.y - tip_face.y;
    const double bz = e1.z + rf * nrm.z - tip_face.z;
    const double qb = 2.0 * (by * dir.y + bz * dir.z);
    const double qc = by * by + bz * bz - (rf - kTipRadius_mm) * (rf - kTipRadius_mm);
    const double t = 0.5 * (-qb - std::sqrt(qb * qb - 4.0 * qc));
    const Point fm{tip_face.y + by + t * dir.y, tip_face.z + bz + t * dir.z};
    const Point f1{fm.y - rf * nrm.y, fm.z - rf * nrm.z};
    const double k_g = rf / (rf - kTipRadius_mm);
    const Point g1{fm.y + k_g * (tip_face.y - fm.y), fm.z + k_g * (tip_face.z - fm.z)};
    mark("Hm", back_centre);
    mark("H1", h1);
    mark("RIm", tip_back);
    mark("S", s_point);
    mark("REm", tip_face);
    mark("G1", g1);
    mark("Fm", fm);
    mark("F1", f1);
    mark("E1", e1);
    mark("Dm", root_centre);

    add(arc_piece("flange back R20.5", back_centre, kBackRadius_mm, 1.0, kBackY_mm, h1.y), "",
        true);
    add(arc_piece("flange tip R12 (back)", tip_back, kTipRadius_mm, 1.0, 0.0, s_point.y), "H1",
        true);
    if (s > 0.0) {
      add(arc_piece("flange tip R12 (face)", tip_face, kTipRadius_mm, 1.0, 0.0, g1.y), "S", false);
    } else {
      w_.pieces_.back().y1 = g1.y;  // the two R12 arcs coincide
    }
    add(arc_piece("flange outer arc", fm, rf, 1.0, 0.0, f1.y), "G1", true);
    add(line_piece("flank 70°", f1, -std::tan(kFlankAngle_rad), e1.y), "F1", true);
    w_.pieces_.back().y0 = f1.y;
  }

  /// S1002 (Annex B): R13 root, the UIC throat and tread polynomials; a thinner flange (s > 0)
  /// shifts the throat and joins the shifted tread to the unshifted one by a line T1–D0.
  /// @return B1, where the outer slope starts.
  Point s1002_throat_and_tread() {
    const double s = s_;
    add(arc_piece("flange root R13", root_centre_, kRootRadius_mm, -1.0, 0.0, d1_y_), "E1", true);
    add(polynomial_piece("S1002 throat (UIC C)", uic_s1002::kC, s, 0.0, uic_s1002::kYBC - s), "D1",
        true);
    const bool uic_slope = w_.parameters_.outer_slope.uic_1in15;
    const double b1_y = uic_slope ? uic_s1002::kYAB : 32.158;
    if (s > 0.0) {
      add(polynomial_piece("S1002 tread (UIC B, shifted)", uic_s1002::kB, s, 0.0, -0.5 - s), "C1",
          true);
      const double t1_z = polynomial(uic_s1002::kB, -0.5);
      add(line_piece("T1-D0 line", {-0.5 - s, t1_z}, -t1_z / (0.5 + s), 0.0), "T1", false);
      add(polynomial_piece("S1002 tread (UIC B)", uic_s1002::kB, 0.0, 0.0, b1_y), "D0", false);
    } else {
      add(polynomial_piece("S1002 tread (UIC B)", uic_s1002::kB, 0.0, 0.0, b1_y), "C1", true);
    }
    return uic_slope ? Point{b1_y, uic_s1002::kAA - uic_s1002::kBA * b1_y} : Point{32.158, -0.780};
  }

  /// 1/40 (Annex C): R13 root, an R36 transition tangent to it and to the 1:40 tread line.
  /// @return B1, where the outer slope starts.
  Point throat_and_tread_1in40() {
    const double s = s_;
    const Point& root_centre = root_centre_;
    // R36 tangent to the R13 root (internally) and to the 1:40 line z = -(y + s)/40.
    const double q = std::sqrt(1.0 + 1.0 / 1600.0);
    const double rj = 36.0;
    const double dd = rj - kRootRadius_mm;
    // In the e = 32.5 frame: (u - Dm.y)² + (-u/40 + rj q - Dm.z)² = dd².
    const double dmy = -uic_s1002::kCD;
    const double c0 = rj * q - uic_s1002::kAD;
    const double qa = 1.0 + 1.0 / 1600.0;
    const double qbb = -2.0 * dmy - 2.0 * c0 / 40.0;
    const double qcc = dmy * dmy + c0 * c0 - dd * dd;
    const double u = (-qbb + std::sqrt(qbb * qbb - 4.0 * qa * qcc)) / (2.0 * qa);
    const Point jm{u - s, -u / 40.0 + rj * q};
    const Point d1a{jm.y + rj / dd * (root_centre.y - jm.y),
                    jm.z + rj / dd * (root_centre.z - jm.z)};
    const Point c11a{jm.y - rj * (1.0 / 40.0) / q, jm.z - rj / q};
    mark("Jm", jm);
    mark("D1a", d1a);
    mark("C11a", c11a);
    add(arc_piece("flange root R13", root_centre, kRootRadius_mm, -1.0, 0.0, d1_y_), "E1", true);
    add(arc_piece("1/40 root R13", root_centre, kRootRadius_mm, -1.0, 0.0, d1a.y), "D1", true);
    add(arc_piece("1/40 transition R36", jm, rj, -1.0, 0.0, c11a.y), "D1a", true);
    if (s > 0.0) {
      add(line_piece("1/40 inner tread", c11a, -1.0 / 40.0, -0.5 - s), "C11a", true);
      const double t1_z = c11a.z - (-0.5 - s - c11a.y) / 40.0;
      add(line_piece("T1-D0 line", {-0.5 - s, t1_z}, -t1_z / (0.5 + s), 0.0), "T1", false);
      add(line_piece("1/40 outer tread", {0.0, 0.0}, -1.0 / 40.0, 35.0), "D0", false);
    } else {
      add(line_piece("1/40 tread", c11a, -1.0 / 40.0, 35.0), "C11a", true);
    }
    return {35.0, -35.0 / 40.0};
  }

  /// EPS (Annex D): R13 root, the tabulated transition of Table D.1 (a monotone cubic through its
  /// points), R100, R330 and a flat tread.
  /// @return B1, where the outer slope starts.
  Point eps_throat_and_tread() {
    const double e = w_.parameters_.flange_thickness_mm;
    const Point& root_centre = root_centre_;
    const double k = (e - en13715::kEpsTableFirstE_mm) / en13715::kEpsTableStep_mm;
    const double k_round = std::round(k);
    if (std::fabs(k - k_round) > 1e-9) {
      throw std::invalid_argument(
          "EPS is defined by Table D.1 only for e = 28.5, 29.0, … 32.5 mm, got " +
          std::to_string(e));
    }
    const auto column = static_cast<std::size_t>(k_round);
    const double z_flat = -0.5474;  // C12 – B1b (EN 15302 wheel C: -0.5474)
    const Point j330{19.0, z_flat + 330.0};
    const Point j100{-6.5, j330.z - std::sqrt(230.0 * 230.0 - 25.5 * 25.5)};
    const Point c11b{j330.y + 330.0 / 230.0 * (j100.y - j330.y),
                     j330.z + 330.0 / 230.0 * (j100.z - j330.z)};
    mark("Jm", j100);
    mark("Jm1", j330);
    mark("C11b", c11b);
    const std::size_t n = en13715::kEpsTableCount[column];
    std::vector<double> xs(n);
    std::vector<double> zs(n);
    for (std::size_t i = 0; i < n; ++i) {
      xs[i] = d1_y_ + 0.5 * static_cast<double>(i);
      zs[i] = en13715::kEpsTableZ_mm[column][i];
    }
    xs.back() = -26.0;
    // Through every tabulated point. The table's end values differ from the adjoining arcs by
    // its rounding (D1: root arc 6.86750 vs 6.867; C1b: R100 2.79023 vs 2.790), < 1 µm jumps.
    w_.cubics_.emplace_back(xs, zs, arc_tan(root_centre, kRootRadius_mm, -1.0, d1_y_));
    add(arc_piece("flange root R13", root_centre, kRootRadius_mm, -1.0, 0.0, d1_y_), "E1", true);
    WheelProfile::Piece cubic;
    cubic.name = "EPS transition (Table D.1, monotone cubic)";
    cubic.kind = WheelProfile::Kind::kCubic;
    cubic.y1 = -26.0;
    cubic.cubic = w_.cubics_.size() - 1;
    add(cubic, "D1", true);
    add(arc_piece("EPS R100", j100, 100.0, -1.0, 0.0, c11b.y), "C1b", false);
    add(arc_piece("EPS R330", j330, 330.0, -1.0, 0.0, 19.0), "C11b", true);
    add(line_piece("EPS flat", {19.0, z_flat}, 0.0, 29.0), "C12", true);
    return {29.0, z_flat};
  }

  /// The outer slope from B1 to the front face, less the 5 mm chamfer where there is one.
  void outer_slope_and_chamfer(Point b1) {
    const WheelParameters& parameters = w_.parameters_;
    const double p = outer_slope_gradient(parameters.outer_slope);
    const double front_y = parameters.width_mm - 70.0;
    const double a1_y = parameters.chamfer ? front_y - kChamfer_mm : front_y;
    const bool tangent_b1 =
        parameters.family == WheelFamily::kS1002 && parameters.outer_slope.uic_1in15;
    add(line_piece("outer slope", b1, -p, a1_y), "B1", tangent_b1);
    if (parameters.chamfer) {
      const Point a1{a1_y, b1.z - p * (a1_y - b1.y)};
      add(line_piece("chamfer", a1, -1.0, front_y), "A1", false);
    }
  }

  WheelProfile& w_;
  double s_;           ///< 32.5 - e, how much thinner the flange is than the nominal one
  double dh_;          ///< h - 28
  Point root_centre_;  ///< Dm, the centre of the R13 flange root
  double d1_y_;        ///< where the R13 root ends (D1)
};

WheelProfile::WheelProfile(const WheelParameters& parameters) : parameters_(parameters) {
  check_parameters(parameters);
  WheelProfileBuilder(*this).build();
}

std::string WheelProfile::name() const {
  std::ostringstream o;
  o << to_string(parameters_.family) << " h" << parameters_.flange_height_mm << " e"
    << parameters_.flange_thickness_mm << " " << to_string(parameters_.outer_slope)
    << (parameters_.outer_slope.uic_1in15 ? "" : "%") << " w" << parameters_.width_mm
    << (parameters_.chamfer ? "" : " no-chamfer");
  return o.str();
}

ProfileValue WheelProfile::piece_at(std::size_t index, double y) const {
  const Piece& p = pieces_[index];
  switch (p.kind) {
    case Kind::kLine:
      return {p.a + p.b * (y - p.y0), p.b};
    case Kind::kArc: {
      const double dy = y - p.cy;
      const double root = std::sqrt(std::max(0.0, p.r * p.r - dy * dy));
      const double tan = root > 0.0
                             ? -p.side * dy / root
                             : (-p.side * dy > 0.0 ? std::numeric_limits<double>::infinity()
                                                   : -std::numeric_limits<double>::infinity());
      return {p.cz + p.side * root, tan};
    }
    case Kind::kPolynomial: {
      const double x = y + p.shift;
      double v = 0.0;
      double d = 0.0;
      for (std::size_t i = p.c.size(); i-- > 0;) {
        d = d * x + v;
        v = v * x + p.c[i];
      }
      return {v, d};
    }
    case Kind::kCubic:
      return {cubics_[p.cubic].value(y), cubics_[p.cubic].slope(y)};
  }
  return {0.0, 0.0};
}

ProfileValue WheelProfile::at(double y) const {
  if (!(y >= y_min_mm() - 1e-12 && y <= y_max_mm() + 1e-12)) {
    std::ostringstream msg;
    msg << name() << ": y = " << y << " mm is outside [" << y_min_mm() << ", " << y_max_mm() << "]";
    throw std::out_of_range(msg.str());
  }
  const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), y,
                                   [](const Piece& p, double value) { return p.y1 < value; });
  const std::size_t index =
      it == pieces_.end() ? pieces_.size() - 1 : static_cast<std::size_t>(it - pieces_.begin());
  return piece_at(index, y);
}

SampledProfile WheelProfile::sample(double step_mm) const {
  if (!(step_mm > 0.0)) {
    throw std::invalid_argument("sample step must be positive");
  }
  SampledProfile out;
  out.name = name();
  const double span = y_max_mm() - y_min_mm();
  const auto n = static_cast<std::size_t>(std::floor(span / step_mm + 1e-9));
  for (std::size_t i = 0; i <= n; ++i) {
    double y = y_min_mm() + static_cast<double>(i) * step_mm;
    y = std::round(y * 1e9) / 1e9;
    out.y_mm.push_back(y);
    out.z_mm.push_back(at(y).z_mm);
  }
  if (out.y_mm.back() < y_max_mm() - 1e-9) {
    out.y_mm.push_back(y_max_mm());
    out.z_mm.push_back(at(y_max_mm()).z_mm);
  }
  return out;
}

std::vector<WheelParameters> standard_wheel_parameters(OuterSlope slope, double width_mm) {
  std::vector<WheelParameters> all;
  for (const WheelFamily family : {WheelFamily::kS1002, WheelFamily::kEps, WheelFamily::k1in40}) {
    for (const double h : {28.0, 30.0, 32.0}) {
      for (int k = 0; k <= 8; ++k) {
        all.push_back({family, h, 28.5 + 0.5 * k, slope, width_mm, true});
      }
    }
  }
  return all;
}

}  // namespace tread::profile
