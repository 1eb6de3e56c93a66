#pragma once
// Rail scenario: a suspended wheelset (rail/wheelset_model.hpp) driven by the wheel-rail forces the
// node answers (RailWheel messages: Y, Fx and spin moment of each wheel from Hertz, Polach and the
// contact table), run as a series of stability runs at different speeds:
//  1. a low-speed run from a 3 mm displacement: its wavelength against Klingel's at the EN 15302
//     equivalent conicity for the amplitude it runs at;
//  2. runs from a 1 mm displacement on a speed scan until the motion's growth rate changes sign,
//     then regula-falsi refinements of that speed: critical_speed (node in the loop);
//  3. one run below (0.9x) where the motion decays and one above (1.1x) where a limit cycle grows
//     until the flanges bound it, with Y/Q against Nadal's limit.
// The rig's own double model of the same contact (rig/wheelset_stability.hpp) gives the
// eigenvalues of the linearised equations and critical_speed_linear; the two must agree.

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "contact/contact_mechanics.hpp"
#include "rig/rig_scenario.hpp"
#include "rig/wheelset_stability.hpp"

namespace tread::host {

struct DynamicHuntingSettings {
  WheelsetForceSetup setup;  ///< the node's force channel (the same contact)
  rail::WheelsetParams<double> params{};
  double initial_y_mm{1.0};  ///< start of every stability run
  double run_s{2.5};         ///< length of a stability run
  std::vector<double> scan_speeds_m_s{20.0, 35.0, 50.0, 65.0, 80.0, 100.0, 120.0, 150.0};
  int refinements{3};
  double low_speed_m_s{10.0};
  double low_speed_amplitude_mm{3.0};
  double low_speed_run_s{4.0};
  double below_factor{0.9};
  double above_factor{1.1};
  double above_run_s{6.0};
};

class DynamicHuntingScenario final : public RigScenario {
 public:
  /// Builds the rig's contact model and the linear analysis; throws std::runtime_error on a bad
  /// profile.
  explicit DynamicHuntingScenario(const DynamicHuntingSettings& settings);

  [[nodiscard]] std::string name() const override { return "dynamic-hunting"; }
  [[nodiscard]] std::string description() const override;
  [[nodiscard]] double duration_s() const override;
  [[nodiscard]] bool finished() const override { return phase_ == Phase::done; }
  void inputs(double t_s, proto::RigData& data) override;
  void advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
               double dt_s) override;
  [[nodiscard]] std::vector<std::string> trace_columns() const override;
  void trace_values(std::vector<double>& row) const override;
  [[nodiscard]] std::vector<ScenarioMetric> metrics() const override;
  std::vector<std::filesystem::path> plot(const std::filesystem::path& trace_csv,
                                          const std::filesystem::path& out_dir) const override;

  enum class Phase { low_speed, scan, refine, below, above, done };

  /// One finished run.
  struct Run {
    Phase phase{Phase::scan};
    double speed_m_s{0.0};
    double growth_rate_per_s{0.0};  ///< from the envelope of the motion (NaN: too few swings)
    double amplitude_mm{0.0};       ///< largest |y| in the last second
    double wavelength_m{0.0};       ///< from the zero crossings
    double max_y_over_q{0.0};
    double min_nadal_margin{0.0};
    bool answered{false};  ///< at least one answer without a status flag (else Y/Q is not known)
    std::size_t held_answers{0};  ///< cycles whose answer was flagged (the last fresh one held)
  };
  [[nodiscard]] const std::vector<Run>& runs() const { return runs_; }
  [[nodiscard]] double critical_speed() const { return critical_; }
  [[nodiscard]] double critical_speed_linear() const { return critical_linear_; }
  /// Klingel's wavelength at the EN 15302 equivalent conicity for the low-speed run's amplitude.
  [[nodiscard]] double klingel_wavelength_m() const;

 private:
  void start(Phase phase, double speed_m_s, double y0_mm, double duration_s);
  void finish_run();
  /// Why critical_ is NaN, from the scan runs' growth rates.
  [[nodiscard]] std::string no_critical_speed_reason() const;
  [[nodiscard]] static double growth_rate(const std::vector<double>& t,
                                          const std::vector<double>& y, double cap_mm);
  [[nodiscard]] static double wavelength(const std::vector<double>& t, const std::vector<double>& y,
                                         double speed_m_s);

  DynamicHuntingSettings settings_;
  contact::RigidContact contact_;
  contact::ContactTable reference_;
  WheelsetContactModel model_;
  double critical_linear_{0.0};
  /// Empty, or why the linearisation at the centre does not describe the motion (a contact that
  /// jumps there, as S1002 on 60E1 1:40 does).
  std::string smoothness_note_;
  LinearMode mode_at_critical_{};
  // The run in progress.
  Phase phase_{Phase::low_speed};
  double speed_{0.0};
  double run_duration_{0.0};
  double run_t_{0.0};
  rail::WheelsetState<double> state_{};
  Eigen::Matrix4d jacobian_ = Eigen::Matrix4d::Zero();  ///< the linearised system at speed_
  rail::Vector2<double> force_ = rail::Vector2<double>::Zero();
  proto::RailWheelOutput answer_[2]{};
  std::vector<double> run_time_;
  std::vector<double> run_y_;
  Run current_{};
  std::array<double, 12> row_{};  ///< the trace row of the last step
  // The search.
  std::vector<Run> runs_;
  std::size_t scan_index_{0};
  double lo_v_{0.0}, lo_sigma_{0.0}, hi_v_{0.0}, hi_sigma_{0.0};
  int refined_{0};
  int side_{0};
  double critical_{std::nan("")};
};

}  // namespace tread::host
