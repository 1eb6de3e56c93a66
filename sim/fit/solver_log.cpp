#include "fit/solver_log.hpp"

#include <glog/logging.h>

#include <mutex>

namespace tread::fit {

void quiet_solver_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    FLAGS_logtostderr = true;
    FLAGS_minloglevel = google::GLOG_FATAL;
    if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging("tread");
  });
}

}  // namespace tread::fit
