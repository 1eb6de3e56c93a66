#pragma once
// Where golden tests find ../shared/refdata: the TREAD_REFDATA_DIR environment variable if set,
// else the CMake cache variable of the same name compiled in. A missing directory fails the test
// (never skips).

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tread::testing {

inline std::filesystem::path refdata_dir() {
  if (const char* env = std::getenv("TREAD_REFDATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return TREAD_REFDATA_DIR;
}

/// refdata_dir() / relative; the caller should ASSERT_TRUE(exists(...)) with a clear message.
inline std::filesystem::path refdata(const std::string& relative) {
  return refdata_dir() / relative;
}

}  // namespace tread::testing
