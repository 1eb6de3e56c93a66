#pragma once
#include <string>

namespace tread::host {

/// "tread 0.1.0 (compiler, build type)".
std::string version_string();

}  // namespace tread::host
