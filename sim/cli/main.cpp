// tread: the host command line (evaluation, profiles, contact, node, rig, demo, fit).
#include <iostream>

#include "cli/commands.hpp"
#include "host_info.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tread — real-time Magic Formula tyre and wheel–rail contact core, host tools"};
  app.require_subcommand(1);
  app.set_version_flag("--version", tread::host::version_string());
  tread::cli::add_registered_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "tread: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
