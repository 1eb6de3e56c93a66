#include "profile/profile_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>
#include <tuple>

#include "profile/miniprof_profile.hpp"
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

std::string num(double v, int decimals = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals,
                std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v);
  return buf;
}

/// A wheel or rail profile is some 100 to 200 mm wide and a few tens of mm deep. A file whose
/// points span more than a metre is in other units (µm?) or broken; refused before anything is
/// sampled at a fine step over it.
void check_extent(const ProfilePoints& points, const std::string& file) {
  constexpr double kMaxSpan_mm = 1000.0;
  const auto check = [&](const std::vector<double>& v, const char* axis) {
    if (v.empty()) return;
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    if (*hi - *lo > kMaxSpan_mm) {
      const auto line_of = [&](auto it) {
        const auto k = static_cast<std::size_t>(it - v.begin());
        return k < points.line.size() ? std::to_string(points.line[k]) : std::string("?");
      };
      throw std::runtime_error(file + ":" + line_of(hi) + ": the points span " + num(*hi - *lo, 1) +
                               " mm in " + axis + " (lines " + line_of(lo) + " and " + line_of(hi) +
                               "): a wheel or rail profile spans less than 1000 mm (is the file "
                               "in millimetres?)");
    }
  };
  check(points.y_mm, "y");
  check(points.z_mm, "z");
}

/// "1:N" for an inclination (rad).
std::string ratio(double rad) {
  if (std::abs(rad) < 1e-9) {
    return "none";
  }
  return "1:" + num(1.0 / std::tan(std::abs(rad)), 1);
}

/// Applies the axis options to the points as read.
void apply_axes(ProfilePoints& p, const ProfileReadOptions& options) {
  if (options.z_down) {
    for (double& z : p.z_mm) {
      z = -z;
    }
  }
  if (options.mirror_y) {
    for (double& y : p.y_mm) {
      y = -y;
    }
  }
}

struct Envelope {
  SampledProfile profile;
  std::vector<double> depth_mm;  ///< per input point: envelope minus its z (0 on the envelope)
};

