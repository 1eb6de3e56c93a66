#pragma once
// An output file written whole or not at all (host side: throws).
//
// The text goes to a temporary file beside the target (same directory, so the final rename stays
// on one file system); commit() closes it and renames it over the target. Without commit() — an
// exception while writing, an early return — the destructor removes the temporary, and whatever
// was at the target before (an older output, or nothing) is left as it was. A target that exists
// and is not a regular file (/dev/stdout, a named pipe) is written directly instead.

#include <filesystem>
#include <fstream>

namespace tread::host {

class ReplaceFile {
 public:
  /// Opens the temporary beside `target`; throws std::runtime_error if it cannot be created.
  explicit ReplaceFile(std::filesystem::path target);
  ~ReplaceFile();
  ReplaceFile(const ReplaceFile&) = delete;
  ReplaceFile& operator=(const ReplaceFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::filesystem::path& temporary() const { return temporary_; }

  /// Flushes, checks every write succeeded and renames the temporary over the target; throws
  /// std::runtime_error (the temporary removed, the target untouched) otherwise.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool committed_ = false;
  bool direct_ = false;  ///< the target is not a regular file: written in place
};

}  // namespace tread::host
