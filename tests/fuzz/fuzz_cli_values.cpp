// The values users type on the command line and in spec strings, parsed by tread's own code (CLI11
// parses the plain options): .tir number tokens (tir::parse_number), profile numbers
// (profile::parse_number_text), built-in wheel specs ("S1002:h=28,e=32.5,slope=1:15") with the
// wheel they build, cants, rail sections and inclinations, wheel families, outer slopes, profile
// formats, sign conventions. The first byte picks the parser; the rest is the text.
// - a number token either parses to a finite value that its shortest text reads back exactly, or
//   is refused; the profile number parser agrees on every plain decimal, and so does a CSV row's
//   one-pass reader (host::read_csv_number_at) with a CSV cell's reader;
// - a spec either parses or throws a std::exception whose message quotes the text or the part of
//   it that is wrong (checked for short printable texts);
// - a wheel spec that parses builds a wheel whose sampled profile is finite with y increasing, or
//   is refused with a clear error.
#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "contact/contact_setup.hpp"
#include "fuzz_support.hpp"
#include "io/csv_number.hpp"
#include "io/text_line.hpp"
#include "profile/profile_file.hpp"
#include "profile/rail_profile.hpp"
#include "profile/wheel_profile.hpp"
#include "tir/tir_file.hpp"
#include "tyre/input_table.hpp"

namespace {

using namespace tread;
using fuzz::fuzz_check;
using fuzz::is_finite;

bool printable(std::string_view text) {
  for (const char c : text) {
    if (c < 0x20 || c > 0x7E) return false;
  }
  return !text.empty() && text.size() <= 40;
}

/// Whether `what` quotes `text`: the whole of it, a part of it in quotes ('1', ''), or one of its
/// words (split at spaces, ',', ':', '=') of two characters or more anywhere; true when the text
/// has no word at all.
bool quotes(const std::string& what, const std::string& text) {
  if (what.find(text) != std::string::npos) return true;
  // A part of the text in quotes, the empty one included ("family ''" for ":h=28").
  for (std::size_t open = what.find('\''); open != std::string::npos;) {
    const std::size_t close = what.find('\'', open + 1);
    if (close == std::string::npos) break;
    if (text.find(what.substr(open + 1, close - open - 1)) != std::string::npos) return true;
    open = what.find('\'', close + 1);
  }
  bool any_word = false;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find_first_of(" ,:=", start), text.size());
    if (end > start) {
      any_word = true;
      const std::string word = text.substr(start, end - start);
      if (word.size() >= 2 ? what.find(word) != std::string::npos
                           : what.find("'" + word + "'") != std::string::npos) {
        return true;
      }
    }
    start = end + 1;
  }
  return !any_word;
}

/// The spec parser throws only std::exception, with a message that says something; for a short
/// printable text it quotes what was wrong.
template <typename F>
bool parses(const std::string& text, F&& f) {
  try {
    f();
    return true;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    const std::string what = e.what();
    fuzz_check(!what.empty(), "an error without words for '" + text + "'");
    if (printable(text)) {
      fuzz_check(quotes(what, text),
                 "an error that does not quote the text '" + text + "': " + what);
    }
    return false;
  }
}

void number_token(std::string_view text) {
  const std::optional<double> v = tir::parse_number(text);
  if (v) {
    fuzz_check(is_finite(*v), "parse_number gave a value that is not finite");
    const std::optional<double> back = tir::parse_number(tir::format_number(*v));
    fuzz_check(back && std::bit_cast<std::uint64_t>(*back) == std::bit_cast<std::uint64_t>(*v),
               "format_number's text does not read back exactly");
    double plain = 0.0;
    if (text.find_first_of("dD") == std::string_view::npos &&
        host::text::parse_number_text(text, plain)) {
      fuzz_check(std::bit_cast<std::uint64_t>(plain) == std::bit_cast<std::uint64_t>(*v),
                 "the .tir and profile number parsers disagree on '" + std::string(text) + "'");
    }
  }
}

// A ',' row's one pass reads a cell where it stands (host::read_csv_number_at): where it reads
// the whole cell, the value is the cell's own (host::read_csv_number, '.' point), to the bit; and
// it reads every plain number that the cell's reading takes.
void csv_cell(std::string_view text) {
  const std::string_view cell = host::text::trim_blanks(text);
  double whole = 0.0;
  const bool number = host::read_csv_number(cell, false, whole);
  const char* end = text.data() + text.size();
  const char* p = text.data();
  while (p != end && host::text::is_blank(*p)) ++p;
  double at = 0.0;
  const char* stop = host::read_csv_number_at(p, end, at);
  while (stop != nullptr && stop != end && host::text::is_blank(*stop)) ++stop;
  if (stop == end) {
    fuzz_check(
        number && std::bit_cast<std::uint64_t>(at) == std::bit_cast<std::uint64_t>(whole),
        "the one-pass CSV reader takes '" + std::string(text) + "' as the cell's reader does not");
  } else if (number && cell.find_first_of("dD") == std::string_view::npos) {
    fuzz_check(false,
               "the one-pass CSV reader declines the plain number '" + std::string(text) + "'");
  }
}

void wheel(const std::string& text) {
  profile::WheelParameters parameters;
  if (!parses(text, [&] { parameters = contact::parse_wheel_spec(text); })) return;
  try {
    const profile::WheelProfile w(parameters);
    const profile::SampledProfile s = w.sample(1.0);
    fuzz_check(s.y_mm.size() >= 2, "a built wheel with fewer than 2 samples");
    for (std::size_t i = 0; i < s.y_mm.size(); ++i) {
      fuzz_check(is_finite(s.y_mm[i]) && is_finite(s.z_mm[i]),
                 "a built wheel with a non-finite point");
      fuzz_check(i == 0 || s.y_mm[i] > s.y_mm[i - 1], "a built wheel with y not increasing");
    }
  } catch (const std::invalid_argument& e) {
    fuzz_check(std::string_view(e.what()).size() > 0, "a wheel refused without words");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input input(data, size);
  const std::uint8_t pick = input.byte();
  const std::string text(input.rest());
  switch (pick % 9U) {
    case 0:
      number_token(text);
      csv_cell(text);
      break;
    case 1:
      wheel(text);
      break;
    case 2:
      parses(text, [&] {
        const double c = contact::parse_cant_rad(text);
        fuzz_check(is_finite(c) && c >= 0.0 && c <= std::atan(1.0 / 5.0),
                   "a cant that is not between 0 and 1:5");
      });
      break;
    case 3:
      parses(text, [&] { static_cast<void>(profile::parse_rail_section(text)); });
      break;
    case 4:
      parses(text, [&] { static_cast<void>(profile::parse_rail_inclination(text)); });
      break;
    case 5:
      parses(text, [&] { static_cast<void>(profile::parse_wheel_family(text)); });
      break;
    case 6:
      parses(text, [&] { static_cast<void>(profile::parse_outer_slope(text)); });
      break;
    case 7:
      parses(text, [&] { static_cast<void>(profile::parse_profile_format(text)); });
      break;
    default:
      static_cast<void>(tyre::parse_sign_convention(text));
      break;
  }
  return 0;
}
