#pragma once
// Turns Magic Formula parameters (tread::mf::MfParameters<double>, e.g. from
// tyre::load_mf_parameters) into a constexpr C++ header holding a ready MfParameters<float> or
// <double>, so an ECU build flashes a tyre without a file system or parser:
//
//   #include "mf/mf_parameters.hpp"
//   namespace <ns> {
//   inline constexpr tread::mf::MfParameters<float> <name> = {
//       .fit_type = static_cast<tread::mf::FitType>(61), .tyre_side = ..., .longvl_mps = 16.6f,
//       ...};
//   }
//
// The members follow TREAD_MF_PARAMETER_LIST (designated initializers, declaration order), so a
// key added there is generated without touching this file. Each value is written in the shortest
// form that reads back to exactly the target scalar: for float, static_cast<float>(double value),
// i.e. bit-identical to mf::convert_parameters<float>().

#include <string>

#include "mf/mf_parameters.hpp"

namespace tread::tir {

struct MfHeaderOptions {
  std::string name = "kTyre";
  std::string name_space = "tyres";
  bool use_float = true;  ///< MfParameters<float> (ECU) or <double>
  std::string source;     ///< mentioned in the header comment
  /// MfParameters<fixed::Fixed64> (cores without an FPU), overriding use_float: every value as
  /// Fixed64::from_raw of mf::to_fixed_parameters()'s raw value (bit-identical to the host's
  /// conversion), its decimal in the comment; a value outside Q31.32 as Fixed64::invalid().
  bool use_fixed = false;
};

/// Throws TirError (line 0) for an invalid identifier or namespace.
std::string generate_mf_header(const mf::MfParameters<double>& params, const MfHeaderOptions& o);

}  // namespace tread::tir
