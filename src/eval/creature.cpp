#include "eval/creature.h"

#include <string>

#include "brain/river/river_controller.h"
#include "task/river/quadruped.h"
#include "develop/develop.h"
#include "eval/motif_file.h"
#include "eval/motif_kind.h"
#include "genome/graph_genotype.h"

namespace bx {

namespace {

Result<Creature> develop_graph(const Genotype& g, const SimConfig& cfg) {
  Development dev = develop(*graph_genome(g), cfg.develop);
  if (!dev.viable()) return Error{dev.reason};
  return graph_creature(std::move(*dev.model));
}

// the river crossing: its quadruped, built in code, driven by the hybrid
// controller whose weights are the genes
Result<Creature> develop_river(const Genotype& g, const SimConfig& cfg) {
  const RiverDef& r = cfg.river;
  if (Status s = check_quadruped_def(r.body); !s) return Error{s.error()};
  auto model = make_river_brain_model(r.brain, cfg.motif, static_cast<const FloatVector&>(g).genes);
  if (!model) return Error{model.error()};
  Creature c;
  c.body = std::make_unique<const CreatureModel>(make_quadruped(r.body));
  c.controller = std::make_unique<RiverController>(std::move(*model));
  return c;
}

FloatVectorDef river_genes(const SimConfig& cfg) {
  const RiverDef& r = cfg.river;
  return {river_gene_count(r.brain.shape), -r.gene_range, r.gene_range, r.gene_sigma};
}

std::vector<SimField> river_fields() {
  auto motif_row = [](int i) -> std::function<void*(SimConfig&)> {
    return [i](SimConfig& c) -> void* { return &c.motif.w[static_cast<std::size_t>(i)]; };
  };
  return {
      {"river", "unit", SimField::Real, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.body.unit; }, "river crossing: a cell's width, the quadruped's length unit (m)"},
      {"river", "density", SimField::Real, 1e-12, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.body.density; }, "river crossing: the quadruped's parts' density (kg/m^3)"},
      {"river", "pn_hidden", SimField::Int, 1, 1000, {}, [](SimConfig& c) -> void* { return &c.river.brain.shape.pn_hidden; }, "river crossing: the physical network's hidden neurons (the paper is silent)"},
      {"river", "sweeps", SimField::Int, 0, 100000, {}, [](SimConfig& c) -> void* { return &c.river.brain.landscape.sweeps; }, "river crossing: shunting model iterations from zero (eq. 3)"},
      {"river", "max_activity", SimField::Real, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.brain.landscape.max_activity; }, "river crossing: maxI, the shunting model's cap"},
      {"river", "iota_scale", SimField::Real, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.brain.landscape.iota_scale; }, "river crossing: a cell's input is its kind's iota (-1, 0, 1) times this"},
      {"river", "resource_iota", SimField::Choice, 0, 0, {"decided", "shown"}, [](SimConfig& c) -> void* { return &c.river.brain.resource_iota; }, "river crossing: who sets the resource's (and food's) iota: the decision network (decided, the paper's), or 1 always (shown: a bootstrap, ours)"},
      {"river", "gene_range", SimField::Real, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.gene_range; }, "river crossing: every weight stays in [-gene_range, gene_range]"},
      {"river", "gene_sigma", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.gene_sigma; }, "river crossing: a mutated weight moves by N(0, gene_sigma)"},
      {"motif", "w0", SimField::Triple, -1e6, 1e6, {}, motif_row(0), "river crossing's CTRNN motif: weights into neuron 0 from neurons 0, 1, 2 (eq. 5)"},
      {"motif", "w1", SimField::Triple, -1e6, 1e6, {}, motif_row(1), "... into neuron 1"},
      {"motif", "w2", SimField::Triple, -1e6, 1e6, {}, motif_row(2), "... into neuron 2"},
      {"motif", "tau", SimField::Triple, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.motif.tau; }, "... time constants (s)"},
      {"motif", "alpha", SimField::Triple, -1e6, 1e6, {}, [](SimConfig& c) -> void* { return &c.motif.alpha; }, "... biases (eq. 6)"},
      {"motif", "input", SimField::Int, 0, 2, {}, [](SimConfig& c) -> void* { return &c.motif.input; }, "... the neuron that takes the physical network's drive"},
      {"motif", "output", SimField::Int, 0, 2, {}, [](SimConfig& c) -> void* { return &c.motif.output; }, "... the neuron the motor neurons read"},
      {"motif", "file", SimField::Text, 0, 0, {}, [](SimConfig& c) -> void* { return &c.motif_source.file; }, "... read from this motif file instead: a shipped one's name (motifs/: stanton2015-found) or a path; its motif replaces the keys above (docs/rivercrossing.md, \"The motif file\")"},
      {"motif", "hash", SimField::Text, 0, 0, {}, [](SimConfig& c) -> void* { return &c.motif_source.hash; }, "... the hash of that file's text as it was read (FNV-1a 64), written by the reader: beside motif.file (a run's resolved config) the keys above stand and the file is not read again"},
  };
}

