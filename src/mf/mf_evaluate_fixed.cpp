// The Magic Formula on fixed::Fixed64, instantiated once, with the core's flags.
#include "mf/mf_fixed.hpp"

#include "mf/mf_evaluate.hpp"

namespace tread::mf {

template MfOutput<Fixed64> evaluate<Fixed64, Fixed64>(const MfParameters<Fixed64>&,
                                                      const MfInput<Fixed64>&, const MfOptions&);

MfParameters<Fixed64> to_fixed_parameters(const MfParameters<double>& p) {
  MfParameters<Fixed64> out;
  out.fit_type = p.fit_type;
  out.tyre_side = p.tyre_side;
#define TREAD_MF_FIXED_MEMBER(member, section, key, value, description) \
  out.member = Fixed64::from_double(p.member);
  TREAD_MF_PARAMETER_LIST(TREAD_MF_FIXED_MEMBER)
#undef TREAD_MF_FIXED_MEMBER
  return out;
}

}  // namespace tread::mf
