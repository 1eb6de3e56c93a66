#pragma once
// A test's own scratch directory: $TREAD_TEST_TMP (set by CTest to the build tree) or the system's
// temporary directory, then `name`; created if missing.

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tread::testing {

inline std::filesystem::path test_dir(const std::string& name) {
  const char* env = std::getenv("TREAD_TEST_TMP");
  std::filesystem::path dir = env != nullptr ? env : std::filesystem::temp_directory_path();
  dir /= name;
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tread::testing
