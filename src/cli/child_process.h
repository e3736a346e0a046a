// Running another program from the CLI: `render` runs node (its script drives
// headless Chromium and ffmpeg), `plot` runs Chromium for a PNG. One child at a
// time, its output read through pipes while it runs.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"

namespace bx {

/// An executable file named `name` on PATH (or `name` itself if it has a '/').
std::optional<std::string> find_program(const std::string& name);

/// The Chromium that render and plot's PNG run headless: $BESTIARY_CHROMIUM
/// when set, else Debian's (/usr/bin/chromium, else `chromium` on PATH); an
/// error, `who` first, naming a BESTIARY_CHROMIUM that is no program or
/// saying how to get one (`install` a hint to add).
Result<std::string> find_chromium(const std::string& who, const std::string& install);

/// How a child program ended: its exit code (-1 if it could not start or died
/// of a signal) and the last non-empty line it wrote on stderr, its own
/// explanation of a failure.
struct Ended {
  int code = -1;
  std::string last_err;
};

/// Runs argv with stdin from /dev/null, reading its stdout and stderr through
/// pipes while it runs: each stdout line goes to `on_line`. One poll loop, no
/// threads; it stops once the child has exited and its pipes are drained, even
/// if a grandchild still holds them open.
Ended run_program(const std::vector<std::string>& argv, const std::function<void(const std::string&)>& on_line);

}  // namespace bx
