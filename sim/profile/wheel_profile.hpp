#pragma once
// EN 13715:2020 wheel profiles S1002, EPS and 1/40 for every flange height h ∈ {28, 30, 32} mm and
// flange thickness e ∈ [28.5, 32.5] mm, outer slope 1:15 or any 6.7 … 15 %, wheel width 135 or
// 140 mm, with or without the 5 x 5 mm chamfer — one parametric construction of lines, arcs,
// polynomials and a shape-preserving interpolation, evaluable at any y (z and dz/dy).
//
// Convention: y lateral from the taping line D0 (70 mm from the wheel back), + toward the field
// side; z = radius increase, + toward the flange tip (r = r0 + z); tan = dz/dy.
//
// Construction (the rail definitions in data/PROVENANCE.md, every point derived from geometry):
// - Flange (Annex A), s = 32.5 - e, dh = h - 28: R20.5 flange back centred (-49.5, AH + dh) tangent
//   to the wheel back at y = -70 and internally to the R12 tip arc centred (-55, 16 + dh); the face
//   side R12 arc centred (-55 - s, 16 + dh) (the two meet in a cusp S for s > 0); the flange outer
//   arc of radius 20 + 0.75 dh tangent to that R12 arc and to the 70° flank; the flank tangent to
//   the R13 root centred (-26.210665 - s, 16.446). For h = 28, e = 32.5 this reproduces the UIC
//   S1002 sections D–H to 1e-7 mm.
// - S1002 (Annex C): the UIC closed-form polynomials (throat, tread) shifted by -s from D1 to
//   T1 = -0.5 - s, a straight line T1 → D0, the UIC tread polynomial from D0 to B1 = 32.158; for
//   e = 32.5 the UIC polynomial runs through without the T1 line.
// - 1/40 (Annex B): R13 root to D1a, R36 tangent to it and to the 1:40 line, 1:40 line to T1, line
//   T1 → D0, z = -y/40 to B1a = 35.
// - EPS (Annex D): Table D.1 from D1 to C1b = -26 through a monotone cubic (tangent to the R13 root
//   at D1), R100 and R330 arcs (tangent), flat to B1b = 29.
// - Outer slope from B1 to A1 (y = width - 75), then the 45° chamfer to I (y = width - 70). The
//   S1002 "1:15" variant is the UIC section A (through the polynomial's end at 32.15796); the
//   percentage slopes start at the tabulated B1 = (32.158, -0.780).

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "profile/monotone_cubic.hpp"
#include "profile/sampled_profile.hpp"

namespace tread::profile {

enum class WheelFamily { kS1002, kEps, k1in40 };

/// The outer slope (B1 → A1): the UIC S1002 1:15 section, or any gradient from 6.7 % to 15 %
/// (EN 13715), starting at the family's B1.
struct OuterSlope {
  double gradient = 1.0 / 15.0;  ///< tan of the slope (falling toward the outer face)
  bool uic_1in15 = true;  ///< the UIC 1:15 variant (S1002: section A from the polynomial's end)

  static constexpr double kMinPercent = 6.7;
  static constexpr double kMaxPercent = 15.0;
  /// The four values the standard's tables name.
  static const OuterSlope k1in15;
  static const OuterSlope k6_7;
  static const OuterSlope k10;
  static const OuterSlope k15;

