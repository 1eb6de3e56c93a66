#include "tir/tir_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>

#include "io/text_line.hpp"

namespace tread::tir {

namespace {

char lower(char c) noexcept {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool is_space(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f';
}
bool is_comment_start(char c) noexcept {
  return c == '$' || c == '!';
}
bool is_key_start(char c) noexcept {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
}
bool is_key_char(char c) noexcept {
  return is_key_start(c) || (c >= '0' && c <= '9');
}

[[noreturn]] void fail(const std::string& origin, int line, const std::string& what) {
  throw TirError(origin, line, what);
}

// Parses the part after '=' of an entry line into entry.value/quote/comment.
void parse_value(std::string_view rest, Entry& entry, const std::string& origin, int line) {
  rest = host::text::trim_blanks(rest);
  if (rest.empty() || is_comment_start(rest.front())) {
    fail(origin, line, "missing value after '=' for key '" + entry.key + "'");
  }
  if (rest.front() == '\'' || rest.front() == '"') {
    const char q = rest.front();
    const std::size_t close = rest.find(q, 1);
    if (close == std::string_view::npos) {
      fail(origin, line,
           std::string("unterminated quote (") + q + ") in value of '" + entry.key + "'");
    }
    entry.quote = q;
    entry.value = std::string(rest.substr(1, close - 1));
    const std::string_view after = host::text::trim_blanks(rest.substr(close + 1));
    if (!after.empty() && !is_comment_start(after.front())) {
      fail(origin, line,
           "unexpected text after closing quote in value of '" + entry.key + "': '" +
               host::text::excerpt(after) + "'");
    }
    entry.comment = std::string(after);
    return;
  }
  std::size_t end = 0;
  while (end < rest.size() && !is_comment_start(rest[end])) ++end;
  entry.value = std::string(host::text::trim_blanks(rest.substr(0, end)));
  entry.comment = std::string(host::text::trim_blanks(rest.substr(end)));
  if (entry.value.find_first_of("'\"") != std::string::npos) {
    fail(origin, line, "stray quote in value of '" + entry.key + "'");
  }
}

// The longest key or section name read (the Magic Formula's and Adams's are under 30 characters):
// every message that names one stays short.
constexpr std::size_t kMaxNameLength = 64;

// Matches `KEY = ...`; returns the key length or 0.
std::size_t match_key(std::string_view s) noexcept {
  if (s.empty() || !is_key_start(s.front())) return 0;
  std::size_t n = 1;
  while (n < s.size() && is_key_char(s[n])) ++n;
  std::size_t i = n;
  while (i < s.size() && is_space(s[i])) ++i;
  return (i < s.size() && s[i] == '=') ? n : 0;
}

template <typename Sections>
auto find_in(Sections& sections, std::string_view section, std::string_view key) noexcept
    -> decltype(sections.front().find(key)) {
  for (auto& s : sections) {
    if (!iequals(s.name, section)) continue;
    if (auto* e = s.find(key)) return e;
  }
  return nullptr;
}

void write_line(std::string& out, const Line& l, const std::string& eol) {
  if (l.kind == Line::Kind::kEntry) {
    out += l.entry.source.empty() ? entry_text(l.entry) : l.entry.source;
  } else {
    out += l.text;
  }
  out += eol;
}

// True for an Adams sub-block header such as `(COMMENTS)`.
bool is_block_header(std::string_view t) noexcept {
  if (t.size() < 3 || t.front() != '(' || t.back() != ')') return false;
  const std::string_view name = t.substr(1, t.size() - 2);
  return std::all_of(name.begin(), name.end(), is_key_char);
}

// True for the lines inside such a block: `{column names}` or a quoted text line.
bool is_block_body(std::string_view t) noexcept {
  if (t.empty()) return false;
  if (t.front() == '{') return t.find('}') != std::string_view::npos;
  if (t.front() == '\'' || t.front() == '"') {
    const std::size_t close = t.find(t.front(), 1);
    if (close == std::string_view::npos) return false;
    const std::string_view after = host::text::trim_blanks(t.substr(close + 1));
    return after.empty() || is_comment_start(after.front());
  }
  return false;
}

// `KEY =` with nothing (or only a comment) after the '='.
bool has_empty_value(std::string_view t) noexcept {
  const std::string_view rest = host::text::trim_blanks(t.substr(t.find('=') + 1));
  return rest.empty() || is_comment_start(rest.front());
}

}  // namespace

TirError::TirError(std::string file, int line, const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + message),
      file_(std::move(file)),
      line_(line) {}

std::string entry_text(const Entry& e, std::size_t key_width, bool with_comment) {
  std::string out = e.key;
  if (out.size() < key_width) out.append(key_width - out.size(), ' ');
  out += key_width > 0 ? "= " : " = ";
  if (e.is_quoted()) {
    out += e.quote;
    out += e.value;
    out += e.quote;
  } else {
    out += e.value;
  }
  if (with_comment && !e.comment.empty()) {
    out += "  ";
    out += e.comment;
  }
  return out;
}

bool iequals(std::string_view a, std::string_view b) noexcept {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return lower(x) == lower(y); });
}

