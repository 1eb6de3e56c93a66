#include "plot/gnuplot.hpp"

#include <sys/wait.h>

#include <csignal>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace tread::host {

void run_gnuplot(const std::string& script, const std::string& what) {
  // gnuplot's messages go to tread's stderr; its standard output, where it writes the image when
  // `set output` could not open the file, goes nowhere (it was dumped onto tread's stdout).
  // SIGPIPE is ignored while the script is written: a gnuplot that is missing or exits early
  // killed tread (exit 141) instead of giving this error.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  struct sigaction previous {};
  sigaction(SIGPIPE, &ignore, &previous);
  FILE* pipe = popen("exec gnuplot >/dev/null", "w");
  if (pipe == nullptr) {
    sigaction(SIGPIPE, &previous, nullptr);
    throw std::runtime_error(what + ": cannot start gnuplot (scripts/install-deps.sh installs it)");
  }
  std::fwrite(script.data(), 1, script.size(), pipe);
  const int status = pclose(pipe);
  sigaction(SIGPIPE, &previous, nullptr);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    throw std::runtime_error(what +
                             ": gnuplot is not installed, or not on PATH "
                             "(scripts/install-deps.sh installs it)");
  }
  if (status != 0) {
    throw std::runtime_error(what + ": gnuplot failed (status " + std::to_string(status) +
                             "; its message is above)");
  }
}

void run_gnuplot_with_data(const std::string& script, const std::string& what,
                           const std::filesystem::path& data_file) {
  try {
    run_gnuplot(script, what);
  } catch (...) {
    std::filesystem::remove(data_file);
    throw;
  }
  std::filesystem::remove(data_file);
}

std::string format_script(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0U, '\0');
  if (n > 0) {
    std::vsnprintf(out.data(), out.size() + 1U, format, args);
  }
  va_end(args);
  return out;
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
