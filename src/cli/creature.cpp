#include "cli/creature.h"

#include <CLI/CLI.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "cli/commands.h"
#include "core/files.h"
#include "core/hash.h"
#include "core/text.h"
#include "eval/records_json.h"
#include "run/run.h"
#include "genome/dialect.h"
#include "genome/float_vector.h"
#include "genome/genotype_file.h"
#include "genome/graph_genotype.h"
#include "io/run_store.h"
#include "io/syllabus.h"

namespace bx {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A run target split into its directory and its selector (after the colon).
struct RunTarget {
  std::string dir;
  std::string selector;  ///< "", "ID" or "gen=G"
};

std::optional<RunTarget> split_run(const std::string& target) {
  if (fs::is_directory(target)) return RunTarget{target, ""};
  auto colon = target.rfind(':');
  if (colon == std::string::npos || colon == 0) return std::nullopt;
  std::string dir = target.substr(0, colon);
  if (!fs::is_directory(dir)) return std::nullopt;
  return RunTarget{dir, target.substr(colon + 1)};
}

// a whole decimal number in [lo, hi], or nullopt
template <class T>
std::optional<T> whole(const std::string& s, T lo, T hi) {
  T v{};
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || v < lo || v > hi) return std::nullopt;
  return v;
}

std::string joined_sets(const std::vector<std::string>& set) {
  std::string out;
  for (const auto& s : set) out += (out.empty() ? "--set " : ", --set ") + s;
  return out;
}

Status apply_seconds(Subject& c, const std::optional<double>& seconds) { return set_seconds(c.cfg.sim, seconds); }

// --trial K: one of the evaluation's task.trials (all of them still run: the
// fitness is their fold), so it keeps the settings as scored
Status apply_trial(Subject& c, const std::optional<int>& trial) {
  if (!trial) return Ok{};
  if (!has_body(c.cfg.sim.creature)) return Error{"--trial: " + no_body(c.cfg.sim.creature, "no trials to pick")};
  const int n = std::max(1, c.cfg.sim.trials);
  if (*trial < 1 || *trial > n)
    return Error{"--trial: " + std::to_string(*trial) + ", but the evaluation has " +
                 (n == 1 ? std::string("one trial") : std::to_string(n) + " trials") + " (task.trials = " +
                 std::to_string(n) + "): expected " + (n == 1 ? std::string("1") : "1 to " + std::to_string(n))};
  c.trial = *trial - 1;
  return Ok{};
}

// whether two run configs evaluate a creature alike: the same simulation and
// the same evolution (which says how the elite was re-evaluated); check's
// gates may differ
bool evaluates_alike(const RunConfig& a, const RunConfig& b) {
  return a.dialect == b.dialect && a.sim == b.sim && a.evolution == b.evolution;
}

