// Explicit instantiations of the Magic Formula for the core's two scalars, compiled with the core's
// flags (no exceptions, no RTTI). ceres::Jet and other scalars instantiate the header themselves.
#include "mf/mf_evaluate.hpp"

namespace tread::mf {

template MfOutput<float> evaluate<float>(const MfParameters<float>&, const MfInput<float>&,
                                         const MfOptions&);
template MfOutput<double> evaluate<double>(const MfParameters<double>&, const MfInput<double>&,
                                           const MfOptions&);

}  // namespace tread::mf
