#pragma once
// Everything a running node owns, built from the command line's settings at init (this may
// allocate; the loop afterwards does not): tyre parameters in float, MF channels, contact tables in
// float, the node itself.

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_setup.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "node/contact_table_channel.hpp"
#include "node/mf_tyre_channel.hpp"
#include "node/node.hpp"

namespace tread::host {

struct NodeSettings {
  std::filesystem::path tir;        ///< required when wheels > 0
  int use_mode{111};                ///< MFeval useMode for the tyre model
  std::string side{"as-measured"};  ///< mounted side: as-measured | left | right
  bool relaxation{false};  ///< first-order transient slips (relaxation lengths of the .tir)
  node::NodeConfig node{};
  /// Wheelset contact: "key=value,..." with keys wheel, wheel-file, rail, rail-file, rail-frame,
  /// cant, gauge, b2b, r0, r0-right (the options of `tread contact`). Empty: no wheelsets.
  std::string wheelset_profile;
  double wheelset_ymax_mm{12.0};
  double wheelset_step_mm{0.1};
};

/// Parses a --wheelset-profile spec into a ContactSetup; throws std::invalid_argument naming the
/// key.
contact::ContactSetup parse_wheelset_profile(const std::string& spec);

using RuntimeNode = node::Node<node::MfTyreChannel, node::ContactTableChannel>;

class NodeRuntime {
 public:
  /// Loads the .tir, builds the contact table; throws std::runtime_error with a clear message.
  explicit NodeRuntime(const NodeSettings& settings);
  NodeRuntime(const NodeRuntime&) = delete;
  NodeRuntime& operator=(const NodeRuntime&) = delete;

  RuntimeNode& node() { return *node_; }
  [[nodiscard]] const mf::MfParameters<double>& tyre_parameters() const { return params_double_; }
  [[nodiscard]] const mf::MfOptions& tyre_options() const { return options_; }
  [[nodiscard]] const std::string& tir_warning() const { return tir_warning_; }
  [[nodiscard]] const rail::ContactTableF32& contact_table() const { return table_; }

 private:
  mf::MfParameters<double> params_double_{};
  mf::MfParameters<float> params_{};
  mf::MfOptions options_{};
  std::string tir_warning_;
  std::array<node::MfTyreChannel, proto::kMaxWheels> tyres_{};
  std::array<node::ContactTableChannel, proto::kMaxWheelsets> contacts_{};
  std::vector<rail::ContactRowF32> rows_;  ///< the contact table
  rail::ContactTableF32 table_{};
  std::unique_ptr<RuntimeNode> node_;
};

}  // namespace tread::host
