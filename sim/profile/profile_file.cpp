#include "profile/profile_file.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "profile/profile_csv.hpp"
#include "profile/simpack_profile.hpp"

namespace tread::profile {

const char* role_name(ProfileRole role) {
  return role == ProfileRole::kWheel ? "wheel" : "rail";
}

const char* format_name(ProfileFormat format) {
  switch (format) {
    case ProfileFormat::kAuto:
      return "auto";
    case ProfileFormat::kCsv:
      return "csv";
    case ProfileFormat::kSimpack:
      return "simpack";
    case ProfileFormat::kMiniProf:
      return "miniprof";
  }
  return "?";
}

ProfileFormat parse_profile_format(const std::string& text) {
  for (const ProfileFormat f : {ProfileFormat::kAuto, ProfileFormat::kCsv, ProfileFormat::kSimpack,
                                ProfileFormat::kMiniProf}) {
    if (text == format_name(f)) {
      return f;
    }
  }
  throw std::invalid_argument("profile format '" + text +
                              "': expected auto, csv, simpack or miniprof");
}

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

ProfileFormat detect_format(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".prw" || ext == ".prr") {
    return ProfileFormat::kSimpack;
  }
  if (ext == ".whl" || ext == ".ban") {
    return ProfileFormat::kMiniProf;
  }
  return ProfileFormat::kCsv;
}

/// Applies the axis options and restores increasing y.
void apply_axes(SampledProfile& p, const ProfileReadOptions& options) {
  if (options.z_down) {
    for (double& z : p.z_mm) {
      z = -z;
    }
  }
  if (options.mirror_y) {
    for (double& y : p.y_mm) {
      y = -y;
    }
    std::reverse(p.y_mm.begin(), p.y_mm.end());
    std::reverse(p.z_mm.begin(), p.z_mm.end());
  }
}

}  // namespace

ProfileFile read_profile_file(const std::filesystem::path& path, ProfileRole role,
                              const ProfileReadOptions& options) {
  ProfileFile out;
  out.role = role;
  out.format = options.format == ProfileFormat::kAuto ? detect_format(path) : options.format;
  switch (out.format) {
    case ProfileFormat::kSimpack: {
      SimpackProfile read = read_simpack_profile(path);
      const ProfileRole file_role =
          read.type == SimpackProfileType::kWheel ? ProfileRole::kWheel : ProfileRole::kRail;
      if (file_role != role) {
        throw std::runtime_error(path.string() + ": the header says this is a " +
                                 role_name(file_role) + " profile, but it was given as the " +
                                 role_name(role));
      }
      out.profile = std::move(read.profile);
      break;
    }
    case ProfileFormat::kMiniProf:
      throw std::runtime_error(path.string() + ": MiniProf files are not read yet");
    case ProfileFormat::kCsv:
    case ProfileFormat::kAuto:
      out.profile = read_profile_csv(path);
      break;
  }
  apply_axes(out.profile, options);
  return out;
}

}  // namespace tread::profile
