#pragma once
// Plots through gnuplot (Debian gnuplot-nox): the tools write their data to files and a script to a
// gnuplot pipe. One place for starting gnuplot, quoting and error reporting.

#include <filesystem>
#include <string>

namespace tread::host {

/// Runs `script` through gnuplot; throws std::runtime_error naming `what` if gnuplot cannot start
/// or reports failure.
void run_gnuplot(const std::string& script, const std::string& what);

/// run_gnuplot, then removes `data_file` (the plot's data), also when gnuplot fails.
void run_gnuplot_with_data(const std::string& script, const std::string& what,
                           const std::filesystem::path& data_file);

/// printf-style formatting of a gnuplot script.
std::string format_script(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// A gnuplot single-quoted string literal ('it''s').
std::string gnuplot_quote(const std::string& text);

/// "pngcairo" or "svg" terminal line for `path` (by its extension), with the given pixel size.
std::string gnuplot_terminal(const std::string& path, int width, int height);

}  // namespace tread::host
