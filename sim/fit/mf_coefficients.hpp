#pragma once
// Magic Formula coefficients addressed by their .tir key, for the staged fitter: every stage
// names the coefficients it frees ("PCX1", "QDZ8", ...) and reads/writes them in
// tread::mf::MfParameters<T> through one table built from TREAD_MF_PARAMETER_LIST — the same list
// that drives the struct, so no coefficient is spelt twice. Host side.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "mf/mf_parameters.hpp"

namespace tread::fit {

/// The members of MfParameters<T>, in TREAD_MF_PARAMETER_LIST order.
template <typename T>
inline constexpr std::array<T mf::MfParameters<T>::*, mf::kMfParameterCount> kMfMembers = {
#define TREAD_FIT_MEMBER(member, section, key, value, description) &mf::MfParameters<T>::member,
    TREAD_MF_PARAMETER_LIST(TREAD_FIT_MEMBER)
#undef TREAD_FIT_MEMBER
};

/// Index of a .tir key in TREAD_MF_PARAMETER_LIST (case-sensitive, upper case), −1 if unknown.
int coefficient_index(std::string_view key);
/// The index of `key`; throws std::invalid_argument for an unknown key (a programming error).
int required_coefficient_index(std::string_view key);
const char* coefficient_key(int index);
const char* coefficient_section(int index);
/// The book (MFeval default) value of the coefficient.
double coefficient_default(int index);

template <typename T>
T& coefficient(mf::MfParameters<T>& p, int index) {
  return p.*kMfMembers<T>[static_cast<std::size_t>(index)];
}
template <typename T>
const T& coefficient(const mf::MfParameters<T>& p, int index) {
  return p.*kMfMembers<T>[static_cast<std::size_t>(index)];
}

/// Lower and upper bound of a fitted coefficient (±infinity where free). The seed's 1 < C < 3 for
/// the force shape factors, curvatures E ≤ 1, positive shape and slope factors of the trail and
/// of the combined-slip weighting functions, a finite range for the residual torque's Br (QBZ9,
/// QBZ10).
struct CoefficientBounds {
  double lower, upper;
};
CoefficientBounds coefficient_bounds(std::string_view key);

}  // namespace tread::fit