Result<Subject> from_run(const RunTarget& t, const CreatureFlags& f) {
  if (!f.config.empty())
    return Error{"--config: a run's creature is evaluated with its run's config (use --set to vary it)"};
  if (f.seed) return Error{"--seed: a run's creature is evaluated with its own stored evaluation seed"};
  auto store = RunStore::open(run_db_path(t.dir));
  if (!store) return Error{store.error()};
  std::optional<std::int64_t> id = f.id;
  std::optional<int> gen = f.gen;
  if (!t.selector.empty()) {
    if (f.id || f.gen) return Error{"--id/--gen: the creature is already named by \"" + t.dir + ":" + t.selector + "\""};
    if (t.selector.rfind("gen=", 0) == 0) {
      gen = whole<int>(t.selector.substr(4), 0, 1 << 30);
      if (!gen) return Error{t.dir + ":" + t.selector + ": expected gen=G with G a generation number"};
    } else {
      id = whole<std::int64_t>(t.selector, 0, INT64_MAX);
      if (!id) return Error{t.dir + ":" + t.selector + ": expected RUN_DIR:ID (an individual's id) or RUN_DIR:gen=G"};
    }
  }
  if (id && gen) return Error{"--id/--gen: name an individual or a generation, not both"};
  Result<Individual> ind = Error{""};
  if (id) {
    ind = (*store)->individual(*id);
    if (!ind) return Error{t.dir + ": " + ind.error()};
  } else if (gen) {
    auto gens = (*store)->generations();
    if (gens.empty()) return Error{t.dir + ": no generation finished yet"};
    auto g = std::find_if(gens.begin(), gens.end(), [&](const GenerationStats& s) { return s.generation == *gen; });
    if (g == gens.end())
      return Error{t.dir + ": no generation " + std::to_string(*gen) + " (generations " +
                   std::to_string(gens.front().generation) + " to " + std::to_string(gens.back().generation) + ")"};
    ind = (*store)->individual(g->best_id);
    if (!ind) return Error{t.dir + ": generation " + std::to_string(*gen) + "'s best: " + ind.error()};
  } else {
    ind = (*store)->best_individual();
    if (!ind) return Error{t.dir + ": " + ind.error()};
  }
  auto text = (*store)->config_text();
  if (!text) return Error{text.error()};
  // the config of its stage (a run of one stage: the run's)
  const std::string source = run_db_path(t.dir) + " (the run's config)";
  auto syl = read_syllabus(*text, source, f.set);
  if (!syl) return Error{syl.error()};
  const StageRow stage = stage_of((*store)->stages(), ind->id);
  if (stage.index >= static_cast<int>(syl->stages.size()))
    return Error{t.dir + ": individual " + std::to_string(ind->id) + " is of stage " + std::to_string(stage.index + 1) +
                 ", but the run's config has " + std::to_string(syl->stages.size())};
  const RunConfig* cfg = &syl->stages[stage.index].cfg;
  Subject c;
  c.genotype = ind->genotype;
  c.cfg = *cfg;
  c.seed = ind->seed;
  c.label = t.dir + " individual " + std::to_string(ind->id) + " (generation " + std::to_string(ind->generation) +
            (syl->staged() ? ", stage \"" + stage.name + "\"" : "") + ")";
  c.run_config_text = *text;
  if (syl->staged()) {
    auto plain = read_syllabus(*text, source);
    if (!plain) return Error{plain.error()};
    c.run_config_text = "# Stage \"" + one_line(stage.name) + "\" of the run " + one_line(utf8_text(t.dir)) + "\n" +
                        config_to_toml(plain->stages[stage.index].cfg);
  }
  c.stored_fitness = ind->fitness;
  c.evaluations = ind->evaluations;
  c.individual = *ind;
  c.run_dir = t.dir;
  auto held = (*store)->held_out();
  if (!held) return Error{held.error()};
  if (*held && (*held)->id == ind->id) c.held_out = **held;
  // --set keys that change no evaluation (check's gates) keep it as scored
  bool same = f.set.empty();
  if (!same) {
    auto plain = read_syllabus(*text, source, {});
    same = plain && evaluates_alike(plain->stages[stage.index].cfg, *cfg);
  }
  c.scored_settings = same && !f.seconds;
  c.settings = c.scored_settings
                   ? "as scored: the run's config" + (f.set.empty() ? std::string() : " (with " + joined_sets(f.set) + ")") +
                         " and its evaluation seed " + std::to_string(c.seed)
                   : "not as scored: the run's config and seed with " +
                         joined_sets(f.set) + (f.seconds ? std::string(f.set.empty() ? "" : ", ") + "--seconds" : "");
  if (Status s = apply_seconds(c, f.seconds); !s) return Error{s.error()};
  return c;
}

