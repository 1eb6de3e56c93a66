#include "io/line_chunks.hpp"

#include <cstring>
#include <stdexcept>
#include <utility>

namespace tread::host {

namespace {

constexpr std::size_t kReadBytes = 64 * 1024;

// Position after the n-th '\n' of `text` from `from` (counting `seen` already), or npos with
// `seen` updated to the newlines found; the position of each newline found is added to `ends`.
std::size_t after_newline(const std::string& text, std::size_t from, std::size_t n,
                          std::size_t& seen, std::vector<std::size_t>& ends) {
  const char* const begin = text.data();
  const char* p = begin + from;
  const char* const end = begin + text.size();
  while (seen < n) {
    const void* hit = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (hit == nullptr) return std::string::npos;
    p = static_cast<const char*>(hit);
    ends.push_back(static_cast<std::size_t>(p - begin));
    ++p;
    ++seen;
  }
  return static_cast<std::size_t>(p - begin);
}

}  // namespace

LineChunker::LineChunker(std::istream& in, std::string name, std::size_t lines_per_chunk,
                         int next_line, std::string pending)
    : in_(in),
      name_(std::move(name)),
      lines_per_chunk_(lines_per_chunk == 0 ? 1 : lines_per_chunk),
      next_line_(next_line),
      carry_(std::move(pending)) {}

bool LineChunker::next(LineChunk& chunk) {
  std::string& text = chunk.text;
  text.assign(carry_);
  carry_.clear();
  chunk.ends.clear();
  std::size_t seen = 0;
  std::size_t scanned = 0;
  std::size_t cut = after_newline(text, scanned, lines_per_chunk_, seen, chunk.ends);
  while (cut == std::string::npos && !eof_) {
    scanned = text.size();
    text.resize(scanned + kReadBytes);
    in_.read(text.data() + scanned, static_cast<std::streamsize>(kReadBytes));
    const auto got = static_cast<std::size_t>(in_.gcount());
    text.resize(scanned + got);
    if (got < kReadBytes) {
      if (in_.bad()) throw std::runtime_error(name_ + ": read error");
      eof_ = true;
    }
    cut = after_newline(text, scanned, lines_per_chunk_, seen, chunk.ends);
  }
  if (cut != std::string::npos && cut < text.size()) {
    carry_.assign(text, cut, std::string::npos);
    text.resize(cut);
  }
  if (text.empty()) return false;
  std::size_t lines = seen;
  if (text.back() != '\n') {  // the stream's last line, without a '\n'
    ++lines;
    chunk.ends.push_back(text.size());
  }
  chunk.first_line = next_line_;
  chunk.lines = lines;
  next_line_ += static_cast<int>(lines);
  bytes_ += text.size();
  return true;
}

}  // namespace tread::host