/// The max-z envelope of the polyline through the points in their order (see the header, step 2).
Envelope max_z_envelope(const ProfilePoints& p) {
  const std::size_t n = p.y_mm.size();
  std::vector<double> ys = p.y_mm;
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const std::size_t m = ys.size();
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  constexpr std::size_t kNoSeg = std::numeric_limits<std::size_t>::max();
  std::vector<double> env(m, kNone);
  // Per interval [ys[k], ys[k+1]]: the top spanning segment at each end.
  std::vector<double> left_z(m, kNone);
  std::vector<double> right_z(m, kNone);
  std::vector<std::size_t> left_seg(m, kNoSeg);
  std::vector<std::size_t> right_seg(m, kNoSeg);
  const auto index_of = [&](double y) {
    return static_cast<std::size_t>(std::lower_bound(ys.begin(), ys.end(), y) - ys.begin());
  };
  const auto at = [&](std::size_t i, double y) {
    const double dy = p.y_mm[i + 1] - p.y_mm[i];
    return p.z_mm[i] + (y - p.y_mm[i]) / dy * (p.z_mm[i + 1] - p.z_mm[i]);
  };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const std::size_t ki = index_of(p.y_mm[i]);
    const std::size_t kj = index_of(p.y_mm[i + 1]);
    const std::size_t ka = std::min(ki, kj);
    const std::size_t kb = std::max(ki, kj);
    if (ka == kb) {  // vertical segment
      env[ka] = std::max({env[ka], p.z_mm[i], p.z_mm[i + 1]});
      continue;
    }
    const auto z_at_k = [&](std::size_t k) {
      return k == ki ? p.z_mm[i] : k == kj ? p.z_mm[i + 1] : at(i, ys[k]);
    };
    for (std::size_t k = ka; k <= kb; ++k) {
      const double z = z_at_k(k);
      env[k] = std::max(env[k], z);
      if (k < kb) {
        const double zr = z_at_k(k + 1);
        if (z > left_z[k]) {
          left_z[k] = z;
          left_seg[k] = i;
        }
        if (zr > right_z[k]) {
          right_z[k] = zr;
          right_seg[k] = i;
        }
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {  // single points (no segment) cannot occur: n >= 2
    const std::size_t k = index_of(p.y_mm[i]);
    env[k] = std::max(env[k], p.z_mm[i]);
  }
  Envelope out;
  out.profile.name = p.name;
  for (std::size_t k = 0; k < m; ++k) {
    out.profile.y_mm.push_back(ys[k]);
    out.profile.z_mm.push_back(env[k]);
    if (k + 1 < m && left_seg[k] != kNoSeg && right_seg[k] != kNoSeg &&
        left_seg[k] != right_seg[k]) {
      // Two segments cross inside the interval: the envelope has a corner there.
      const std::size_t a = left_seg[k];
      const std::size_t b = right_seg[k];
      const double h = ys[k + 1] - ys[k];
      const double fa0 = at(a, ys[k]);
      const double fb0 = at(b, ys[k]);
      const double fa1 = at(a, ys[k + 1]);
      const double fb1 = at(b, ys[k + 1]);
      const double d0 = fa0 - fb0;
      const double d1 = fa1 - fb1;
      if (std::abs(d0 - d1) > 0.0) {
        const double t = d0 / (d0 - d1);
        if (t > 1e-9 && t < 1.0 - 1e-9) {
          out.profile.y_mm.push_back(ys[k] + t * h);
          out.profile.z_mm.push_back(fa0 + t * (fa1 - fa0));
        }
      }
    }
  }
  out.depth_mm.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.depth_mm[i] = env[index_of(p.y_mm[i])] - p.z_mm[i];
  }
  return out;
}

/// Step 2 with its warnings.
SampledProfile clean(const ProfilePoints& p, const std::string& file, ProfileRole role,
                     const ProfileReadOptions& options, ProfileFile& out) {
  const Envelope e = max_z_envelope(p);
  const std::size_t n = p.y_mm.size();
  constexpr double kHiddenDepth_mm = 1e-9;
  constexpr double kGeometryDepth_mm = 1.0;  // deeper than this is geometry even without back-step
  // Back-step of each point behind the furthest point before it (file order, y increasing).
  std::vector<double> back(n, 0.0);
  double furthest = p.y_mm[0];
  for (std::size_t i = 1; i < n; ++i) {
    back[i] = std::max(0.0, furthest - p.y_mm[i]);
    furthest = std::max(furthest, p.y_mm[i]);
  }
  std::size_t noise_points = 0;
  std::size_t noise_places = 0;
  double noise_back = 0.0;
  double noise_y0 = std::numeric_limits<double>::infinity();
  double noise_y1 = -std::numeric_limits<double>::infinity();
  std::vector<std::string> geometry;
  std::size_t i = 0;
  while (i < n) {
    if (!(e.depth_mm[i] > kHiddenDepth_mm)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < n && e.depth_mm[j + 1] > kHiddenDepth_mm) {
      ++j;
    }
    const std::size_t lo = i > 0 ? i - 1 : i;
    const std::size_t hi = std::min(j + 1, n - 1);
    double run_back = 0.0;
    double depth = 0.0;
    double y0 = std::numeric_limits<double>::infinity();
    double y1 = -y0;
    for (std::size_t k = lo; k <= hi; ++k) {
      run_back = std::max(run_back, back[k]);
    }
    for (std::size_t k = i; k <= j; ++k) {
      depth = std::max(depth, e.depth_mm[k]);
      y0 = std::min(y0, p.y_mm[k]);
      y1 = std::max(y1, p.y_mm[k]);
    }
    const std::size_t count = j - i + 1;
    out.points_hidden += count;
    if (run_back <= options.backstep_tolerance_mm && depth <= kGeometryDepth_mm) {
      noise_points += count;
      ++noise_places;
      noise_back = std::max(noise_back, run_back);
      noise_y0 = std::min(noise_y0, y0);
      noise_y1 = std::max(noise_y1, y1);
    } else {
      const std::string where = "lines " + std::to_string(p.line[i]) + "-" +
                                std::to_string(p.line[j]) + ", y " + num(y0) + " to " + num(y1) +
                                " mm";
      geometry.push_back((run_back > 0.0
                              ? "the profile turns back in y by " + num(run_back) + " mm (" +
                                    where + ": an undercut)"
                              : "the profile runs vertical (" + where + ": a vertical side)") +
                         ": " + std::to_string(count) + " point" + (count == 1 ? "" : "s") +
                         " up to " + num(depth) + " mm below the contact envelope hidden");
    }
    i = j + 1;
  }
  const char* env_name = role == ProfileRole::kRail ? "upper envelope" : "max-z envelope";
  if (noise_points > 0) {
    out.warnings.push_back(
        file + ": " + std::to_string(noise_points) + " point" + (noise_points == 1 ? "" : "s") +
        " in " + std::to_string(noise_places) + " place" + (noise_places == 1 ? "" : "s") +
        " between y = " + num(noise_y0) + " and " + num(noise_y1) + " mm step back in y by up to " +
        num(noise_back) + " mm (measurement noise, tolerance " +
        num(options.backstep_tolerance_mm) + " mm): dropped, the " + env_name + " is kept");
  }
  constexpr std::size_t kMaxListed = 4;
  for (std::size_t k = 0; k < geometry.size() && k < kMaxListed; ++k) {
    out.warnings.push_back(file + ": " + geometry[k] + "; the " + env_name + " is used");
  }
  if (geometry.size() > kMaxListed) {
    out.warnings.push_back(file + ": " + std::to_string(geometry.size() - kMaxListed) +
                           " more places where the profile turns back in y");
  }
  return e.profile;
}

/// Linear interpolation of an increasing profile (clamped).
double z_at(const SampledProfile& p, double y) {
  if (y <= p.y_mm.front()) {
    return p.z_mm.front();
  }
  if (y >= p.y_mm.back()) {
    return p.z_mm.back();
  }
  const auto it = std::upper_bound(p.y_mm.begin(), p.y_mm.end(), y);
  const auto k = static_cast<std::size_t>(it - p.y_mm.begin());
  const double t = (y - p.y_mm[k - 1]) / (p.y_mm[k] - p.y_mm[k - 1]);
  return p.z_mm[k - 1] + t * (p.z_mm[k] - p.z_mm[k - 1]);
}

/// The width of a profile's top `depth_mm` below its highest point (index `top`): the chord
/// between the crossings of that level on either side. nullopt where the profile ends before it
/// falls that far on a side.
std::optional<double> top_chord_mm(const SampledProfile& p, std::size_t top, double depth_mm) {
  const double level = p.z_mm[top] - depth_mm;
  std::size_t l = top;
  while (l > 0 && p.z_mm[l - 1] >= level) --l;
  std::size_t h = top;
  while (h + 1 < p.z_mm.size() && p.z_mm[h + 1] >= level) ++h;
  if (l == 0 || h + 1 == p.z_mm.size()) return std::nullopt;
  const auto cross = [&](std::size_t a, std::size_t b) {
    return p.y_mm[a] + (level - p.z_mm[a]) / (p.z_mm[b] - p.z_mm[a]) * (p.y_mm[b] - p.y_mm[a]);
  };
  return cross(h, h + 1) - cross(l - 1, l);
}

// A wheel's flange and a rail's head told apart by their width 10 mm below the top: an EN 13715
// flange is about 27 mm wide there (25 to 31 mm from thin to thick), a rail head 60 to 72 mm (the
// full head width: its sides are steep from a few mm below the crown).
constexpr double kTopChordDepth_mm = 10.0;
constexpr double kFlangeChordMax_mm = 45.0;  // wider: a rail head given as a wheel
constexpr double kHeadChordMin_mm = 35.0;    // narrower, with a tread beside it: a wheel as a rail
constexpr double kTreadBeside_mm = 40.0;     // a wheel's tread runs on this far past its flange

/// A single point standing off its neighbours, up then down (or down then up) over steep flanks:
/// a measuring fault (dust, a reflection), which the contact search would touch as if it were
/// the profile. Said, with the first one and how many; not removed (it could be a real edge).
void warn_spikes(const SampledProfile& p, const std::string& file, ProfileFile& out) {
  constexpr double kNeighbourGap_mm = 1.0;  // neighbours this close: a measured point's spacing
  constexpr double kSpikeHeight_mm = 0.3;   // off the chord of its neighbours by at least this
  constexpr double kSteepSlope = 3.0;       // both flanks steeper than 72 degrees
  std::size_t count = 0;
  std::size_t first = 0;
  double first_height = 0.0;
  for (std::size_t k = 1; k + 1 < p.y_mm.size(); ++k) {
    const double dy1 = p.y_mm[k] - p.y_mm[k - 1];
    const double dy2 = p.y_mm[k + 1] - p.y_mm[k];
    if (dy1 > kNeighbourGap_mm || dy2 > kNeighbourGap_mm) continue;
    const double s1 = (p.z_mm[k] - p.z_mm[k - 1]) / dy1;
    const double s2 = (p.z_mm[k + 1] - p.z_mm[k]) / dy2;
    const double chord = p.z_mm[k - 1] + (p.z_mm[k + 1] - p.z_mm[k - 1]) * dy1 / (dy1 + dy2);
    const double height = p.z_mm[k] - chord;
    if (s1 * s2 < 0.0 && std::abs(s1) >= kSteepSlope && std::abs(s2) >= kSteepSlope &&
        std::abs(height) >= kSpikeHeight_mm) {
      if (count++ == 0) {
        first = k;
        first_height = height;
      }
    }
  }
  if (count == 0) return;
  out.warnings.push_back(
      file + ": " + std::to_string(count) + (count == 1 ? " point stands" : " points stand") +
      " off its neighbours as a spike (the first at y = " + num(p.y_mm[first]) + " mm, " +
      num(first_height) +
      " mm off the line between them): a measuring fault? The contact touches it as part of the "
      "profile; remove it, or smooth the profile (--smooth)");
}

/// Step 3: flange side, z sense and the taping line of a wheel.
void check_wheel(SampledProfile& w, const std::string& file, const ProfileReadOptions& options,
                 ProfileFile& out) {
  constexpr double kFlangeDrop_mm = 10.0;   // the flange stands this much above the tread
  constexpr double kTreadExtent_mm = 30.0;  // the tread side of the tip is at least this long
  constexpr double kNominalTip_mm = -55.0;  // EN 13715 flange tip (R12 arc top)
  constexpr double kTipTolerance_mm = 6.0;  // worn and thin flanges move the tip this much
  constexpr double kSteepRise_mm = 2.0;     // back flank: z rises this much over the first mm
  const std::size_t n = w.y_mm.size();
  const double y0 = w.y_mm.front();
  const double y1 = w.y_mm.back();
  // A flange: an interior extremum with a long tread on one side, >= 10 mm below it.
  struct Flange {
    bool found = false;
    bool tread_on_plus_y = true;
    double y_tip = 0.0;
    std::size_t tip = 0;
  };
  const auto find_flange = [&](double sign) {
    Flange f;
    std::size_t tip = 0;
    for (std::size_t k = 1; k < n; ++k) {
      if (sign * w.z_mm[k] > sign * w.z_mm[tip]) {
        tip = k;
      }
    }
    if (tip == 0 || tip + 1 == n) {
      return f;
    }
    double drop_left = 0.0;
    double drop_right = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double drop = sign * (w.z_mm[tip] - w.z_mm[k]);
      if (k < tip) {
        drop_left = std::max(drop_left, drop);
      } else {
        drop_right = std::max(drop_right, drop);
      }
    }
    f.y_tip = w.y_mm[tip];
    f.tip = tip;
    f.tread_on_plus_y = y1 - f.y_tip >= f.y_tip - y0;
    const double extent = f.tread_on_plus_y ? y1 - f.y_tip : f.y_tip - y0;
    const double drop = f.tread_on_plus_y ? drop_right : drop_left;
    f.found = drop >= kFlangeDrop_mm && extent >= kTreadExtent_mm;
    return f;
  };
  const Flange up = find_flange(1.0);
  if (!up.found) {
    const Flange down = find_flange(-1.0);
    if (down.found) {
      throw std::runtime_error(
          file + ": the wheel's flange points toward -z (its tip is the lowest point, at y = " +
          num(down.y_tip) + " mm): this project's wheel z is the radius increase, + toward the " +
          "flange tip; " + (options.z_down ? "do not pass " : "pass ") + options.option_prefix +
          "z-down");
    }
    // No flange (a cone, a tread-only profile): nothing to locate by, and no flange contact.
    out.warnings.push_back(file +
                           ": no flange (no interior point 10 mm above a tread at least 30 mm "
                           "long): a cone or a tread alone; flange contact, its angle and the "
                           "measures are not available");
    return;
  }
  if (const std::optional<double> chord = top_chord_mm(w, up.tip, kTopChordDepth_mm);
      chord && *chord > kFlangeChordMax_mm) {
    throw std::runtime_error(
        file + ": not a wheel profile: its top (y = " + num(up.y_tip) + " mm) is " +
        num(*chord, 1) + " mm wide " + num(kTopChordDepth_mm, 0) +
        " mm below it, a rail head's width (a wheel's flange is 25 to 31 mm wide there); a rail "
        "goes in as the rail (--rail-file, --role rail)");
  }
  if (!up.tread_on_plus_y) {
    throw std::runtime_error(
        file + ": the wheel's flange (tip at y = " + num(up.y_tip) +
        " mm) is on the +y side of its tread: this project's wheel y is + toward the field " +
        "side, the flange at negative y; " + (options.mirror_y ? "do not pass " : "pass ") +
        options.option_prefix + "mirror-y");
  }
  const double offset = y0 + kTapingLineFromFlangeBack_mm;  // flange back found at -70 + offset
  const bool back_measured = z_at(w, y0 + 1.0) - w.z_mm.front() >= kSteepRise_mm;
  out.header.emplace_back("tread.flange_tip_y_mm", num(up.y_tip));
  if (back_measured) {
    out.header.emplace_back("tread.flange_back_y_mm", num(y0));
  }
  if (std::abs(offset) <= options.origin_tolerance_mm) {
    return;
  }
  if (!back_measured) {
    const double tip_offset = up.y_tip - kNominalTip_mm;
    if (std::abs(tip_offset) > kTipTolerance_mm) {
      throw std::runtime_error(
          file +
          ": y = 0 does not look like the taping line: the flange tip is at y = " + num(up.y_tip) +
          " mm, " + num(tip_offset) + " mm from an EN 13715 wheel's (" + num(kNominalTip_mm, 0) +
          " mm), and the flange back is not in the file (no steep back flank at its start, y = " +
          num(y0) + " mm) to locate it by: give y from the taping line, 70 mm from the flange " +
          "back");
    }
    out.warnings.push_back(file +
                           ": the flange back is not in the file (it starts at y = " + num(y0) +
                           " mm without the steep back flank): the taping line is taken as given");
    return;
  }
  if (!options.locate_wheel_origin) {
    out.warnings.push_back(file + ": the flange back is at y = " + num(y0) + " mm, " + num(offset) +
                           " mm from -70: y = 0 is not the taping line (not moved)");
    return;
  }
  for (double& y : w.y_mm) {
    y -= offset;
  }
  out.y_shift_mm = -offset;
  out.warnings.push_back(file + ": the flange back is at y = " + num(y0) +
                         " mm in the file, not -70: the profile was shifted by " + num(-offset) +
                         " mm so that y = 0 is the taping line (70 mm from the flange back)");
}

