// libFuzzer target: the config reader, as `bestiary run CONFIG.toml --set
// KEY=V...` reads a config (TOML text, then the overrides). Aborts (a
// finding) on a crash, a sanitizer report, an error of several lines, or a
// config whose printed form does not read back as itself.
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "io/config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace bx;
  bxfuzz::Input in = bxfuzz::split(data, size);

  auto cfg = read_run_config(in.text, "fuzz.toml", in.overrides);
  if (!cfg) {
    bxfuzz::check_one_line(cfg.error());
  } else {
    // the resolved config (what a run directory stores) reads back as itself
    std::string printed = config_to_toml(*cfg);
    auto again = read_run_config(printed, "config.toml");
    if (!again) bxfuzz::broken("printed config does not read back", again.error() + "\n" + printed);
    if (config_to_toml(*again) != printed) bxfuzz::broken("printed config reads back as another", printed);
  }
  // `bestiary config --config FILE`, `simulate --config FILE`: the sim sections onto a dialect's defaults
  RunConfig rc = default_run_config(Dialect::Chaumont2007);
  if (Status s = apply_config_toml(rc, in.text, "fuzz.toml"); !s) bxfuzz::check_one_line(s.error());
  return 0;
}
