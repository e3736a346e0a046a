// libFuzzer target: the genome reader, development and a short simulation,
// as `bestiary simulate GENOME.json --set develop.KEY=V... --seconds 0.3`
// runs them. Aborts (a finding) on a crash, a sanitizer report, an error of
// several lines, or a genome that does not read back as itself.
#include <cstdint>
#include <string>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "fuzz_input.h"
#include "genome/genome_json.h"
#include "io/config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace bx;
  bxfuzz::Input in = bxfuzz::split(data, size);

  // read: a genome or a one-line refusal
  auto g = genome_from_string(in.text, "fuzz.json");
  if (!g) {
    bxfuzz::check_one_line(g.error());
    return 0;
  }
  // its canonical text reads back as the same genome
  std::string text = genome_to_string(*g);
  auto again = genome_from_string(text, "canonical");
  if (!again) bxfuzz::broken("canonical text does not read back", again.error());
  if (!(*again == *g)) bxfuzz::broken("canonical text reads back as another genome", text);

  // the config `simulate` gives a genome file: its dialect's defaults, a
  // catapult throws; then the input's develop.* overrides (the config target
  // covers the rest), then a fraction of a second of simulated time
  std::vector<std::string> set = {"genome.dialect=" + std::string(to_string(g->dialect))};
  if (g->catapult) {
    set.push_back("catapult.enabled=true");
    set.push_back("task.kind=throwing");
  }
  for (const auto& o : in.overrides)
    if (o.rfind("develop.", 0) == 0) set.push_back(o);
  auto cfg = read_run_config("", "fuzz", set);
  if (!cfg) {
    bxfuzz::check_one_line(cfg.error());
    return 0;
  }
  SimConfig sim = cfg->sim;
  task_seconds(sim) = 0.3;
  sim.task.settle.timeout = std::min(sim.task.settle.timeout, 0.3);  // chaumont2007's sequence
  sim.task.burst_seconds = std::min(sim.task.burst_seconds, 0.1);

  // develop: a creature or a reason; simulate the creature
  Development dev = develop(*g, sim.develop);
  if (!dev.viable()) {
    if (dev.reason.empty()) bxfuzz::broken("non-viable without a reason", text);
    return 0;
  }
  // develop.max_parts allows 100,000 parts: development is linear in them,
  // stepping them (ODE's simple space) is not; a creature that big is
  // developed, not simulated, here
  if (dev.model->n_parts() > 200) return 0;
  EvalResult r = evaluate(*dev.model, sim, 1);
  if (r.failed && r.failure.empty()) bxfuzz::broken("failed evaluation without a reason", text);
  return 0;
}
