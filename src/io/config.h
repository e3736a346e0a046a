// TOML configs: sections map one to one onto the definition structs
// (SimConfig's PhysicsDef, MotorDef, DevelopDef, LocomotionDef; EvolutionDef;
// OperatorDef). Unknown keys, wrong types and out-of-range values are errors
// that name the key and the value, and change nothing.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "eval/check.h"
#include "eval/sim_config.h"
#include "evolve/evolution_def.h"
#include "genome/operators.h"

namespace bx {

/// Everything a run needs: the dialect, the simulation, the algorithm and
/// the operators.
struct RunConfig {
  Dialect dialect = Dialect::Sims1994;
  SimConfig sim;
  EvolutionDef evolution;
  OperatorDef operators;
  CheckDef check;  ///< the gates of `bestiary check`
  friend bool operator==(const RunConfig&, const RunConfig&) = default;
};

/// What a run of this config evolves, in a word: a graph genome's dialect
/// (sims1994, ...), or another creature kind's name (its genotype.kind).
std::string evolved_name(const RunConfig& cfg);

/// The defaults of a dialect (its paper's constants).
RunConfig default_run_config(Dialect d);

/// Overlays TOML text onto `cfg`. `source` names the text in errors.
Status apply_config_toml(RunConfig& cfg, std::string_view text, std::string_view source);

/// A run config from TOML text and `--set section.key=value` overrides: the
/// dialect (genome.dialect, default sims1994) picks the defaults, then the
/// text and the overrides are overlaid in order.
Result<RunConfig> read_run_config(std::string_view text, std::string_view source,
                                  const std::vector<std::string>& overrides = {});

/// One layer of a config: TOML text and its name in messages.
struct ConfigLayer {
  std::string text;
  std::string source;
};

/// read_run_config of several layers of TOML text overlaid in order (a
/// multi-stage run's stage on its base, io/syllabus.h), then the overrides;
/// the first layer's source names the whole in messages about it.
Result<RunConfig> read_run_config(std::vector<ConfigLayer> layers, const std::vector<std::string>& overrides = {});

/// Reads a TOML file onto a simulation config (a run config works too: its
/// other sections are checked and ignored).
Status apply_config_file(SimConfig& cfg, const std::string& path);

/// The config as TOML, every key (for run directories and `bestiary config`).
std::string config_to_toml(const RunConfig& cfg, bool sim_only = false);
std::string config_to_toml(const SimConfig& cfg);

/// Every key with each dialect's default and its meaning, as a Markdown
/// table (docs/config.md is made from it: `bestiary config --reference`).
std::string config_reference_markdown();

}  // namespace bx
