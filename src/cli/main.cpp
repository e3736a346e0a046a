// The `bestiary` command: one binary, one subcommand per task.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "cli/commands.h"

namespace bx {

int fail(const std::string& message) {
  std::fprintf(stderr, "bestiary: %s\n", message.c_str());
  return 2;
}

}  // namespace bx

int main(int argc, char** argv) {
  CLI::App app{"Bestiary: evolve virtual creatures, bodies and brains together, in 3D physics"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(BESTIARY_VERSION) + " (" + BESTIARY_GIT + ")");
  bx::add_simulate_commands(app);
  bx::add_evolve_commands(app);
  bx::add_watch_commands(app);
  bx::add_check_command(app);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
