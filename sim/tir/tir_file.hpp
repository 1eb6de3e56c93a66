#pragma once
// TNO / Adams tyre property files (.tir): reader, writer and lookups. Host side (allocates,
// throws).
//
// Grammar accepted by read_tir()/parse_tir():
//   - `[NAME]` starts a section (optionally followed by a comment). Sections may come in any
//     order and the same name may appear more than once (Chrono's FEDA file repeats
//     [DEFLECTION_LOAD_CURVE]); lookups search every section of that name in file order.
//   - `KEY = value` with KEY = [A-Za-z_][A-Za-z0-9_]*; value is a quoted string ('...' or "...", no
//     escapes) or an unquoted token (number, or bare word) up to the comment/end of line.
//   - Comments start with `$` or `!` (whole line or trailing, outside quotes).
//   - Adams sub-blocks in key/value sections (e.g. [MDI_HEADER]): a `(NAME)` line such as
//     `(COMMENTS)` starts a block whose following `{column names}` and quoted-text lines ('...')
//     are kept verbatim for the round trip and carry no values (Line::Kind::kBlockText). The block
//     ends at the next `KEY = value` line or section.
//   - `KEY =` with nothing after the '=' (some exporters write it) is kept verbatim but treated as
//     absent: lookups do not see it and warnings() names it with file:line.
//   - Table sections ([SHAPE], [DEFLECTION_LOAD_CURVE], ...): lines that are not `KEY = value`
//     (e.g. `{pen fz}` or rows of numbers) are kept verbatim as table rows. A section is either a
//     key/value section or a table section: mixing the two in one section is an error.
//   - Lines may end in CRLF; trailing CRs are dropped, and the file remembers its line ending (that
//     of its first line) for the writer.
//   - Section names and keys are looked up case-insensitively (ASCII); they are kept as written.
// Errors (TirError, message `file:line: what`):
//   - unterminated quote, text after a closing quote, a malformed section header, a key (or table
//     row) before the first section;
//   - a duplicate key within sections of the same name (the message names both lines) — the files
//     give no rule for which one would win, so we refuse instead of guessing;
//   - number(): the key exists but its value is not a finite number (quoted text, bare word,
//   NaN...).
// Round trip: write_tir(read_tir(f)) reproduces every line of f verbatim with the file's line
// ending (LF or CRLF; a missing final newline is added); entries
// changed with set() are written as `KEY = value` with the shortest text that reads back to the
// same double, keeping their trailing comment.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tread::tir {

/// Bad input: what() is `file:line: message`.
class TirError : public std::runtime_error {
 public:
  TirError(std::string file, int line, const std::string& message);
  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }

 private:
  std::string file_;
  int line_;
};

/// One `KEY = value` line.
struct Entry {
  std::string key;      ///< as written
  std::string value;    ///< unquoted content for quoted strings; the token otherwise
  char quote = '\0';    ///< '\'' or '"' for quoted strings, '\0' for unquoted values
  std::string comment;  ///< trailing comment including its `$`/`!` marker, or empty
  int line = 0;         ///< 1-based source line; 0 for entries added with set()
  std::string source;   ///< the verbatim source line; cleared when the entry is modified

  bool is_quoted() const noexcept { return quote != '\0'; }
};

/// A line of a section body (or of the preamble before the first section).
struct Line {
  /// kBlockText: a `(NAME)` sub-block line or a `{...}` / quoted line inside one (no values).
  /// kEmptyEntry: `KEY =` without a value, treated as absent (Line::entry.key holds the key).
  enum class Kind { kBlank, kComment, kEntry, kTableRow, kBlockText, kEmptyEntry };
  Kind kind = Kind::kBlank;
  std::string text;  ///< verbatim text (all kinds but kEntry); unused for kEntry
  int line = 0;      ///< 1-based source line; 0 for added lines
  Entry entry;       ///< valid for kEntry
};

struct Section {
  std::string name;    ///< as written, without brackets
  std::string header;  ///< verbatim header line (e.g. "[SHAPE]  $ comment"); empty if added
  int line = 0;
  std::vector<Line> lines;

  /// True if the section holds table rows instead of `KEY = value` entries.
  bool is_table() const noexcept;
  /// The table rows (including `{...}` column headers), verbatim.
  std::vector<std::string> table_rows() const;
  /// The entries in file order.
  std::vector<const Entry*> entries() const;
  const Entry* find(std::string_view key) const noexcept;  ///< case-insensitive
  Entry* find(std::string_view key) noexcept;
};

