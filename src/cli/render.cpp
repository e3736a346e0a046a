// `bestiary render`: a video of a creature, made from the viewer's page by
// headless Chromium (node drives it) and ffmpeg (docs/viewer.md).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "cli/child_process.h"
#include "cli/commands.h"
#include "cli/creature.h"
#include "cli/watch.h"
#include "core/files.h"
#include "core/text.h"
#include "io/html_view.h"

namespace bx {

namespace {

namespace fs = std::filesystem;

/// Arguments of `render`.
struct RenderArgs {
  std::string genome;  ///< a genome file or a run's creature
  CreatureFlags flags;
  std::string out;
  int width = 1280, height = 720;
  std::optional<int> fps;  ///< default 30 for mp4, 15 for gif
  bool quiet = false;      ///< no progress output
};

/// Where render finds node, its script and the browser and encoder.
struct Tools {
  std::string node, script, chromium, ffmpeg;
};

// The viewer folder holds render.mjs and node_modules (npm ci); the build
// records the source tree's (BESTIARY_VIEWER_DIR), the environment variable
// of the same name overrides it. Chromium: find_chromium's.
Result<Tools> find_tools() {
  Tools t;
  const char* env_dir = std::getenv("BESTIARY_VIEWER_DIR");
  fs::path dir = env_dir && *env_dir ? env_dir : BESTIARY_VIEWER_DIR;
  t.script = (dir / "render.mjs").string();
  if (!fs::exists(t.script) || !fs::exists(dir / "node_modules/playwright-core/package.json"))
    return Error{"render: the viewer's render.mjs and node_modules are not in " + dir.string() +
                 " (run ./scripts/setup, or set BESTIARY_VIEWER_DIR to a viewer/ folder after `npm ci`)"};
  auto node = find_program("node");
  if (!node) return Error{"render: node is not on PATH (Debian package nodejs; ./scripts/setup installs it)"};
  auto chromium = find_chromium("render", "Debian package chromium, or set BESTIARY_CHROMIUM");
  if (!chromium) return Error{chromium.error()};
  auto ffmpeg = find_program("ffmpeg");
  if (!ffmpeg) return Error{"render: ffmpeg is not on PATH (Debian package ffmpeg)"};
  t.node = *node;
  t.chromium = *chromium;
  t.ffmpeg = *ffmpeg;
  return t;
}

int cmd_render(const RenderArgs& a) {
  // inputs: the creature, its config and flags, the output's kind and folder, the tools
  auto c = resolve_creature(a.genome, a.flags);
  if (!c) return fail(c.error());
  if (!has_body(c->cfg.sim.creature)) return fail(no_body(c->cfg.sim.creature, "nothing to render"));
  std::string ext = ascii_lower(fs::path(a.out).extension().string());
  if (ext != ".mp4" && ext != ".gif")
    return fail("--out: expected a file name ending in .mp4 or .gif, got \"" + a.out + "\"");
  std::string format = ext.substr(1);
  for (auto [flag, v] : {std::pair{"--width", a.width}, std::pair{"--height", a.height}}) {
    if (v < 16 || v > 3840)
      return fail(std::string(flag) + ": expected a number of pixels in [16, 3840], got " + std::to_string(v));
    if (format == "mp4" && v % 2 != 0)
      return fail(std::string(flag) + ": an mp4 needs an even number of pixels, got " + std::to_string(v));
  }
  // a GIF compresses far less than H.264: half an mp4's frames keep it small and are smooth enough
  const int fps = a.fps.value_or(format == "gif" ? 15 : 30);
  if (fps < 1 || fps > 60) return fail("--fps: expected frames per second in [1, 60], got " + std::to_string(fps));
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  auto tools = find_tools();
  if (!tools) return fail(tools.error());

  // simulate, and write the page into a fresh temporary folder
  if (!a.quiet) std::printf("simulating %s ...\n", c->label.c_str());
  std::fflush(stdout);
  auto watched = simulate_watched(*c);
  if (!watched) return fail(watched.error());
  Watched* w = &watched->front();
  w->entry.label += trial_text(w->result);
  std::string tmpl = (fs::temp_directory_path() / "bestiary-render-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) return fail("render: cannot make a temporary folder in " + fs::temp_directory_path().string());
  fs::path work = tmpl;
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{work};
  std::string page = (work / "page.html").string();
  if (Status s = save_view_html(page, {w->entry}); !s) return fail(s.error());

  // the page, frame by frame, through ffmpeg into OUT.tmp; renamed when whole
  double seconds = w->result.seconds;
  long frames = std::max(1L, std::lround(seconds * fps));
  std::string tmp = a.out + ".tmp";
  if (!a.quiet) std::printf("rendering %ld frames (%d x %d, %d fps)...\n", frames, a.width, a.height, fps);
  std::fflush(stdout);

  // render.mjs's progress lines: one updating line on a terminal, else one
  // every PROGRESS_SECONDS and the last
  constexpr auto PROGRESS_SECONDS = std::chrono::seconds(10);
  const bool tty = !a.quiet && ::isatty(STDOUT_FILENO);
  const std::string last_frame = "frame " + std::to_string(frames) + "/";
  auto shown = std::chrono::steady_clock::now();
  bool open_line = false;
  auto progress = [&](const std::string& line) {
    if (a.quiet) return;
    auto now = std::chrono::steady_clock::now();
    if (tty) {
      std::printf("\r\033[K%s", line.c_str());
      open_line = true;
    } else if (now - shown >= PROGRESS_SECONDS || line.rfind(last_frame, 0) == 0) {
      std::printf("%s\n", line.c_str());
      shown = now;
    }
    std::fflush(stdout);
  };
  Ended end = run_program({tools->node, tools->script, "--html", page, "--out", tmp, "--format", format,
                   "--frames", std::to_string(frames), "--fps", std::to_string(fps),
                   "--width", std::to_string(a.width), "--height", std::to_string(a.height),
                   "--chromium", tools->chromium, "--ffmpeg", tools->ffmpeg},
                  progress);
  if (open_line) std::printf("\n");
  std::fflush(stdout);
  if (end.code != 0) {
    std::remove(tmp.c_str());
    return fail("render: " + (end.last_err.empty()
                                  ? "node " + tools->script + " failed (exit " + std::to_string(end.code) + ")"
                                  : end.last_err));
  }
  std::error_code ec;
  fs::rename(tmp, a.out, ec);
  if (ec) {
    std::remove(tmp.c_str());
    return fail(a.out + ": cannot replace file (" + ec.message() + ")");
  }
  print_result(*c, w->result);
  std::printf("video written to %s (%ld frames, %.2f s)\n", a.out.c_str(), frames,
              static_cast<double>(frames) / fps);
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app) {
  // arguments live as long as the app: parsing fills them, the callback reads them
  static RenderArgs render;
  auto* r = app.add_subcommand("render", "Simulate a genome and make a video of it (mp4 or gif)");
  add_creature_options(r, render.genome, render.flags);
  add_trial_option(r, render.flags);
  r->add_option("--out", render.out, "Video file to write: .mp4 or .gif")->required();
  r->add_option("--width", render.width, "Width in pixels")->default_val(1280);
  r->add_option("--height", render.height, "Height in pixels")->default_val(720);
  r->add_option("--fps", render.fps, "Frames per second (default 30 for mp4, 15 for gif)");
  r->add_flag("--quiet", render.quiet, "No progress output");
  r->callback([] { std::exit(cmd_render(render)); });
}

}  // namespace bx