/// Step 4: the inclination of a rail head from its symmetry. In a frame where the head stands
/// upright its horizontal chords 1 to 10 mm below the top all have the same midpoint (the head's
/// axis); in any other frame they drift (each circular arc of the head keeps its chords' midpoints
/// at its centre, and the centres of the R300 crown and the R80/R13 sides move apart when
/// inclined). The angle that makes the midpoints' spread least is the inclination (coarse scan of
/// +-0.1 rad by 0.001 rad, then golden-section search). nullopt when the profile does not reach
/// 10 mm below its top on both sides, or when the head is not symmetric at any angle (rms spread
/// over 0.3 mm: a worn head).
std::optional<double> head_inclination_rad(const SampledProfile& r) {
  const std::size_t n = r.y_mm.size();
  std::vector<double> y(n);
  std::vector<double> z(n);
  // The rms spread of the chord midpoints in the frame uncanted by theta; < 0 if not measurable.
  const auto spread = [&](double theta) {
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    for (std::size_t k = 0; k < n; ++k) {
      y[k] = c * r.y_mm[k] + s * r.z_mm[k];
      z[k] = -s * r.y_mm[k] + c * r.z_mm[k];
    }
    const auto top = static_cast<std::size_t>(std::max_element(z.begin(), z.end()) - z.begin());
    constexpr int kLevels = 19;  // 1, 1.5, ..., 10 mm below the top
    double sum = 0.0;
    double sum2 = 0.0;
    for (int level_no = 0; level_no < kLevels; ++level_no) {
      const double level = z[top] - (1.0 + 0.5 * level_no);
      std::size_t l = top;
      while (l > 0 && z[l - 1] >= level) {
        --l;
      }
      std::size_t h = top;
      while (h + 1 < n && z[h + 1] >= level) {
        ++h;
      }
      if (l == 0 || h + 1 == n) {
        return -1.0;
      }
      const double yl = y[l - 1] + (level - z[l - 1]) / (z[l] - z[l - 1]) * (y[l] - y[l - 1]);
      const double yh = y[h] + (level - z[h]) / (z[h + 1] - z[h]) * (y[h + 1] - y[h]);
      const double m = 0.5 * (yl + yh);
      sum += m;
      sum2 += m * m;
    }
    const double mean = sum / kLevels;
    return std::sqrt(std::max(0.0, sum2 / kLevels - mean * mean));
  };
  double best = 0.0;
  double best_spread = spread(0.0);
  if (best_spread < 0.0) {
    return std::nullopt;
  }
  constexpr double kRange_rad = 0.1;
  constexpr double kStep_rad = 0.001;
  for (int k = -100; k <= 100; ++k) {
    const double theta = k * kStep_rad;
    const double f = spread(theta);
    if (f >= 0.0 && f < best_spread) {
      best_spread = f;
      best = theta;
    }
  }
  double a = std::max(-kRange_rad, best - kStep_rad);
  double b = std::min(kRange_rad, best + kStep_rad);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double c1 = b - g * (b - a);
    const double c2 = a + g * (b - a);
    const double f1 = spread(c1);
    const double f2 = spread(c2);
    if (f1 >= 0.0 && (f2 < 0.0 || f1 < f2)) {
      b = c2;
    } else {
      a = c1;
    }
  }
  const double theta = 0.5 * (a + b);
  const double f = spread(theta);
  constexpr double kSymmetric_mm = 0.3;
  if (f < 0.0 || f > kSymmetric_mm) {
    return std::nullopt;
  }
  return theta;
}

