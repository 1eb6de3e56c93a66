#pragma once
// Each subcommand of `tread` lives in its own file `sim/cli/<name>_command.cpp` and registers
// itself with TREAD_REGISTER_COMMAND; main() adds every registered command to the CLI11 app. Adding
// a command touches no shared file.

#include <CLI/CLI.hpp>

namespace tread::cli {

using AddCommand = void (*)(CLI::App& app);

/// Registers a subcommand adder; returns true so it can initialise a namespace-scope constant.
bool register_command(const char* name, AddCommand add);

/// Adds every registered subcommand to `app`, in name order.
void add_registered_commands(CLI::App& app);

}  // namespace tread::cli

#define TREAD_REGISTER_COMMAND(name, function)                     \
  [[maybe_unused]] static const bool tread_registered_##function = \
      ::tread::cli::register_command(name, function)
