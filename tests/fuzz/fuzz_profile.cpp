// Wheel and rail profile files (profile/profile_file.hpp: CSV, SIMPACK/CONTACT .prw/.prr, MiniProf
// .whl/.ban) from bytes no one wrote. The first two bytes pick the file's extension (which also
// picks the reader and, for MiniProf, the role it claims), the role to read it as and the reading
// options; the rest is the file, written to a temporary directory and read as a user's file is.
// Either the reader returns or its error names the file; what it returns is a profile in this
// project's convention — at least two points, y strictly increasing, every value finite — and
// every warning names the file.
#include <unistd.h>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_support.hpp"
#include "profile/profile_file.hpp"

namespace {

using namespace tread;
using fuzz::fuzz_check;
using fuzz::is_finite;

constexpr std::array<const char*, 6> kExtensions{".csv", ".prw", ".prr", ".whl", ".ban", ".txt"};

const std::filesystem::path& work_dir() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("tread_fuzz_profile_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(work_dir(), ec);
    });
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input input(data, size);
  const std::uint8_t a = input.byte();
  const std::uint8_t b = input.byte();
  const std::string name = std::string("fuzz") + kExtensions[(a & 0x7FU) % kExtensions.size()];
  const std::filesystem::path path = work_dir() / name;
  {
    const std::string_view text = input.rest();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  const profile::ProfileRole role =
      (a & 0x80U) != 0U ? profile::ProfileRole::kRail : profile::ProfileRole::kWheel;
  profile::ProfileReadOptions options;
  options.format = static_cast<profile::ProfileFormat>(b % 4U);
  options.z_down = (b & 0x04U) != 0U;
  options.mirror_y = (b & 0x08U) != 0U;
  options.locate_wheel_origin = (b & 0x10U) != 0U;
  options.resample_step_mm = (b & 0x20U) != 0U ? 0.5 : 0.0;
  options.backstep_tolerance_mm = (b & 0x40U) != 0U ? 0.0 : 0.05;

  profile::ProfileFile file;
  if (!fuzz::returns_or_names_source(
          name, [&] { file = profile::read_profile_file(path, role, options); })) {
    return 0;
  }
  const profile::SampledProfile& p = file.profile;
  fuzz_check(p.y_mm.size() == p.z_mm.size() && p.y_mm.size() >= 2,
             "a profile with fewer than 2 points or unequal columns");
  for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
    fuzz_check(is_finite(p.y_mm[i]) && is_finite(p.z_mm[i]), "a profile point that is not finite");
    fuzz_check(i == 0 || p.y_mm[i] > p.y_mm[i - 1], "profile y not strictly increasing");
  }
  fuzz_check(is_finite(file.y_shift_mm), "a wheel origin shift that is not finite");
  for (const std::string& w : file.warnings) {
    fuzz_check(w.find(name) != std::string::npos, "a warning that does not name the file: " + w);
    fuzz::check_message(name, w);
  }
  return 0;
}
