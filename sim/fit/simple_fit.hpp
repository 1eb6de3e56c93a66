#pragma once
// Stage 1 of `tread fit`: the seed's method automated (host side: allocates, throws).
//
// Per load level (clusters of Fz), fit the basic Magic Formula
//   y = D sin(C atan(B x − E (B x − atan(B x)))) + SV,  x = X + SH
// (tread::pac::detail::magic_formula, the core's templated curve) to Fx(κ) at α ≈ 0, Fy(α) and
// Mz(α) at κ ≈ 0 (all at γ ≈ 0), by Ceres (automatic differentiation, Levenberg–Marquardt) with the
// seed's constraints 1 < C < 3 and E < 1 (optionally a 7th constant EA, see SimpleConstants).
// Starting values come from the data: BCD and SV from a straight line through the points nearest
// the origin, D from the peak, C from a short grid of shapes (the best start is kept;
// deterministic). Standard deviations from ceres::Covariance scaled by the residual variance.

#include <array>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "fit/measurement.hpp"

namespace tread::fit {

enum class Channel { fx_kappa, fy_alpha, mz_alpha };
inline constexpr std::array<Channel, 3> kChannels = {Channel::fx_kappa, Channel::fy_alpha,
                                                     Channel::mz_alpha};
const char* channel_name(Channel c);    ///< "Fx(kappa)", ...
const char* channel_column(Channel c);  ///< "Fx_N", "Fy_N", "Mz_Nm"

/// The constants of the basic formula, in this order: B, C, D, E, SH, SV, and EA, an optional
/// asymmetry of the curvature as in PAC94/MF (E·(1 − EA·sgn(x)); 0 → the seed's six constants).
struct SimpleConstants {
  double b = 0.0, c = 0.0, d = 0.0, e = 0.0, sh = 0.0, sv = 0.0, ea = 0.0;
};
inline constexpr std::array<const char*, 7> kConstantNames = {"B", "C", "D", "E", "SH", "SV", "EA"};

/// y(x) of the basic formula.
double simple_curve(const SimpleConstants& k, double x);

struct ChannelFit {
  Channel channel = Channel::fx_kappa;
  double fz_n = 0.0;  ///< mean load of the cluster
  std::size_t points = 0;
  SimpleConstants constants;
  std::array<double, 7> stddev{};  ///< NaN where not available (EA when not fitted)
  double rms = 0.0;                ///< of the residuals, in N or Nm
  double r2 = 0.0;
  std::vector<double> x, y;  ///< the points fitted (slip, measured value)
};

struct SimpleFitSettings {
  double fz_gap_rel = 0.1;      ///< a new load level starts where sorted Fz jump by more than this
  double pure_slip_tol = 1e-3;  ///< |α| (rad) for Fx(κ), |κ| for Fy/Mz(α), |γ| (rad) for all
  std::size_t min_points = 8;   ///< fewer points in a sweep → no fit for it
  /// Also fit EA (a 7th constant: curvature different on either side of the origin, as MF's
  /// PEX4/PEY3). False: the seed's six constants.
  bool asymmetric_e = false;
};

struct SimpleFit {
  std::vector<double> loads_n;   ///< the load levels found (ascending)
  std::vector<ChannelFit> fits;  ///< per channel and load, channel-major, loads ascending
};

/// `progress` (may be empty) receives one line per fit.
SimpleFit fit_simple(const MeasurementSet& data, const SimpleFitSettings& settings,
                     const std::function<void(const std::string&)>& progress);

/// The map over Fz: each constant interpolated linearly between the fitted loads of `channel`
/// (held constant outside). Throws if the channel has no fit.
SimpleConstants interpolate_constants(const SimpleFit& fit, Channel channel, double fz_n);

/// Slope at the origin (dy/dX at X = 0) and the largest |y| over [x_min, x_max] of a curve.
double slope_at_origin(const SimpleConstants& k);
double peak_abs(const SimpleConstants& k, double x_min, double x_max);

/// CSV: channel,fz_N,points,B,C,D,E,SH,SV,EA,sd_B,...,sd_EA,slope_at_origin,rms,r2.
void write_simple_fit_csv(const SimpleFit& fit, std::ostream& out);
/// Markdown report: per channel and load the constants ± standard deviations, RMS and R².
void write_simple_fit_report(const SimpleFit& fit, const std::string& source, std::ostream& out);
/// One PNG per channel and load in `dir` (created): measured points and the fitted curve.
void plot_simple_fit(const SimpleFit& fit, const std::string& dir);

}  // namespace tread::fit
