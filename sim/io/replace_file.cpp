#include "io/replace_file.hpp"

#include <atomic>
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

namespace tread::host {

namespace {

std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path t = target;
  t += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return t;
}

}  // namespace

ReplaceFile::ReplaceFile(std::filesystem::path target) : target_(std::move(target)) {
  // A target that exists and is not a regular file (/dev/stdout, a pipe) is written directly:
  // there is nothing to replace, and no temporary can be made beside it.
  std::error_code ec;
  const auto type = std::filesystem::status(target_, ec).type();
  direct_ = !ec && type != std::filesystem::file_type::not_found &&
            type != std::filesystem::file_type::regular;
  temporary_ = direct_ ? target_ : temporary_beside(target_);
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(target_.string() + ": cannot write");
}

ReplaceFile::~ReplaceFile() {
  if (committed_ || direct_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void ReplaceFile::commit() {
  out_.close();
  if (direct_) {
    if (!out_) throw std::runtime_error(target_.string() + ": write failed");
    committed_ = true;
    return;
  }
  if (!out_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw std::runtime_error(target_.string() + ": write failed");
  }
  std::error_code ec;
  std::filesystem::rename(temporary_, target_, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw std::runtime_error(target_.string() + ": cannot replace: " + ec.message());
  }
  committed_ = true;
}

}  // namespace tread::host