// the paper's body physics and PD motors, its task, and its controller
// stepped once per physics step: the pattern generator's Euler step is the
// paper's 0.01 s (not the sims1994 dialect's two brain steps per physics step)
void river_defaults(SimConfig& c) {
  c.physics = river_physics(c.river.body);
  c.motor = river_motor();
  c.task_kind = TaskKind::River;
  c.brain_hz = 1 / c.physics.dt;
}

// one row per CreatureKind, in its order
const CreatureKindRow kKinds[] = {
    {CreatureKind::Graph, "graph", GraphGenotype::kKind, develop_graph, nullptr, nullptr, nullptr, nullptr, nullptr,
     nullptr, ""},
    {CreatureKind::River, "river", "floats", develop_river, nullptr, river_genes, river_fields, river_defaults,
     resolve_motif_keys, nullptr, "Stanton & Channon 2015"},
    {CreatureKind::Motif, "motif", "floats", nullptr, evaluate_motif_genes, motif_kind_genes, motif_kind_fields,
     nullptr, nullptr, check_motif_kind, "Stanton & Channon 2015"},
};

}  // namespace

const CreatureKindRow& creature_kind_row(CreatureKind kind) { return kKinds[static_cast<int>(kind)]; }

std::span<const CreatureKindRow> creature_kind_rows() { return kKinds; }

std::vector<std::string_view> creature_kind_names() {
  std::vector<std::string_view> out;
  for (const CreatureKindRow& r : kKinds) out.push_back(r.name);
  return out;
}

std::vector<SimField> creature_fields() {
  std::vector<SimField> out;
  for (const CreatureKindRow& r : kKinds)
    if (r.fields)
      for (SimField& f : r.fields()) out.push_back(std::move(f));
  return out;
}

bool has_body(CreatureKind kind) { return creature_kind_row(kind).evaluate == nullptr; }

std::string no_body(CreatureKind kind, std::string_view what) {
  return "genotype.kind \"" + std::string(creature_kind_row(kind).name) + "\" has no body: " + std::string(what);
}

void apply_creature_kind(SimConfig& cfg, CreatureKind kind) {
  cfg.creature = kind;
  if (auto defaults = creature_kind_row(kind).defaults) defaults(cfg);
}

Result<Creature> develop_creature(const Genotype& g, const SimConfig& cfg) {
  const CreatureKindRow& row = creature_kind_row(cfg.creature);
  if (g.kind() != row.genotype_kind)
    return Error{"a genotype of kind " + std::string(g.kind()) + ", but genotype.kind \"" + std::string(row.name) +
                 "\" develops " + std::string(row.genotype_kind) + " genotypes"};
  if (!row.develop) return Error{no_body(cfg.creature, "nothing to develop")};
  return row.develop(g, cfg);
}

Creature graph_creature(CreatureModel body) {
  Creature c;
  auto owned = std::make_unique<const CreatureModel>(std::move(body));
  c.controller = std::make_unique<GraphBrain>(owned->brain);
  c.body = std::move(owned);
  return c;
}

}  // namespace bx