/// A parsed property file. Keeps everything needed to write it back unchanged.
class TirFile {
 public:
  TirFile() = default;
  explicit TirFile(std::string origin) : origin_(std::move(origin)) {}

  /// File name used in error messages.
  const std::string& origin() const noexcept { return origin_; }

  const std::vector<Line>& preamble() const noexcept { return preamble_; }
  const std::vector<Section>& sections() const noexcept { return sections_; }
  std::vector<Line>& preamble() noexcept { return preamble_; }
  std::vector<Section>& sections() noexcept { return sections_; }

  /// "\n" or "\r\n": the line ending the writer uses (that of the file's first line when read).
  const std::string& line_ending() const noexcept { return line_ending_; }
  void set_line_ending(std::string ending) { line_ending_ = std::move(ending); }

  /// Things worth telling the user that are not errors, each `file:line: message` (e.g. a key
  /// without a value, treated as absent).
  const std::vector<std::string>& warnings() const noexcept { return warnings_; }
  void add_warning(std::string warning) { warnings_.push_back(std::move(warning)); }

  /// First section of that name (case-insensitive), or nullptr.
  const Section* section(std::string_view name) const noexcept;

  /// The entry in any section named `section` (case-insensitive), or nullptr.
  const Entry* find(std::string_view section, std::string_view key) const noexcept;
  /// The first entry with that key in any section (file order), or nullptr. Many tools look keys up
  /// globally; TNO key names are unique across the standard sections.
  const Entry* find_any(std::string_view key) const noexcept;

  /// nullopt if the key is missing; throws TirError (file:line) if present but not a finite number.
  std::optional<double> number(std::string_view section, std::string_view key) const;
  std::optional<double> number_any(std::string_view key) const;
  /// The value as text (quoted content without quotes, or the token), nullopt if missing.
  std::optional<std::string> text(std::string_view section, std::string_view key) const;
  std::optional<std::string> text_any(std::string_view key) const;

  /// Set a numeric value; creates the section (at the end) and/or key (after the section's last
  /// entry) if missing. The value is written in shortest round-trip form.
  void set(std::string_view section, std::string_view key, double value);
  /// Set a quoted text value (written with single quotes unless `text` contains one).
  void set_text(std::string_view section, std::string_view key, std::string_view text);
  /// Remove a key; returns false if it was not there.
  bool erase(std::string_view section, std::string_view key);

 private:
  Entry& upsert(std::string_view section, std::string_view key);

  std::string origin_;
  std::string line_ending_ = "\n";
  std::vector<std::string> warnings_;
  std::vector<Line> preamble_;
  std::vector<Section> sections_;
};

/// Parse text; `origin` names the source in error messages.
TirFile parse_tir(std::string_view text, const std::string& origin);
/// Read and parse a file. Throws TirError (also when the file cannot be opened: line 0).
TirFile read_tir(const std::filesystem::path& path);

/// Serialise (see the round-trip note at the top).
std::string write_tir(const TirFile& file);
/// Write to a file; throws TirError if it cannot be written.
void write_tir(const TirFile& file, const std::filesystem::path& path);

/// Parse a .tir number token: decimal with optional sign and exponent (`e`, `E` and Fortran `d`,
/// `D`). nullopt if the token is not a finite number.
std::optional<double> parse_number(std::string_view token) noexcept;
/// Shortest text that parses back to exactly `value`.
std::string format_number(double value);

/// `KEY = value  $comment` as the writer prints a changed entry; with `key_width` > 0 the key is
/// padded to that width before `= ` (the normalised layout), and `with_comment` = false leaves the
/// comment out.
std::string entry_text(const Entry& entry, std::size_t key_width = 0, bool with_comment = true);

/// ASCII case-insensitive equality, as used for section and key lookups.
bool iequals(std::string_view a, std::string_view b) noexcept;

/// A key with its documented default. An empty section means "look the key up in any section".
struct KeyDefault {
  std::string_view section;
  std::string_view key;
  double value;
};

struct ResolvedValues {
  std::vector<double> values;  ///< one per KeyDefault, in order: the file's value or the default
  std::vector<std::string> missing;  ///< "SECTION.KEY" (or "KEY") of each key that took its default
  /// Empty if nothing was missing, else "file: N keys missing, defaults used: A.B, C.D, ..."
  /// (the first 12 keys, then how many more).
  std::string warning(const std::string& origin) const;
};

/// Look up each key; missing keys take their default and are listed. Present keys whose value is
/// not a number throw TirError (file:line).
ResolvedValues resolve_numbers(const TirFile& file, std::span<const KeyDefault> keys);

}  // namespace tread::tir
