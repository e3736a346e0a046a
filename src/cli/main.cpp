// The `bestiary` command: one binary, one subcommand per task.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.h"

namespace bx {

int fail(const std::string& message) {
  std::fprintf(stderr, "bestiary: %s\n", message.c_str());
  return 2;
}

namespace {
std::string g_program = "bestiary";
}

const std::string& program() { return g_program; }

void set_program(const char* argv0) {
  // as run: a path stays a path; a bare name was found on PATH
  if (argv0 && *argv0) g_program = argv0;
}

Status make_parent_dir(const std::string& flag, const std::string& path) {
  namespace fs = std::filesystem;
  auto dir = fs::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty()) fs::create_directories(dir, ec);
  if (ec || (!dir.empty() && !fs::is_directory(dir)))
    return Error{flag + ": cannot create directory \"" + dir.string() + "\"" + (ec ? " (" + ec.message() + ")" : "")};
  return Ok{};
}

}  // namespace bx

int main(int argc, char** argv) {
  bx::set_program(argc > 0 ? argv[0] : nullptr);
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
