#pragma once
// Rail scenario: the suspended wheelset of the dynamic-hunting scenario (rail/wheelset_model.hpp)
// through curves of decreasing radius, on the wheel-rail forces the node answers. Per curve the
// track curvature runs in over a transition and is then held; the wheelset's frame follows the
// track, so its suspension acts on the lateral displacement and yaw angle relative to the track;
// the uncompensated lateral acceleration (cant deficiency) pushes the wheelset toward the outer
// rail. The curve turns right, so the outer rail is the left one (+y).
//
// The node sees the curve through the yaw rate (-V / R, the wheelset following the track): the
// outer wheel must roll faster by e0 / R, so the wheelset shifts outward until delta r gives it
// (pure rolling), and past that it needs flange contact. The steady state of each curve is
// reported: displacement, angle of attack, the outer wheel's Y, Q and Y/Q against Nadal's limit,
// the flange's share of the load; and the lateral equilibrium is checked (contact forces plus the
// cant-deficiency force against the suspension).

#include <array>
#include <string>
#include <vector>

#include "contact/contact_mechanics.hpp"
#include "rig/rig_scenario.hpp"
#include "rig/wheelset_stability.hpp"

namespace tread::host {

struct CurvingSettings {
  WheelsetForceSetup setup;  ///< the node's force channel (the same contact)
  rail::WheelsetParams<double> params{};
  double speed_m_s{20.0};
  double uncompensated_acceleration_m_s2{0.65};  ///< cant deficiency (about 100 mm)
  std::vector<double> radii_m{3000.0, 1500.0, 1000.0, 700.0, 500.0, 400.0, 300.0, 250.0};
  double transition_s{2.0};  ///< curvature ramps in over this
  double hold_s{3.0};        ///< then held; the last second is the steady state
};

class CurvingScenario final : public RigScenario {
 public:
  explicit CurvingScenario(const CurvingSettings& settings);

  [[nodiscard]] std::string name() const override { return "curving"; }
  [[nodiscard]] std::string description() const override;
  [[nodiscard]] double duration_s() const override;
  [[nodiscard]] bool finished() const override { return curve_ >= settings_.radii_m.size(); }
  void inputs(double t_s, proto::RigData& data) override;
  void advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
               double dt_s) override;
  [[nodiscard]] std::vector<std::string> trace_columns() const override;
  void trace_values(std::vector<double>& row) const override;
  [[nodiscard]] std::vector<ScenarioMetric> metrics() const override;
  std::vector<std::filesystem::path> plot(const std::filesystem::path& trace_csv,
                                          const std::filesystem::path& out_dir) const override;

  /// The steady state of one curve (means over its last second).
  struct Steady {
    double radius_m{0.0};
    double y_mm{0.0};
    double yaw_mrad{0.0};   ///< angle of attack (relative to the track tangent)
    double outer_y_n{0.0};  ///< the outer (left) wheel's Y
    double outer_q_n{0.0};
    double outer_y_over_q{0.0};
    double outer_nadal_margin{0.0};
    double inner_y_over_q{0.0};
    double flange_share{0.0};        ///< the outer wheel's second contact point's share of N
    double equilibrium_n{0.0};       ///< contact + cant-deficiency force - suspension (ideally 0)
    double max_outer_y_over_q{0.0};  ///< the largest over the whole curve (run-in included)
  };
  [[nodiscard]] const std::vector<Steady>& curves() const { return done_; }

 private:
  [[nodiscard]] double curvature_per_m() const;
  [[nodiscard]] double cant_deficiency_force_n() const;

  CurvingSettings settings_;
  contact::RigidContact contact_;
  WheelsetContactModel model_;
  Eigen::Matrix4d jacobian_ = Eigen::Matrix4d::Zero();
  std::size_t curve_{0};
  double t_curve_{0.0};
  rail::WheelsetState<double> state_{};
  rail::Vector2<double> force_ = rail::Vector2<double>::Zero();
  proto::RailWheelOutput answer_[2]{};
  Steady sum_{};
  int samples_{0};
  std::vector<Steady> done_;
  std::array<double, 11> row_{};
};

}  // namespace tread::host