// the run config of a genotype file: a graph genome's dialect's defaults (a
// catapult throws), then --config, then --set; the config's creature kind must
// develop the genotype (its kind, and a float vector's length and box)
Result<RunConfig> genotype_config(const Genotype& g, const std::string& file, const std::string& text,
                                  const std::string& source, const std::vector<std::string>& set) {
  std::vector<std::string> layers;
  const Genome* genome = graph_genome(g);
  if (genome) {
    // the file decides the dialect only if it names one (then it must be the genome's)
    bool names_dialect = false;
    try {
      names_dialect = toml::parse(text, source)["genome"]["dialect"].is_value();
    } catch (const toml::parse_error&) {
      // read_run_config reports it with its position
    }
    if (!names_dialect) layers.push_back("genome.dialect=" + std::string(to_string(genome->dialect)));
    if (genome->catapult) {
      layers.push_back("catapult.enabled=true");
      layers.push_back("task.kind=throwing");
    }
  }
  layers.insert(layers.end(), set.begin(), set.end());
  // a config of stages (a staged preset's file): its last stage's, the one
  // whose best such a run reports
  bool staged = false;
  try {
    staged = toml::parse(text, source)["stage"].is_array_of_tables();
  } catch (const toml::parse_error&) {
    // read_run_config reports it with its position
  }
  Result<RunConfig> cfg = Error{""};
  if (staged) {
    auto syl = read_syllabus(text, source, layers);
    if (!syl) return Error{syl.error()};
    cfg = syl->stages.back().cfg;
  } else {
    cfg = read_run_config(text, source, layers);
  }
  if (!cfg) return Error{cfg.error()};
  if (genome && cfg->dialect != genome->dialect)
    return Error{source + ": genome.dialect is " + std::string(to_string(cfg->dialect)) + ", the genome's is " +
                 std::string(to_string(genome->dialect))};
  const CreatureKindRow& row = creature_kind_row(cfg->sim.creature);
  if (g.kind() != row.genotype_kind)
    return Error{source + ": genotype.kind \"" + std::string(row.name) + "\" develops " +
                 std::string(row.genotype_kind) + " genotypes, but " + file + " holds a " + std::string(g.kind()) +
                 " genotype"};
  if (row.float_genes) {
    auto fits = FloatVectorOps(row.float_genes(cfg->sim)).from_json(g.to_json());
    if (!fits) return Error{file + ": " + fits.error() + " (genotype.kind \"" + std::string(row.name) + "\")"};
  }
  return cfg;
}