  friend bool operator==(const OuterSlope&, const OuterSlope&) = default;
};

inline constexpr OuterSlope OuterSlope::k1in15{1.0 / 15.0, true};
inline constexpr OuterSlope OuterSlope::k6_7{0.067, false};
inline constexpr OuterSlope OuterSlope::k10{0.10, false};
inline constexpr OuterSlope OuterSlope::k15{0.15, false};

struct WheelParameters {
  WheelFamily family = WheelFamily::kS1002;
  double flange_height_mm = 28.0;     ///< h: 28, 30 or 32
  double flange_thickness_mm = 32.5;  ///< e: 28.5 … 32.5
  OuterSlope outer_slope = OuterSlope::k1in15;
  double width_mm = 140.0;  ///< 135 or 140
  bool chamfer = true;      ///< 5 x 5 mm chamfer at the outer face
};

/// The gradient of an outer slope (1/15, 0.067 … 0.15).
double outer_slope_gradient(OuterSlope slope);
/// "S1002", "EPS", "1/40"; parse throws std::invalid_argument.
const char* to_string(WheelFamily family);
WheelFamily parse_wheel_family(const std::string& text);
/// "1:15" for the UIC variant, else the percentage without the sign ("6.7", "10", "8.5").
std::string to_string(OuterSlope slope);
/// "1:15" / "1/15" (the UIC variant); a percentage "8.5", "8.5%" or "8.5 %"; or a ratio "1:12".
/// A percentage is taken as the decimal it is written as (gradient = text × 10⁻², correctly
/// rounded, so "6.7" gives exactly 0.067). Throws std::invalid_argument for malformed text and for
/// gradients outside 6.7 … 15 %, naming the allowed range.
OuterSlope parse_outer_slope(const std::string& text);

/// A wheel written as FAMILY[:key=value,...] with the keys h, e, slope, width and chamfer
/// ("S1002:h=30,e=31.5,slope=1:15"); what is not written keeps WheelParameters' default. Throws
/// std::invalid_argument naming `option` (the command-line option it came from, e.g. "--wheel"),
/// the spec and the key. The keys written are added to `given` where it is not null.
WheelParameters parse_wheel_spec(const std::string& spec, const std::string& option,
                                 std::set<std::string>* given = nullptr);

struct ProfileValue {
  double z_mm;
  double tan;  ///< dz/dy; +infinity at the wheel back (y = -70), where the R20.5 arc is vertical
};

/// A junction between two pieces of the construction.
struct ProfileJunction {
  std::string name;  ///< the standard's point name (H1, S, G1, F1, E1, D1, C1, T1, B1, A1, …)
  double y_mm;       ///< lateral position
  bool tangent;      ///< the standard makes the pieces tangent here
  std::size_t left;  ///< index of the piece ending here
};

/// A named point of the construction (the standard's names: Hm, H1, RIm, S, REm, G1, Fm, F1, E1,
/// Dm; 1/40: Jm, D1a, C11a; EPS: Jm (R100 centre), Jm1 (R330 centre), C11b).
struct ProfilePoint {
  std::string name;
  double y_mm;
  double z_mm;
};

class WheelProfile {
 public:
  /// Throws std::invalid_argument for h not in {28, 30, 32}, e outside [28.5, 32.5], a width other
  /// than 135 or 140.
  explicit WheelProfile(const WheelParameters& parameters);

  const WheelParameters& parameters() const { return parameters_; }
  /// E.g. "S1002 h28 e32.5 1:15 w140".
  std::string name() const;
  double y_min_mm() const { return -70.0; }
  double y_max_mm() const { return parameters_.width_mm - 70.0; }

  /// z and tan at y ∈ [y_min, y_max] (throws std::out_of_range outside). At a junction the piece
  /// on the flange side (smaller y) is used.
  ProfileValue at(double y_mm) const;

  /// z and tan of piece `index` at y (no range check): the left/right limits at a junction.
  ProfileValue piece_at(std::size_t index, double y_mm) const;
  std::size_t piece_count() const { return pieces_.size(); }
  const std::string& piece_name(std::size_t index) const { return pieces_[index].name; }
  const std::vector<ProfileJunction>& junctions() const { return junctions_; }
  const std::vector<ProfilePoint>& points() const { return points_; }

  /// Samples from y_min to y_max at `step_mm` (both ends included; the last step may be shorter).
  SampledProfile sample(double step_mm) const;

  /// The piece definition (public for the implementation; use at()/piece_at()).
  enum class Kind { kLine, kArc, kPolynomial, kCubic };
  struct Piece {
    std::string name;
    Kind kind = Kind::kLine;
    double y0 = 0.0;
    double y1 = 0.0;
    // line: z = a + b (y - y0); arc: centre (cy, cz), radius r, upper (+1) / lower (-1) half;
    // polynomial: z = Σ c[i] (y + shift)^i; cubic: index into cubics_.
    double a = 0.0, b = 0.0, cy = 0.0, cz = 0.0, r = 0.0, side = 1.0, shift = 0.0;
    std::vector<double> c;
    std::size_t cubic = 0;
  };

 private:
  friend class WheelProfileBuilder;  // the construction, part by part (wheel_profile.cpp)
  void add(Piece piece, const std::string& junction_name, bool tangent);
  WheelParameters parameters_;
  std::vector<Piece> pieces_;
  std::vector<ProfileJunction> junctions_;
  std::vector<ProfilePoint> points_;
  std::vector<MonotoneCubic> cubics_;
};

/// Every standard profile: 3 families × h {28, 30, 32} × e {28.5 … 32.5 step 0.5} with the given
/// outer slope and width (81 profiles).
std::vector<WheelParameters> standard_wheel_parameters(OuterSlope slope = OuterSlope{},
                                                       double width_mm = 140.0);

}  // namespace tread::profile
