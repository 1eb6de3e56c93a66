#include "tir/tir_normalise.hpp"

#include <cstddef>
#include <string_view>

#include "io/text_line.hpp"

namespace tread::tir {

namespace {

constexpr std::size_t kKeyWidth = 25;  // "KEY" padded so the '=' line up, as TNO files do

// A table row without its trailing `$`/`!` comment.
std::string_view row_without_comment(std::string_view row) noexcept {
  const std::size_t c = row.find_first_of("$!");
  return host::text::trim_blanks(c == std::string_view::npos ? row : row.substr(0, c));
}

}  // namespace

std::string write_normalised_tir(const TirFile& file, const std::string& note) {
  std::string out;
  if (!note.empty()) {
    out += "$ ";
    for (const char c : note) out += (c == '\n' || c == '\r') ? ' ' : c;
    out += '\n';
  }
  for (const Section& s : file.sections()) {
    out += '[';
    out += s.name;
    out += "]\n";
    for (const Line& l : s.lines) {
      if (l.kind == Line::Kind::kEntry) {
        out += entry_text(l.entry, kKeyWidth, /*with_comment=*/false);
        out += '\n';
      } else if (l.kind == Line::Kind::kTableRow) {
        const std::string_view row = row_without_comment(l.text);
        if (!row.empty()) {
          out += row;
          out += '\n';
        }
      }
    }
  }
  return out;
}

}  // namespace tread::tir