std::optional<double> parse_number(std::string_view token) noexcept {
  token = host::text::trim_blanks(token);
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.size() > 64) return std::nullopt;
  // from_chars accepts "inf"/"nan" and hex-less decimal; we allow only digits, sign, '.', exponent.
  std::array<char, 64> buf{};
  std::size_t n = 0;
  for (const char c : token) {
    const bool ok = (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' ||
                    c == 'E' || c == 'd' || c == 'D';
    if (!ok) return std::nullopt;
    buf[n++] = (c == 'd' || c == 'D') ? 'e' : c;
  }
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(buf.data(), buf.data() + n, v);
  if (ec != std::errc() || ptr != buf.data() + n || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string format_number(double value) {
  std::array<char, 64> buf{};
  const auto [ptr, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  (void)ec;  // 64 characters always suffice for the shortest form of a double
  return std::string(buf.data(), ptr);
}

bool Section::is_table() const noexcept {
  return std::any_of(lines.begin(), lines.end(),
                     [](const Line& l) { return l.kind == Line::Kind::kTableRow; });
}

std::vector<std::string> Section::table_rows() const {
  std::vector<std::string> rows;
  for (const auto& l : lines) {
    if (l.kind == Line::Kind::kTableRow) rows.push_back(l.text);
  }
  return rows;
}

std::vector<const Entry*> Section::entries() const {
  std::vector<const Entry*> out;
  for (const auto& l : lines) {
    if (l.kind == Line::Kind::kEntry) out.push_back(&l.entry);
  }
  return out;
}

const Entry* Section::find(std::string_view key) const noexcept {
  for (const auto& l : lines) {
    if (l.kind == Line::Kind::kEntry && iequals(l.entry.key, key)) return &l.entry;
  }
  return nullptr;
}

Entry* Section::find(std::string_view key) noexcept {
  for (auto& l : lines) {
    if (l.kind == Line::Kind::kEntry && iequals(l.entry.key, key)) return &l.entry;
  }
  return nullptr;
}

const Section* TirFile::section(std::string_view name) const noexcept {
  for (const auto& s : sections_) {
    if (iequals(s.name, name)) return &s;
  }
  return nullptr;
}

const Entry* TirFile::find(std::string_view section, std::string_view key) const noexcept {
  return find_in(sections_, section, key);
}

const Entry* TirFile::find_any(std::string_view key) const noexcept {
  for (const auto& s : sections_) {
    if (const auto* e = s.find(key)) return e;
  }
  return nullptr;
}

namespace {

/// A table row of a .tir starts with its column header '{', a number or quoted text; a line
/// starting with a letter is a 'KEY = value' line gone wrong.
bool looks_like_table_row(std::string_view text) {
  const std::string_view t = host::text::trim_blanks(text);
  if (t.empty()) return true;
  const char c = t.front();
  return c == '{' || c == '\'' || c == '"' || c == '+' || c == '-' || c == '.' ||
         (c >= '0' && c <= '9');
}
std::optional<double> entry_number(const Entry* e, const std::string& origin) {
  if (e == nullptr) return std::nullopt;
  if (!e->is_quoted()) {
    if (const auto v = parse_number(e->value)) return v;
  }
  fail(origin, e->line,
       "value of '" + e->key + "' is not a number: " +
           host::text::excerpt(e->is_quoted() ? std::string(1, e->quote) + e->value + e->quote
                                              : e->value));
}
std::optional<std::string> entry_value(const Entry* e) {
  if (e == nullptr) return std::nullopt;
  return e->value;
}
}  // namespace

std::optional<double> TirFile::number(std::string_view section, std::string_view key) const {
  return entry_number(find(section, key), origin_);
}
std::optional<double> TirFile::number_any(std::string_view key) const {
  return entry_number(find_any(key), origin_);
}
std::optional<std::string> TirFile::text(std::string_view section, std::string_view key) const {
  return entry_value(find(section, key));
}
std::optional<std::string> TirFile::text_any(std::string_view key) const {
  return entry_value(find_any(key));
}

Entry& TirFile::upsert(std::string_view section, std::string_view key) {
  if (key.empty() || !is_key_start(key.front()) ||
      !std::all_of(key.begin(), key.end(), is_key_char)) {
    throw TirError(origin_, 0, "invalid key name '" + std::string(key) + "'");
  }
  if (Entry* e = find_in(sections_, section, key)) {
    e->source.clear();
    return *e;
  }
  // A `KEY =` line without a value becomes the entry (in place).
  for (auto& s : sections_) {
    if (!iequals(s.name, section)) continue;
    for (auto& l : s.lines) {
      if (l.kind == Line::Kind::kEmptyEntry && iequals(l.entry.key, key)) {
        l.kind = Line::Kind::kEntry;
        l.text.clear();
        l.entry.source.clear();
        return l.entry;
      }
    }
  }
  Section* target = nullptr;
  for (auto& s : sections_) {
    if (iequals(s.name, section)) target = &s;  // the last section of that name
  }
  if (target == nullptr) {
    Section s;
    s.name = std::string(section);
    sections_.push_back(std::move(s));
    target = &sections_.back();
  }
  if (target->is_table()) {
    throw TirError(
        origin_, target->line,
        "cannot add key '" + std::string(key) + "' to table section [" + target->name + "]");
  }
  // After the last entry, so trailing comment blocks (which usually head the next section) stay
  // put.
  auto pos = target->lines.begin();
  for (auto it = target->lines.begin(); it != target->lines.end(); ++it) {
    if (it->kind == Line::Kind::kEntry) pos = it + 1;
  }
  Line l;
  l.kind = Line::Kind::kEntry;
  l.entry.key = std::string(key);
  return target->lines.insert(pos, std::move(l))->entry;
}

void TirFile::set(std::string_view section, std::string_view key, double value) {
  if (!std::isfinite(value)) {
    throw TirError(origin_, 0, "refusing to set '" + std::string(key) + "' to a non-finite value");
  }
  Entry& e = upsert(section, key);
  e.value = format_number(value);
  e.quote = '\0';
}

void TirFile::set_text(std::string_view section, std::string_view key, std::string_view text) {
  const bool has_single = text.find('\'') != std::string_view::npos;
  const bool has_double = text.find('"') != std::string_view::npos;
  if (has_single && has_double) {
    throw TirError(origin_, 0, "text for '" + std::string(key) + "' contains both quote kinds");
  }
  if (text.find('\n') != std::string_view::npos || text.find('\r') != std::string_view::npos) {
    throw TirError(origin_, 0, "text for '" + std::string(key) + "' contains a line break");
  }
  Entry& e = upsert(section, key);
  e.value = std::string(text);
  e.quote = has_single ? '"' : '\'';
}

bool TirFile::erase(std::string_view section, std::string_view key) {
  for (auto& s : sections_) {
    if (!iequals(s.name, section)) continue;
    for (auto it = s.lines.begin(); it != s.lines.end(); ++it) {
      if (it->kind == Line::Kind::kEntry && iequals(it->entry.key, key)) {
        s.lines.erase(it);
        return true;
      }
    }
  }
  return false;
}

TirFile parse_tir(std::string_view text, const std::string& origin) {
  TirFile file(origin);
  // A UTF-8 byte-order mark (Windows editors write one): not part of the first line, which
  // otherwise read as "text outside any section: '[MDI_HEADER]'" with the mark invisible.
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  // Old Mac line ends (CR only): the whole file was one line.
  std::string cr_lines;
  if (text.find('\n') == std::string_view::npos && text.find('\r') != std::string_view::npos) {
    cr_lines.assign(text);
    std::replace(cr_lines.begin(), cr_lines.end(), '\r', '\n');
    text = cr_lines;
    file.add_warning(origin + ": lines end in CR only (old Mac text): read as line ends");
  }
  int line_no = 0;
  std::size_t pos = 0;
  Section* current = nullptr;
  bool in_block = false;  // inside a `(NAME)` sub-block of the current section
  {
    const std::size_t first_eol = text.find('\n');
    if (first_eol != std::string_view::npos && first_eol > 0 && text[first_eol - 1] == '\r') {
      file.set_line_ending("\r\n");
    }
  }
  struct Seen {
    std::string section;  // lower-cased
    std::string key;      // lower-cased
    int line;
    std::string section_name;  // as written
  };
  std::vector<Seen> seen;
  auto lowered = [](std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = lower(c);
    return out;
  };

  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view raw = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    while (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);  // CRLF (and stray CRs)
    const std::string_view t = host::text::trim_blanks(raw);

    const std::size_t klen = match_key(t);
    if (klen > kMaxNameLength) {
      fail(origin, line_no,
           "a key of " + std::to_string(klen) + " characters (a .tir key has at most " +
               std::to_string(kMaxNameLength) + "): '" + host::text::excerpt(t.substr(0, klen)) +
               "'");
    }
    Line l;
    l.line = line_no;
    l.text = std::string(raw);
    if (t.empty()) {
      l.kind = Line::Kind::kBlank;
    } else if (is_comment_start(t.front())) {
      l.kind = Line::Kind::kComment;
    } else if (t.front() == '[') {
      const std::size_t close = t.find(']');
      if (close == std::string_view::npos) fail(origin, line_no, "section header without ']'");
      const std::string_view name = host::text::trim_blanks(t.substr(1, close - 1));
      const std::string_view after = host::text::trim_blanks(t.substr(close + 1));
      if (name.empty()) fail(origin, line_no, "empty section name");
      if (name.size() > kMaxNameLength) {
        fail(origin, line_no,
             "a section name of " + std::to_string(name.size()) +
                 " characters (a .tir section name has at most " + std::to_string(kMaxNameLength) +
                 "): '" + host::text::excerpt(name) + "'");
      }
      if (!std::all_of(name.begin(), name.end(),
                       [](char c) { return is_key_char(c) || c == '-'; })) {
        fail(origin, line_no, "invalid section name '" + host::text::excerpt(name) + "'");
      }
      if (!after.empty() && !is_comment_start(after.front())) {
        fail(origin, line_no,
             "unexpected text after section header: '" + host::text::excerpt(after) + "'");
      }
      Section s;
      s.name = std::string(name);
      s.header = std::string(raw);
      s.line = line_no;
      file.sections().push_back(std::move(s));
      current = &file.sections().back();
      in_block = false;
      continue;
    } else if (current != nullptr && !current->is_table() &&
               (is_block_header(t) || (in_block && is_block_body(t)))) {
      l.kind = Line::Kind::kBlockText;
      in_block = true;
    } else if (klen != 0 && has_empty_value(t)) {
      l.kind = Line::Kind::kEmptyEntry;
      l.entry.key = std::string(t.substr(0, klen));
      l.entry.line = line_no;
      if (current == nullptr) {
        fail(origin, line_no, "key '" + l.entry.key + "' outside any section");
      }
      in_block = false;
      file.add_warning(origin + ":" + std::to_string(line_no) + ": '" + l.entry.key +
                       "' has no value: treated as absent");
    } else if (klen != 0) {
      in_block = false;
      l.kind = Line::Kind::kEntry;
      l.entry.key = std::string(t.substr(0, klen));
      l.entry.line = line_no;
      l.entry.source = std::string(raw);
      if (current == nullptr) {
        fail(origin, line_no, "key '" + l.entry.key + "' outside any section");
      }
      parse_value(t.substr(t.find('=') + 1), l.entry, origin, line_no);
      const std::string sec = lowered(current->name);
      const std::string key = lowered(l.entry.key);
      for (const auto& s : seen) {
        if (s.section == sec && s.key == key) {
          fail(origin, line_no,
               "duplicate key '" + l.entry.key + "' in [" + current->name + "] (first at line " +
                   std::to_string(s.line) + ")");
        }
      }
      for (const auto& s : seen) {
        // The same key in another section: a lookup by key alone (FNOMIN, UNLOADED_RADIUS, ...)
        // takes the first; said, as the two may differ.
        // [UNITS] names a unit per quantity (MASS = 'kg' beside [INERTIA] MASS): not a value.
        if (s.key == key && s.section != sec && s.section != "units" && sec != "units") {
          file.add_warning(origin + ":" + std::to_string(line_no) + ": '" + l.entry.key +
                           "' is also in [" + s.section_name + "] (line " + std::to_string(s.line) +
                           "): the first, line " + std::to_string(s.line) + ", is the one used");
          break;
        }
      }
      seen.push_back({sec, key, line_no, current->name});
    } else {
      l.kind = Line::Kind::kTableRow;
      if (current == nullptr) {
        fail(origin, line_no, "text outside any section: '" + host::text::excerpt(t) + "'");
      }
    }

    if (current == nullptr) {
      file.preamble().push_back(std::move(l));
      continue;
    }
    // A section is either key/value or table: reject mixing (usually a typo such as a missing '=').
    if (l.kind == Line::Kind::kEntry || l.kind == Line::Kind::kTableRow) {
      const auto other = l.kind == Line::Kind::kEntry ? Line::Kind::kTableRow : Line::Kind::kEntry;
      if (l.kind == Line::Kind::kTableRow && in_block) {
        fail(origin, line_no,
             "line in sub-block is neither '{...}' nor quoted text in section [" + current->name +
                 "]: '" + host::text::excerpt(t) + "'");
      }
      for (const auto& prev : current->lines) {
        if (prev.kind == other && l.kind == Line::Kind::kEntry &&
            !looks_like_table_row(prev.text)) {
          // The section's first "row" is a word and a value: a 'KEY = value' line missing its '='
          // (MF files have no table whose rows start with a name). Point at it, not at the
          // well-formed entries after it.
          fail(origin, prev.line,
               "line is neither 'KEY = value' nor a comment in section [" + current->name +
                   "] (a missing '='? entries follow at line " + std::to_string(line_no) + "): '" +
                   host::text::excerpt(host::text::trim_blanks(prev.text)) + "'");
        }
        if (prev.kind == other) {
          fail(origin, line_no,
               l.kind == Line::Kind::kEntry
                   ? "'KEY = value' line in table section [" + current->name + "]"
                   : "line is neither 'KEY = value' nor a comment in section [" + current->name +
                         "] (first entry at line " + std::to_string(prev.line) + "): '" +
                         host::text::excerpt(t) + "'");
        }
      }
    }
    current->lines.push_back(std::move(l));
  }
  return file;
}

TirFile read_tir(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TirError(path.string(), 0, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw TirError(path.string(), 0, "read error");
  return parse_tir(ss.str(), path.string());
}

std::string write_tir(const TirFile& file) {
  std::string out;
  const std::string& eol = file.line_ending();
  for (const auto& l : file.preamble()) write_line(out, l, eol);
  for (const auto& s : file.sections()) {
    out += s.header.empty() ? "[" + s.name + "]" : s.header;
    out += eol;
    for (const auto& l : s.lines) write_line(out, l, eol);
  }
  return out;
}

void write_tir(const TirFile& file, const std::filesystem::path& path) {
  const std::string text = write_tir(file);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw TirError(path.string(), 0, "cannot open file for writing");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw TirError(path.string(), 0, "write error");
}

std::string ResolvedValues::warning(const std::string& origin) const {
  if (missing.empty()) return {};
  std::string out = origin + ": " + std::to_string(missing.size()) + " key" +
                    (missing.size() == 1 ? "" : "s") + " missing, defaults used: ";
  // A file with next to nothing in it would list some 200 keys on one line: the first few, and
  // where to see the rest.
  constexpr std::size_t kListed = 12;
  for (std::size_t i = 0; i < missing.size() && i < kListed; ++i) {
    if (i != 0) out += ", ";
    out += missing[i];
  }
  if (missing.size() > kListed) {
    out += " … and " + std::to_string(missing.size() - kListed) +
           " more ('tread tir info' lists them all)";
  }
  return out;
}

ResolvedValues resolve_numbers(const TirFile& file, std::span<const KeyDefault> keys) {
  ResolvedValues r;
  r.values.reserve(keys.size());
  for (const auto& k : keys) {
    const auto v = k.section.empty() ? file.number_any(k.key) : file.number(k.section, k.key);
    if (v) {
      r.values.push_back(*v);
    } else {
      r.values.push_back(k.value);
      r.missing.push_back(k.section.empty() ? std::string(k.key)
                                            : std::string(k.section) + "." + std::string(k.key));
    }
  }
  return r;
}

}  // namespace tread::tir
