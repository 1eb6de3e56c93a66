#pragma once
// Everything a running node owns, built from the command line's settings at init (this may
// allocate; the loop afterwards does not): tyre parameters, MF channels, contact tables, the node
// itself — in float, or (settings.fixed) on the integer-only path an FPU-less target runs:
// Fixed64 tyre parameters, the fixed-point MF, the contact table in integers (0.1 µm, µrad), the
// codec's integer signal route.

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "contact/contact_mechanics.hpp"
#include "contact/contact_setup.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "node/contact_table_channel.hpp"
#include "node/contact_table_channel_fixed.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/mf_tyre_channel_fixed.hpp"
#include "node/node.hpp"
#include "node/rail_force_channel.hpp"

namespace tread::host {

struct NodeSettings {
  std::filesystem::path tir;        ///< required when wheels > 0
  int use_mode{111};                ///< MFeval useMode for the tyre model
  std::string side{"as-measured"};  ///< mounted side: as-measured | left | right
  bool relaxation{false};  ///< first-order transient slips (relaxation lengths of the .tir)
  /// The fixed-point node (Q31.32 MF, integer contact table and signal route): exactly the
  /// arithmetic of the FPU-less firmware image.
  bool fixed{false};
  node::NodeConfig node{};
  /// Wheelset contact: "key=value,..." with keys wheel, wheel-file, rail, rail-file, rail-frame,
  /// cant, gauge, b2b, r0, r0-right (the options of `tread contact`). Empty: no wheelsets.
  std::string wheelset_profile;
  double wheelset_ymax_mm{12.0};
  double wheelset_step_mm{0.1};
  /// Wheel-rail forces (node.wheelset_forces > 0): Polach's parameters by name (kalker, dry,
  /// wet), mu0 (0: the set's own) and the materials of wheel and rail.
  std::string friction{"kalker"};
  double mu{0.0};
  contact::ContactMaterials materials{};
};

/// The tyre model's options of a node with `use_mode` (MFeval useMode) and mounted `side`
/// (as-measured, left, right), Rl among the outputs. Throws std::runtime_error on a bad value.
/// The node's and the rig's reference use the same.
[[nodiscard]] mf::MfOptions node_tyre_options(int use_mode, const std::string& side);

using contact::parse_wheelset_profile;  // the --wheelset-profile spec (contact/contact_setup.hpp)

using RuntimeNode =
    node::Node<node::MfTyreChannel, node::ContactTableChannel, node::RailForceTableChannel>;
using RuntimeNodeFixed = node::Node<node::MfTyreChannelFixed, node::ContactTableChannelFixed>;

class NodeRuntime {
 public:
  /// Loads the .tir, builds the contact table; throws std::runtime_error with a clear message.
  explicit NodeRuntime(const NodeSettings& settings);
  NodeRuntime(const NodeRuntime&) = delete;
  NodeRuntime& operator=(const NodeRuntime&) = delete;

  /// Calls `f` with the node (RuntimeNode& or RuntimeNodeFixed&); both calls must return the
  /// same type.
  template <typename F>
  decltype(auto) visit(F&& f) {
    if (node_fixed_) {
      return std::forward<F>(f)(*node_fixed_);
    }
    return std::forward<F>(f)(*node_);
  }
  [[nodiscard]] bool fixed() const { return node_fixed_ != nullptr; }
  [[nodiscard]] const node::NodeConfig& config() const {
    return node_fixed_ ? node_fixed_->config() : node_->config();
  }
  [[nodiscard]] node::NodeCounters counters() const {
    return node_fixed_ ? node_fixed_->counters() : node_->counters();
  }
  [[nodiscard]] const mf::MfParameters<double>& tyre_parameters() const { return params_double_; }
  [[nodiscard]] const mf::MfOptions& tyre_options() const { return options_; }
  [[nodiscard]] const std::string& tir_warning() const { return tir_warning_; }
  [[nodiscard]] const rail::ContactTableF32& contact_table() const { return table_; }
  /// The same table in integers (rows rounded to 0.1 µm and µrad, y to µm), as the flashed `.q`.
  [[nodiscard]] const rail::ContactTableQ& contact_table_q() const { return table_q_; }
  /// The wheel-rail force table and settings (empty without wheelset forces).
  [[nodiscard]] const rail::MechanicsTableF32& mechanics_table() const { return mechanics_; }
  [[nodiscard]] const node::RailForceSettings& force_settings() const { return force_settings_; }

 private:
  void build_forces(const contact::RigidContact& contact, const contact::ContactSetup& setup,
                    const NodeSettings& settings, double y_first_mm, double y_last_mm,
                    double step_mm);

  mf::MfParameters<double> params_double_{};
  mf::MfParameters<float> params_{};
  mf::MfOptions options_{};
  std::string tir_warning_;
  std::array<node::MfTyreChannel, proto::kMaxWheels> tyres_{};
  std::array<node::ContactTableChannel, proto::kMaxWheelsets> contacts_{};
  std::vector<rail::ContactRowF32> rows_;  ///< the contact table
  rail::ContactTableF32 table_{};
  mf::MfParameters<fixed::Fixed64> params_fixed_{};
  std::array<node::MfTyreChannelFixed, proto::kMaxWheels> tyres_fixed_{};
  std::array<node::ContactTableChannelFixed, proto::kMaxWheelsets> contacts_fixed_{};
  std::vector<rail::ContactRowQ> rows_q_;
  rail::ContactTableQ table_q_{};
  std::vector<rail::MechanicsRowF32> mechanics_rows_;
  rail::MechanicsTableF32 mechanics_{};
  node::RailForceSettings force_settings_{};
  std::array<node::RailForceTableChannel, proto::kMaxWheelsets> forces_{};
  std::unique_ptr<RuntimeNode> node_;             ///< the float node, or
  std::unique_ptr<RuntimeNodeFixed> node_fixed_;  ///< the fixed-point one
};

}  // namespace tread::host
