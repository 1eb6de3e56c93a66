#include "host_info.hpp"

namespace tread::host {

std::string version_string() {
  return std::string("tread 0.1.0 (g++ ") + __VERSION__ + ")";
}

}  // namespace tread::host