Result<Subject> from_genome(const std::string& path, const CreatureFlags& f) {
  if (f.id || f.gen) return Error{"--id/--gen: name an individual of a run; " + path + " is a genome file"};
  auto text = read_file(path);
  if (!text) return Error{text.error()};
  auto g = genotype_from_file_text(*text, path);
  if (!g) return Error{g.error()};
  Subject c;
  c.genotype = std::move(*g);
  c.label = path;
  json prov;
  try {
    prov = json::parse(*text).value("provenance", json::object());
  } catch (const json::exception&) {
    // the genotype reader accepted it, so it parses
  }
  std::string scored_by;  // "RUN individual N"
  std::optional<std::uint64_t> prov_seed;
  auto str = [&](const char* k) {
    return prov.contains(k) && prov[k].is_string() ? prov[k].get<std::string>() : std::string();
  };
  if (!prov.empty()) {
    // written by `best --out`: the run's config and seed travel with the genome
    prov_seed = whole<std::uint64_t>(str("seed"), 0, UINT64_MAX);
    if (!prov_seed || str("config").empty())
      return Error{path + ": provenance: expected the fields \"seed\" (a number as text) and \"config\" (TOML text)"};
    scored_by = str("run") + " individual " + (prov.contains("individual") ? prov["individual"].dump() : "?");
    bool genome_same = str("genome_hash") == fnv1a64_hex(genotype_text(*c.genotype));
    bool config_same = str("config_hash") == fnv1a64_hex(str("config"));
    if (f.config.empty() && !f.seed) {
      auto cfg = genotype_config(*c.genotype, path, str("config"), path + " (provenance.config)", f.set);
      if (!cfg) return Error{cfg.error()};
      c.cfg = *cfg;
      c.seed = *prov_seed;
      bool same = f.set.empty();
      if (!same) {  // --set keys that change no evaluation (check's gates) keep it as scored
        auto plain = genotype_config(*c.genotype, path, str("config"), path + " (provenance.config)", {});
        same = plain && evaluates_alike(*plain, *cfg);
      }
      c.scored_settings = genome_same && config_same && same && !f.seconds;
      if (genome_same && prov.contains("fitness") && prov["fitness"].is_number())
        c.stored_fitness = prov["fitness"].get<double>();
      if (prov.contains("evaluations")) {
        if (!prov["evaluations"].is_number_integer() || prov["evaluations"].get<std::int64_t>() < 1 ||
            prov["evaluations"].get<std::int64_t>() > 1000000)
          return Error{path + ": provenance.evaluations: expected a whole number >= 1, got " +
                       prov["evaluations"].dump().substr(0, 40)};
        c.evaluations = static_cast<int>(prov["evaluations"].get<std::int64_t>());
      }
      if (prov.contains("held_out")) {
        auto held = held_out_from_json(prov["held_out"], path + ": provenance.held_out", false);
        if (!held) return Error{held.error()};
        if (genome_same) c.held_out = std::move(*held);
      }
      if (c.scored_settings)
        c.settings = "as scored (" + scored_by + "): its run's config" +
                     (f.set.empty() ? std::string() : " (with " + joined_sets(f.set) + ")") + " and evaluation seed " +
                     std::to_string(c.seed);
      else if (!genome_same)
        c.settings = "not as scored: the genome was edited after " + scored_by + " was scored";
      else if (!config_same)
        c.settings = "not as scored: the provenance's config was edited";
      else
        c.settings = "not as scored: " + scored_by + "'s config and seed with " + joined_sets(f.set) +
                     (f.seconds ? std::string(f.set.empty() ? "" : ", ") + "--seconds" : "");
      if (Status s = apply_seconds(c, f.seconds); !s) return Error{s.error()};
      return c;
    }
  }
  // --config replaces the config, --seed the seed; with a provenance, the
  // other stays the scored one
  std::string cfg_text = scored_by.empty() ? "" : str("config");
  std::string source = scored_by.empty() ? path : path + " (provenance.config)";
  // a graph genome's dialect gives its defaults; another kind's genotype
  // says nothing of its creature, so without a provenance it needs a config
  if (scored_by.empty() && f.config.empty() && !c.graph_genome())
    return Error{path + ": a " + std::string(c.genotype->kind()) +
                 " genotype without provenance: give --config, a config whose genotype.kind develops it"};
  if (!f.config.empty()) {
    auto t = config_source(f.config);
    if (!t) return Error{t.error()};
    cfg_text = t->second;
    source = f.config;
  }
  auto cfg = genotype_config(*c.genotype, path, cfg_text, source, f.set);
  if (!cfg) return Error{cfg.error()};
  c.cfg = *cfg;
  c.seed = f.seed.value_or(prov_seed.value_or(1));
  if (!scored_by.empty())
    c.settings = "not as scored: " +
                 std::string(f.config.empty() ? "--seed" : f.seed ? "--config and --seed" : "--config") + " given (" +
                 scored_by + " was scored with its run's config and seed " + str("seed") + ")";
  if (Status s = apply_seconds(c, f.seconds); !s) return Error{s.error()};
  return c;
}

}  // namespace

std::string exact_number(double v) { return shortest_number(v); }

Status set_seconds(SimConfig& sim, const std::optional<double>& seconds) {
  if (!seconds) return Ok{};
  if (!has_body(sim.creature)) return Error{"--seconds: " + no_body(sim.creature, "no task to lengthen")};
  if (!(*seconds > 0) || !std::isfinite(*seconds) || *seconds > 1e6)
    return Error{"--seconds: expected a number in (0, 1e6], got " + exact_number(*seconds)};
  task_seconds(sim) = *seconds;
  return Ok{};
}

const Genome* Subject::graph_genome() const { return genotype ? bx::graph_genome(*genotype) : nullptr; }

