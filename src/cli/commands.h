// Subcommands of `bestiary`. Each file of src/cli/ registers its own
// subcommands on the app; a subcommand's callback exits with its code: 0 on
// success, 2 on bad input (after one error line on stderr).
#pragma once

#include <string>
#include <utility>

#include "core/result.h"

namespace CLI {
class App;
class Validator;
}

namespace bx {

/// `simulate` and `config` (src/cli/simulate.cpp).
void add_simulate_commands(CLI::App& app);

/// `run`, `resume`, `verify`, `best` and `presets` (src/cli/evolve_cmds.cpp).
void add_evolve_commands(CLI::App& app);

/// `show` (src/cli/show.cpp).
void add_show_command(CLI::App& app);

/// `render` (src/cli/render.cpp).
void add_render_command(CLI::App& app);

/// `plot` (src/cli/plot.cpp).
void add_plot_command(CLI::App& app);

/// `check` (src/cli/check.cpp).
void add_check_command(CLI::App& app);

/// `crosscheck` (src/cli/crosscheck.cpp).
void add_crosscheck_command(CLI::App& app);

/// Prints "bestiary: MESSAGE" on stderr and returns 2, the bad-input exit code.
int fail(const std::string& message);

/// The program as the user ran it (argv[0], e.g. ./build/bestiary), for the
/// commands we print as next steps.
const std::string& program();
void set_program(const char* argv0);

/// A validator for a flag that takes a whole number in [lo, hi]; its error
/// says so in those words.
CLI::Validator whole_number(long long lo, unsigned long long hi);

/// The name and text of a config: a file at `arg`, or else the preset of
/// that name (`bestiary presets`); an error names both and suggests a preset.
/// `run` takes it, and every `--config`.
Result<std::pair<std::string, std::string>> config_source(const std::string& arg);

/// Makes the folder of an output file (so a bad path fails before any work);
/// errors name `flag`.
Status make_parent_dir(const std::string& flag, const std::string& path);

}  // namespace bx
