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

ReplaceFile::ReplaceFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporary_beside(target_)) {
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(target_.string() + ": cannot write");
}

ReplaceFile::~ReplaceFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void ReplaceFile::commit() {
  out_.close();
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