Result<Creature> Subject::develop() const { return develop_creature(*genotype, cfg.sim); }

Repeats Subject::repeats() const {
  return elite_repeats(cfg.evolution, scored_settings ? evaluations : 1);
}

std::string Subject::evaluations_note() const {
  if (!scored_settings || evaluations <= 1 || !stored_fitness) return "";
  char buf[128];
  std::snprintf(buf, sizeof buf, "(evaluation 1 of %d; the stored fitness %.6g is their %s", evaluations,
                *stored_fitness, score_name(cfg.sim.trial_score));
  const std::string halves = finer_step_text(repeats());
  return buf + (halves.empty() ? "" : "; " + halves) + ")";
}

std::string fitness_line(double fitness, const std::optional<double>& stored) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "fitness %.6g", fitness);
  std::string out = buf;
  if (!stored) return out;
  if (std::memcmp(&fitness, &*stored, sizeof fitness) == 0) return out + " (the stored fitness, bit for bit)";
  return out + " (NOT the stored fitness " + exact_number(*stored) + ": " + exact_number(fitness) + ")";
}

std::string metrics_line(const std::vector<Metric>& metrics) {
  std::string out;
  for (const Metric& m : metrics) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", m.value);
    out += (out.empty() ? "" : ", ") + m.name + " " + buf;
  }
  return out;
}

void add_creature_options(CLI::App* cmd, std::string& target, CreatureFlags& f) {
  cmd->add_option("creature", target,
                  "Genome file (JSON), or a run's creature: RUN_DIR (its best), RUN_DIR:ID, RUN_DIR:gen=G")
      ->required();
  cmd->add_option("--id", f.id, "A run's individual (as RUN_DIR:ID)")->check(whole_number(0, INT64_MAX));
  cmd->add_option("--gen", f.gen, "The best of a run's generation (as RUN_DIR:gen=G)")->check(whole_number(0, INT32_MAX));
  cmd->add_option("--config", f.config, "Config (a file or a preset name) for a genome file, overlaid on its dialect's defaults");
  cmd->add_option("--seed", f.seed, "Evaluation seed for a genome file (default 1, or its provenance's)")
      ->check(whole_number(0, UINT64_MAX));
  cmd->add_option("--set", f.set, "Override one config key: section.key=value (repeatable)");
  cmd->add_option("--seconds", f.seconds, "Simulated seconds (default: the config's task.seconds, or throwing.seconds)");
}

void add_trial_option(CLI::App* cmd, CreatureFlags& f) {
  cmd->add_option("--trial", f.trial,
                  "Watch trial K (from 1) of an evaluation of task.trials: its replay and measures (every trial still "
                  "runs: the fitness is their fold; default 1)")
      ->check(whole_number(1, INT32_MAX));
}

bool names_run(const std::string& target) { return split_run(target).has_value(); }

Result<Subject> resolve_creature(const std::string& target, const CreatureFlags& flags) {
  auto run = split_run(target);
  auto c = run ? from_run(*run, flags) : from_genome(target, flags);
  if (!c) return c;
  if (Status s = apply_trial(*c, flags.trial); !s) return Error{s.error()};
  return c;
}

json provenance_json(const Subject& c, const std::string& config_text) {
  json p;
  p["run"] = c.run_dir;
  if (c.individual) {
    p["individual"] = c.individual->id;
    p["generation"] = c.individual->generation;
    p["fitness"] = c.individual->fitness;
    p["evaluations"] = c.individual->evaluations;
  }
  if (c.held_out) p["held_out"] = held_out_to_json(*c.held_out);
  p["seed"] = std::to_string(c.seed);  // text: JSON numbers lose 64-bit integers in many readers
  p["genome_hash"] = fnv1a64_hex(genotype_text(*c.genotype));
  p["config_hash"] = fnv1a64_hex(config_text);
  p["config"] = config_text;
  return p;
}

}  // namespace bx
