#pragma once
// Ceres logs through glog: without set-up, a fit's diagnostics ("Covariance matrix is near rank
// deficient", "Logging before InitGoogleLogging()") went raw onto tread's stderr between its own
// messages (Ceres logs a rank-deficient covariance as an error). quiet_solver_log keeps only
// glog's fatal messages; what a fit's user needs to know (an undetermined coefficient, a standard
// deviation not found) tread says itself.

namespace tread::fit {

/// Sets glog up once (fatal messages only, to stderr). Safe to call more than once.
void quiet_solver_log();

}  // namespace tread::fit
