#pragma once
// Where a command reads and writes its table (host side: throws): a file, or standard input and
// output for "-" (the Unix convention; a file named "-" was written before).

#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/replace_file.hpp"

namespace tread::host {

/// A table's input: the file `path`, or standard input for "-" (named "<stdin>" in messages).
class TableInput {
 public:
  explicit TableInput(const std::string& path)
      : stdin_(path == "-"), name_(stdin_ ? std::string("<stdin>") : path) {
    if (!stdin_) {
      file_.open(path, std::ios::binary);
      if (!file_) throw std::runtime_error(path + ": cannot open");
    }
  }
  std::istream& stream() { return stdin_ ? std::cin : file_; }
  const std::string& name() const { return name_; }
  bool is_stdin() const { return stdin_; }

 private:
  bool stdin_;
  std::string name_;
  std::ifstream file_;
};

/// A table's output: the file `path`, written whole or not at all (ReplaceFile), or standard
/// output for "-".
class TableOutput {
 public:
  explicit TableOutput(const std::string& path) {
    if (path != "-") file_.emplace(path);
  }
  std::ostream& stream() { return file_ ? file_->stream() : std::cout; }
  bool is_stdout() const { return !file_; }
  /// Renames the file over its target, or flushes standard output; throws std::runtime_error if
  /// a write failed.
  void commit() {
    if (file_) {
      file_->commit();
      return;
    }
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("standard output: cannot write");
  }

 private:
  std::optional<ReplaceFile> file_;
};

}  // namespace tread::host
