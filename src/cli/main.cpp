// The `bestiary` command: one binary, one subcommand per task.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <algorithm>
#include <charconv>
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "cluster/mpi_evaluator.h"
#include "core/text.h"
#include "core/version.h"

namespace bx {

int fail(const std::string& message) {
  // one line whatever the input quoted in it (a newline in a value, a huge key)
  std::fprintf(stderr, "bestiary: %s\n", one_line(message, 4000).c_str());
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

CLI::Validator whole_number(long long lo, unsigned long long hi) {
  std::string range = "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        bool ok = false;
        if (!text.empty() && text[0] == '-') {
          long long v = 0;
          auto r = std::from_chars(text.data(), text.data() + text.size(), v);
          ok = r.ec == std::errc() && r.ptr == text.data() + text.size() && v >= lo;
        } else {
          unsigned long long v = 0;
          auto r = std::from_chars(text.data(), text.data() + text.size(), v);
          ok = r.ec == std::errc() && r.ptr == text.data() + text.size() && v <= hi &&
               (lo <= 0 || v >= static_cast<unsigned long long>(lo));
        }
        return ok ? "" : "expected " + range + ", got \"" + text + "\"";
      },
      range);
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
  // under mpirun with --evaluator mpi: rank 0 goes on with the command, the
  // other ranks evaluate for it until it ends (docs/cluster.md)
  if (bx::mpi_requested(argc, argv))
    if (auto code = bx::mpi_start(&argc, &argv)) return *code;
  CLI::App app{"Bestiary: evolve virtual creatures, bodies and brains together, in 3D physics"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(bx::bestiary_version()) + " (" + bx::bestiary_git() + ")");
  bx::add_simulate_commands(app);
  bx::add_evolve_commands(app);
  bx::add_show_command(app);
  bx::add_render_command(app);
  bx::add_plot_command(app);
  bx::add_check_command(app);
  bx::add_crosscheck_command(app);
  // a command that is not one: name it, and the nearest, before CLI11 does in its words
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const auto* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      return bx::fail(std::string(argv[1]) + ": no such command" + bx::did_you_mean(argv[1], names) +
                      "; the commands: " + list);
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // a usage error: one line, exit code 2, like every other bad input
    std::string what = e.what();
    for (char& c : what)
      if (c == '\n') c = ' ';
    while (!what.empty() && what.back() == ' ') what.pop_back();
    std::string sub;
    for (const auto* s : app.get_subcommands()) sub = " " + s->get_name();
    return bx::fail(what + " (see " + bx::program() + sub + " --help)");
  }
  return 0;
}
