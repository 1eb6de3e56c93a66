#pragma once
// A text stream cut into chunks of whole lines (host side), each with the number of its first
// line, for processing a large file a chunk at a time (sim/io/ordered_pipeline.hpp): memory in
// proportion to the chunk, not the file.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace tread::host {

/// Whole lines of a stream, '\n' after each (the stream's last line may lack it).
struct LineChunk {
  std::string text;
  int first_line = 0;     ///< line number of the first line of `text` (1-based)
  std::size_t lines = 0;  ///< lines in `text`
  /// Where each line ends in `text` (its '\n', or text.size() for a last line without one), as
  /// LineChunker found them; empty in a chunk made otherwise.
  std::vector<std::size_t> ends;
};

/// Calls `f(line, number)` for each line of `chunk`, without its '\n'.
template <typename F>
void for_each_line(const LineChunk& chunk, F&& f) {
  const std::string_view text = chunk.text;
  std::size_t start = 0;
  int number = chunk.first_line;
  if (!chunk.ends.empty()) {  // the lines as the chunker found them: no second search
    for (const std::size_t end : chunk.ends) {
      f(text.substr(start, end - start), number++);
      start = end + 1;
    }
    return;
  }
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    f(text.substr(start, end - start), number++);
    start = end + 1;
  }
}

class LineChunker {
 public:
  /// Reads `in` (called `name` in messages) from where it stands. `next_line` numbers its first
  /// line; `pending` is text already taken from the stream that comes first (whole lines, each
  /// ending in '\n').
  LineChunker(std::istream& in, std::string name, std::size_t lines_per_chunk, int next_line,
              std::string pending = {});

  /// Fills `chunk` with the next lines (up to lines_per_chunk); false at the end of the input.
  /// `chunk.text`'s buffer is reused. Throws std::runtime_error ("name: read error") if the
  /// stream fails.
  bool next(LineChunk& chunk);

  /// Bytes handed out in chunks so far.
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::istream& in_;
  std::string name_;
  std::size_t lines_per_chunk_;
  int next_line_;
  std::string carry_;  ///< read from the stream, not yet handed out
  bool eof_ = false;
  std::uint64_t bytes_ = 0;
};

}  // namespace tread::host
