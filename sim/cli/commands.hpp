#pragma once
// Each subcommand of `tread` registers itself on the CLI11 app; one file per subcommand.

#include <CLI/CLI.hpp>

namespace tread::cli {

void add_demo_command(CLI::App& app);

}  // namespace tread::cli
