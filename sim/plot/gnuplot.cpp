#include "plot/gnuplot.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace tread::host {

void run_gnuplot(const std::string& script, const std::string& what) {
  FILE* pipe = popen("gnuplot 2>&1", "w");
  if (pipe == nullptr) {
    throw std::runtime_error(what + ": cannot start gnuplot (scripts/install-deps.sh installs it)");
  }
  std::fwrite(script.data(), 1, script.size(), pipe);
  const int status = pclose(pipe);
  if (status != 0) {
    throw std::runtime_error(what + ": gnuplot failed (status " + std::to_string(status) + ")");
  }
}

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    out += c;
    if (c == '\'') {
      out += '\'';
    }
  }
  return out + "'";
}

std::string gnuplot_terminal(const std::string& path, int width, int height) {
  const std::string ext = std::filesystem::path(path).extension().string();
  const std::string size = std::to_string(width) + "," + std::to_string(height);
  if (ext == ".svg") {
    return "set terminal svg size " + size + " dynamic background rgb 'white'\n";
  }
  return "set terminal pngcairo size " + size + "\n";
}

}  // namespace tread::host
