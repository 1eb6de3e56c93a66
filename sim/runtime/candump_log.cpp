#include "runtime/candump_log.hpp"

#include <cerrno>
#include <cstring>
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
  abandon();
}

void CandumpWriter::open(const std::filesystem::path& path, std::string interface) {
  abandon();
  path_ = path;
  std::error_code ec;
  const bool special =
      std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec);
  partial_ = special ? path : std::filesystem::path(path.string() + ".partial");
  file_ = std::fopen(partial_.c_str(), "w");
  if (file_ == nullptr) {
    throw std::runtime_error(path.string() + ": cannot open for writing (" + std::strerror(errno) +
                             (special ? "" : ", as " + partial_.string()) + ")");
  }
  if (!special) {
    // An older log under this name is not this run's: gone now, as opening it for writing would
    // have truncated it, so a failed run cannot leave it standing as if complete; so is an older
    // run's incomplete one, which would otherwise stand beside this run's log.
    std::filesystem::remove(path, ec);
    std::filesystem::remove(path.string() + ".incomplete", ec);
  }
  buffer_.assign(1U << 20U, '\0');
  std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
  interface_ = std::move(interface);
  errno_ = 0;
}

void CandumpWriter::write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
  if (file_ == nullptr) return;
  if (errno_ != 0) {
    return;
  }
  char line[kCandumpLineMax + 2];
  const std::size_t n = format_candump_line(frame, time_ns, interface_, line);
  line[n] = '\n';
  errno = 0;
  if (std::fwrite(line, 1, n + 1, file_) != n + 1) {
    errno_ = errno != 0 ? errno : EIO;
  }
}

std::string CandumpWriter::finish(std::uint64_t dropped_frames) {
  if (file_ == nullptr) return "";
  errno = 0;
  if (std::fflush(file_) != 0 && errno_ == 0) {
    errno_ = errno != 0 ? errno : EIO;
  }
  if (std::fclose(file_) != 0 && errno_ == 0) {
    errno_ = errno != 0 ? errno : EIO;
  }
  file_ = nullptr;
  const std::string dropped =
      dropped_frames == 0 ? ""
                          : std::to_string(dropped_frames) +
                                " frames were not logged (the log ring was full): the log is not "
                                "complete";
  const std::string also_dropped = dropped.empty() ? "" : "; " + dropped;
  if (partial_ == path_) {  // written directly (not a regular file)
    if (errno_ != 0) {
      return path_.string() + ": writing the log failed (" + std::strerror(errno_) + ")" +
             also_dropped;
    }
    return dropped.empty() ? "" : path_.string() + ": " + dropped;
  }
  std::error_code ec;
  if (errno_ == 0 && dropped.empty()) {
    std::filesystem::rename(partial_, path_, ec);
    if (!ec) return "";
    return partial_.string() + ": the log is complete but could not be renamed to " +
           path_.string() + " (" + ec.message() + ")";
  }
  const std::filesystem::path incomplete(path_.string() + ".incomplete");
  std::filesystem::rename(partial_, incomplete, ec);
  const std::filesystem::path kept = ec ? partial_ : incomplete;
  if (errno_ == 0) {
    return path_.string() + ": " + dropped + "; the frames that were logged are in " +
           kept.string() + ", not claimed as the log";
  }
  const std::uintmax_t bytes = std::filesystem::file_size(kept, ec);
  return path_.string() + ": writing the log failed (" + std::strerror(errno_) + ")" +
         also_dropped + "; the " + (ec ? std::string("?") : std::to_string(bytes)) +
         " bytes that reached the disk (the last line may be cut short) are in " + kept.string() +
         ", not claimed as the log";
}

void CandumpWriter::abandon() noexcept {
  if (file_ == nullptr) return;
  std::fclose(file_);
  file_ = nullptr;
  if (partial_ != path_) {
    std::error_code ec;
    std::filesystem::rename(partial_, path_.string() + ".incomplete", ec);
  }
}

}  // namespace tread::host