void resample(SampledProfile& p, double step_mm) {
  SampledProfile out;
  out.name = p.name;
  const double first = std::ceil(p.y_mm.front() / step_mm - 1e-9) * step_mm;
  for (double y = first; y <= p.y_mm.back() + 1e-9; y += step_mm) {
    const double yc = std::min(y, p.y_mm.back());
    out.y_mm.push_back(yc);
    out.z_mm.push_back(z_at(p, yc));
  }
  if (out.y_mm.size() >= 2) {
    p = std::move(out);
  }
}

}  // namespace

ProfileFile read_profile_file(const std::filesystem::path& path, ProfileRole role,
                              const ProfileReadOptions& options) {
  const std::string file = path.string();
  // A directory opens as an empty stream, and an empty file reads as "file:0: fewer than 2
  // points": each said as what it is.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw std::runtime_error(file + ": is a directory, not a profile file");
  }
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error(file + ": cannot open the file");
  }
  if (in.peek() == std::ifstream::traits_type::eof()) {
    throw std::runtime_error(file + ": the file is empty");
  }
  ProfileFile out;
  out.role = role;
  out.format = options.format == ProfileFormat::kAuto ? detect_format(path) : options.format;
  ProfilePoints points;
  bool miniprof_wheel = false;
  switch (out.format) {
    case ProfileFormat::kSimpack: {
      SimpackPoints read = read_simpack_points(in, file);
      const ProfileRole file_role =
          read.type == SimpackProfileType::kWheel ? ProfileRole::kWheel : ProfileRole::kRail;
      out.header.emplace_back("type", read.type == SimpackProfileType::kWheel ? "1" : "0");
      if (!read.comment.empty()) {
        out.header.emplace_back("comment", read.comment);
      }
      if (file_role != role) {
        throw std::runtime_error(
            file + ": the header says this is a " + role_name(file_role) +
            " profile (type = " + (file_role == ProfileRole::kWheel ? "1" : "0") +
            "), but it was given as the " + role_name(role));
      }
      points = std::move(read.points);
      out.warnings.insert(out.warnings.end(), read.notes.begin(), read.notes.end());
      break;
    }
    case ProfileFormat::kMiniProf: {
      // MiniProf names the role by the extension: .whl wheel, .ban rail (track, "bane").
      const std::string ext = lower_extension(path);
      if ((ext == ".whl" && role == ProfileRole::kRail) ||
          (ext == ".ban" && role == ProfileRole::kWheel)) {
        throw std::runtime_error(file + ": a MiniProf " + ext + " file is a " +
                                 (ext == ".whl" ? "wheel" : "rail") +
                                 " profile, but it was given as the " + role_name(role));
      }
      MiniProfFile read = read_miniprof(in, file);
      std::string offsets;
      for (const auto& [name, mm, line] :
           {std::tuple{"XOffset", read.x_offset_mm, read.x_offset_line},
            std::tuple{"YOffset", read.y_offset_mm, read.y_offset_line}}) {
        if (line > 0) {
          offsets += (offsets.empty() ? "" : ", ") + std::string(name) + " = " + num(mm) +
                     " mm (line " + std::to_string(line) + ")";
        }
      }
      if (!offsets.empty()) {
        out.warnings.push_back(file + ": the header's " + offsets +
                               " added to every point's X and Y as read");
      }
      out.header = std::move(read.header);
      points = std::move(read.points);
      if (role == ProfileRole::kWheel) {
        // X from the flange back, Y up with the flange pointing down.
        for (double& y : points.y_mm) {
          y -= kTapingLineFromFlangeBack_mm;
        }
        for (double& z : points.z_mm) {
          z = -z;
        }
        miniprof_wheel = true;
      }
      break;
    }
    case ProfileFormat::kCsv:
    case ProfileFormat::kAuto:
      points = read_profile_csv_points(in, file, CsvDialect::kTolerant);
      out.header = points.header;
      break;
  }
  out.points_read = points.y_mm.size();
  check_extent(points, file);
  apply_axes(points, options);
  if (points.y_mm.back() < points.y_mm.front()) {  // given in decreasing y
    std::reverse(points.y_mm.begin(), points.y_mm.end());
    std::reverse(points.z_mm.begin(), points.z_mm.end());
    std::reverse(points.line.begin(), points.line.end());
  }
  out.profile = clean(points, file, role, options, out);
  if (out.profile.y_mm.size() < 2) {
    throw std::runtime_error(file + ": fewer than 2 distinct y values");
  }
  {
    // Measured profiles are sampled every 0.1 to 0.5 mm; at several mm between points the
    // contact angles, measures and conicity come from the straight lines between them.
    std::vector<double> gaps;
    for (std::size_t k = 1; k < out.profile.y_mm.size(); ++k) {
      gaps.push_back(out.profile.y_mm[k] - out.profile.y_mm[k - 1]);
    }
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2),
                     gaps.end());
    const double median_gap = gaps[gaps.size() / 2];
    if (median_gap > 1.0) {
      out.warnings.push_back(file + ": the points are " + num(median_gap) +
                             " mm apart (median): too coarse for contact angles and conicity, "
                             "which take the straight lines between them (measured profiles are "
                             "sampled every 0.1 to 0.5 mm)");
    } else {
      // One gap among fine points: where the contact falls into it, the straight line across it
      // is taken for the profile (a 20 mm gap in the tread gave a conicity 20 times too small).
      const auto& y = out.profile.y_mm;
      std::size_t widest = 1;
      for (std::size_t k = 2; k < y.size(); ++k) {
        if (y[k] - y[k - 1] > y[widest] - y[widest - 1]) widest = k;
      }
      const double gap = y[widest] - y[widest - 1];
      if (gap > 2.0 && gap > 10.0 * median_gap) {
        out.warnings.push_back(file + ": no points between y = " + num(y[widest - 1]) + " and " +
                               num(y[widest]) + " mm (a gap of " + num(gap) +
                               " mm where the points are " + num(median_gap) +
                               " mm apart): a contact there lies on the straight line across it");
      }
    }
  }
  warn_spikes(out.profile, file, out);
  if (role == ProfileRole::kWheel) {
    check_wheel(out.profile, file, options, out);
    // A wheel's z is referred to its taping line (y = 0, where --r0 is the radius): a file that
    // stops short of it (a flange only, a cut file) gave z(0) as the end point's and contacts
    // at the end of the profile under ok.
    // (Kept as it is with locate_wheel_origin off: check_wheel has said where its back lies.)
    if (options.locate_wheel_origin &&
        (out.profile.y_mm.front() > 0.0 || out.profile.y_mm.back() < 0.0)) {
      throw std::runtime_error(
          file + ": the wheel's points run from y = " + num(out.profile.y_mm.front()) + " to " +
          num(out.profile.y_mm.back()) +
          " mm and do not reach the taping line (y = 0, 70 mm from the flange back), where the "
          "wheel's radius is referred");
    }
    if (!miniprof_wheel) {
      // z is the radius increase over the taping line (r0 is the radius there): a file whose z
      // at y = 0 is far from 0 (an absolute radius, another reference) is referred to it.
      const double z0 = z_at(out.profile, 0.0);
      if (std::abs(z0) > 0.01) {
        for (double& z : out.profile.z_mm) {
          z -= z0;
        }
        out.taping_z_in_file_mm = z0;
        out.warnings.push_back(file + ": z at the taping line (y = 0) is " + num(z0) +
                               " mm in the file: z referred to it (z = 0 there, where --r0 is "
                               "the radius)");
      }
    }
    if (miniprof_wheel) {
      // MiniProf's Y has no wheel reference: z is referred to the taping line (r0 is there).
      const double z0 = z_at(out.profile, 0.0);
      for (double& z : out.profile.z_mm) {
        z -= z0;
      }
      out.taping_z_in_file_mm = z0;
    }
  } else {
    // A rail head's top is its highest point, the sides fall away from it; a head whose lowest
    // point lies inside with both ends 5 mm above it is written with z down.
    const auto& z = out.profile.z_mm;
    const auto lowest = std::min_element(z.begin(), z.end());
    if (lowest != z.begin() && lowest + 1 != z.end() && z.front() - *lowest >= 5.0 &&
        z.back() - *lowest >= 5.0) {
      throw std::runtime_error(file + ": the rail head's lowest point is inside the profile (y = " +
                               num(out.profile.y_mm[static_cast<std::size_t>(lowest - z.begin())]) +
                               " mm) with its ends above it: z points down; " +
                               (options.z_down ? "do not pass " : "pass ") + options.option_prefix +
                               "z-down");
    }
    {
      // A wheel given as the rail: its flange is the highest part, narrow, with the tread beside.
      const SampledProfile& r = out.profile;
      const auto top = static_cast<std::size_t>(std::max_element(z.begin(), z.end()) - z.begin());
      const std::optional<double> chord = top_chord_mm(r, top, kTopChordDepth_mm);
      const double beside = std::max(r.y_mm[top] - r.y_mm.front(), r.y_mm.back() - r.y_mm[top]);
      if (chord && *chord < kHeadChordMin_mm && beside - 0.5 * *chord >= kTreadBeside_mm) {
        throw std::runtime_error(
            file + ": not a rail profile: its top (y = " + num(r.y_mm[top]) + " mm) is " +
            num(*chord, 1) + " mm wide " + num(kTopChordDepth_mm, 0) + " mm below it with " +
            num(beside, 0) +
            " mm of profile beside it: a wheel's flange and tread (a rail head is 60 to 72 mm wide "
            "there); a wheel goes in as the wheel (--wheel-file, --role wheel)");
      }
    }
    out.rail_inclination_rad = head_inclination_rad(out.profile);
    if (out.rail_inclination_rad) {
      out.header.emplace_back("tread.head_inclination", ratio(*out.rail_inclination_rad) + " (" +
                                                            num(*out.rail_inclination_rad, 4) +
                                                            " rad, + toward -y)");
    }
  }
  if (options.resample_step_mm > 0.0) {
    resample(out.profile, options.resample_step_mm);
  }
  out.profile.name = path.stem().string();
  return out;
}

}  // namespace tread::profile
