#include "develop/graph_ops.h"

#include <cassert>

#include "genome/dialect.h"
#include "genome/encapsulate.h"
#include "genome/genome_json.h"
#include "genome/graph_genotype.h"
#include "genome/reconcile.h"

namespace bx {

namespace {

const Genome& genome_of(const Genotype& g) {
  const Genome* p = graph_genome(g);
  assert(p && "a graph operator given another kind of genotype");
  return *p;
}

std::unique_ptr<Genotype> wrap(Genome g) { return std::make_unique<GraphGenotype>(std::move(g)); }

}  // namespace

std::string_view GraphOps::kind() const { return GraphGenotype::kKind; }

std::unique_ptr<Genotype> GraphOps::random(Rng& rng) const { return wrap(random_genome(dialect_, ops_, rng)); }

std::unique_ptr<Genotype> GraphOps::mutate(const Genotype& g, double rate, Rng& rng) const {
  Genome child = genome_of(g);
  if (!ops_.reconcile_skill.empty())
    mutate_skill_wires(child, ops_.reconcile_skill, ops_, rate, rng);
  else
    bx::mutate(child, ops_, rate, rng);
  return wrap(std::move(child));
}

std::unique_ptr<Genotype> GraphOps::with_body_locked(const Genotype& g) const {
  Genome locked = genome_of(g);
  for (NodeGene& n : locked.nodes) n.lock |= kLockBody | kLockJoint | kLockInEdges | kLockOutEdges;
  return wrap(std::move(locked));
}

bool GraphOps::can_encapsulate() const { return !dialect_rules(dialect_).group_fn.empty(); }

Result<std::unique_ptr<Genotype>> GraphOps::with_skill_encapsulated(const Genotype& g, const SkillDef& skill,
                                                                    const std::vector<std::string>& uses) const {
  Genome out = genome_of(g);
  if (!skill.name.empty()) {
    auto e = encapsulate(out, skill);
    if (!e) return Error{e.error()};
    out = std::move(*e);
  }
  open_switches(out, uses);
  return wrap(std::move(out));
}

std::unique_ptr<Genotype> GraphOps::crossover(const Genotype& a, const Genotype& b, Rng& rng) const {
  if (!ops_.reconcile_skill.empty()) return wrap(cross_skill_wires(genome_of(a), genome_of(b), ops_.reconcile_skill, rng));
  return wrap(bx::crossover(genome_of(a), genome_of(b), ops_, rng));
}

std::unique_ptr<Genotype> GraphOps::graft(const Genotype& trunk, const Genotype& branch, Rng& rng) const {
  if (!ops_.reconcile_skill.empty())
    return wrap(cross_skill_wires(genome_of(trunk), genome_of(branch), ops_.reconcile_skill, rng));
  return wrap(bx::graft(genome_of(trunk), genome_of(branch), ops_, rng));
}

Status GraphOps::viable(const Genotype& g) const {
  const Genome& genome = genome_of(g);
  if (Status s = validate(genome); !s) return s;
  const Development d = develop(genome, develop_);
  if (!d.viable()) return Error{d.reason};
  return Ok{};
}

Result<std::unique_ptr<Genotype>> GraphOps::from_json(const nlohmann::json& j) const {
  auto g = genome_from_json(j, "genotype");
  if (!g) return Error{g.error()};
  if (g->dialect != dialect_)
    return Error{"genotype: dialect is " + std::string(to_string(g->dialect)) + ", the run's is " +
                 std::string(to_string(dialect_))};
  return wrap(std::move(*g));
}

}  // namespace bx
