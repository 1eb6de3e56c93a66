#include "node/candump_log.hpp"

#include <fstream>
#include <stdexcept>

namespace tread::host {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::runtime_error(where + ": " + what);
}

}  // namespace

LoggedFrame parse_candump_line(std::string_view line, const std::string& where) {
  proto::CandumpLine parsed;
  const proto::CandumpError error = proto::parse_candump_line(line, parsed);
  if (error == proto::CandumpError::bad_data_length) {
    fail(where, std::string(proto::describe(error)) + " " + std::to_string(parsed.data_len));
  }
  if (error != proto::CandumpError::none) {
    fail(where, proto::describe(error));
  }
  return LoggedFrame{parsed.time_ns, std::string(parsed.interface), parsed.frame};
}

std::vector<LoggedFrame> read_candump_log(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error(path.string() + ": cannot open");
  }
  std::vector<LoggedFrame> frames;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    frames.push_back(parse_candump_line(line, path.string() + ":" + std::to_string(line_no)));
  }
  return frames;
}

CandumpWriter::~CandumpWriter() {
  close();
}

void CandumpWriter::open(const std::filesystem::path& path, std::string interface) {
  close();
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw std::runtime_error(path.string() + ": cannot open for writing");
  }
  buffer_.assign(1U << 20U, '\0');
  std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
  interface_ = std::move(interface);
}

void CandumpWriter::write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
  if (file_ == nullptr) return;
  char line[kCandumpLineMax + 2];
  const std::size_t n = format_candump_line(frame, time_ns, interface_, line);
  line[n] = '\n';
  std::fwrite(line, 1, n + 1, file_);
}

void CandumpWriter::close() noexcept {
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
}

}  // namespace tread::host
