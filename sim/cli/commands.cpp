#include "cli/commands.hpp"

#include <map>
#include <string>

namespace tread::cli {
namespace {

std::map<std::string, AddCommand>& registry() {
  static std::map<std::string, AddCommand> commands;
  return commands;
}

}  // namespace

bool register_command(const char* name, AddCommand add) {
  registry().emplace(name, add);
  return true;
}

void add_registered_commands(CLI::App& app) {
  for (const auto& [name, add] : registry()) {
    add(app);
  }
}

}  // namespace tread::cli
