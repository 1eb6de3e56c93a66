// The fuzz targets without libFuzzer: runs LLVMFuzzerTestOneInput on every file named on the
// command line or found (recursively) in a directory named there — the seed corpus and the crash
// inputs kept in tests/fuzz/regressions — so they are regression tests in every build (ctest label
// unit). A broken invariant aborts, naming the file first.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_support.hpp"

namespace {

int run_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "fuzz replay: cannot read %s\n", path.c_str());
    return 1;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  std::fprintf(stderr, "fuzz replay: %s\n", path.c_str());
  static_cast<void>(
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t files = 0;
  int failed = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg(argv[i]);
    if (std::filesystem::is_directory(arg)) {
      std::vector<std::filesystem::path> paths;
      for (const auto& e : std::filesystem::recursive_directory_iterator(arg)) {
        if (e.is_regular_file() && e.path().filename().string().front() != '.' &&
            e.path().filename() != "README.md") {
          paths.push_back(e.path());
        }
      }
      std::sort(paths.begin(), paths.end());
      for (const auto& p : paths) {
        failed += run_file(p);
        ++files;
      }
    } else if (std::filesystem::exists(arg)) {
      failed += run_file(arg);
      ++files;
    } else {
      std::fprintf(stderr, "fuzz replay: %s does not exist\n", argv[i]);
      ++failed;
    }
  }
  if (failed != 0 || files == 0) {
    std::printf("fuzz replay: %zu inputs replayed, %d paths missing or unreadable\n", files,
                failed);
    return 1;
  }
  std::printf("fuzz replay: %zu inputs, every invariant held\n", files);
  return 0;
}
