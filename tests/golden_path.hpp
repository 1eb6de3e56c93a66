#pragma once
// Where tests find their data. Everything a test reads ships with the project:
//   - tests/data/   golden references in the project's own formats (MFeval outputs, EN 13715 /
//                   EN 15302 tables, benchmark profiles, the seed's appendix table);
//   - data/tyres/   the example tyre property files (rewritten by `tread tir convert`).
// data/PROVENANCE.md says where each came from. The originals (../shared/refdata) are optional:
// refdata_originals() names them for the one test that checks the shipped numbers against them.
// A missing shipped file fails the test (never skips).

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace tread::testing {

/// The project's source root (compiled in).
inline std::filesystem::path source_dir() {
  return TREAD_SOURCE_DIR;
}

/// tests/data / relative; the caller should ASSERT_TRUE(exists(...)) with a clear message.
inline std::filesystem::path test_data(const std::string& relative) {
  return source_dir() / "tests" / "data" / relative;
}

/// The example tyres' folder, data/tyres.
inline std::filesystem::path tyres_dir() {
  return source_dir() / "data" / "tyres";
}

/// data/tyres / name.
inline std::filesystem::path tyre_file(const std::string& name) {
  return tyres_dir() / name;
}

/// The originals the shipped data was made from: the TREAD_REFDATA_DIR environment variable if
/// set, else the CMake cache variable of that name; nullopt when that directory does not exist
/// (a clone with nothing beside it).
inline std::optional<std::filesystem::path> refdata_originals() {
  std::filesystem::path dir = TREAD_REFDATA_DIR;
  if (const char* env = std::getenv("TREAD_REFDATA_DIR"); env != nullptr && *env != '\0') {
    dir = env;
  }
  if (dir.empty() || !std::filesystem::is_directory(dir)) return std::nullopt;
  return dir;
}

}  // namespace tread::testing
