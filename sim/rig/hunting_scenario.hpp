#pragma once
// Rail scenario: one or two free wheelsets on straight track hunting kinematically (see
// wheelset_hunting.hpp), each driven by the delta r the node answers for its lateral displacement.
// The rig keeps its own contact table in double, built from the same wheelset profile the node was
// given, as the reference: after the run the measured wavelength of each wheelset is compared with
// Klingel's formula at the EN 15302 equivalent conicity for the measured amplitude.

#include <array>
#include <string>
#include <vector>

#include "contact/rigid_contact.hpp"
#include "rig/rig_scenario.hpp"
#include "rig/wheelset_hunting.hpp"

namespace tread::host {

struct HuntingSettings {
  std::uint8_t wheelsets{2};
  double speed_mps{30.0};
  double duration_s{3.0};  ///< at least; longer if 4.5 periods need more
  /// Initial lateral displacement from the centre of the motion, per wheelset (mm).
  std::array<double, proto::kMaxWheelsets> amplitude_mm{3.0, 5.0};
  std::string wheelset_profile;  ///< the node's --wheelset-profile (the reference)
  double ymax_mm{12.0};
  double step_mm{0.1};
};

class HuntingScenario final : public RigScenario {
 public:
  /// Builds the reference contact table; throws std::runtime_error on a bad profile spec.
  explicit HuntingScenario(const HuntingSettings& settings);

  [[nodiscard]] std::string name() const override { return "hunting"; }
  [[nodiscard]] std::string description() const override;
  [[nodiscard]] double duration_s() const override { return settings_.duration_s; }
  void inputs(double t_s, proto::RigData& data) override;
  void advance(const proto::RigData& inputs_seen, const proto::NodeData& answers,
               double dt_s) override;
  [[nodiscard]] std::vector<std::string> trace_columns() const override;
  void trace_values(std::vector<double>& row) const override;
  [[nodiscard]] std::vector<ScenarioMetric> metrics() const override;
  std::vector<std::filesystem::path> plot(const std::filesystem::path& trace_csv,
                                          const std::filesystem::path& out_dir) const override;

  /// Per wheelset after the run: the motion's analysis and Klingel's wavelength at the EN 15302
  /// equivalent conicity for the measured amplitude (NaN when it cannot be computed).
  struct Result {
    HuntingAnalysis motion;
    double tan_gamma_e{0.0};
    double klingel_wavelength_m{0.0};
  };
  [[nodiscard]] Result result(std::size_t wheelset) const;

 private:
  HuntingSettings settings_;
  contact::ContactTable reference_;
  double centre_mm_{0.0};
  std::array<WheelsetHunting, proto::kMaxWheelsets> wheelsets_{};
  std::array<double, proto::kMaxWheelsets> delta_r_mm_{};
  double t_s_{0.0};
  std::vector<double> t_trace_;
  std::array<std::vector<double>, proto::kMaxWheelsets> y_trace_;
};

}  // namespace tread::host
