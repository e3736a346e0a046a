#include "genome/reconcile.h"

#include <algorithm>
#include <vector>

namespace bx {

namespace {

// calls f on every input gated by switch `gate`, in genome order: the nodes'
// effectors, then the global neurons (the switches of the skills it drives)
template <class G, class F>
void each_wire(G& g, int gate, F f) {
  for (auto& n : g.nodes)
    for (auto& ef : n.effectors)
      for (auto& in : ef.inputs)
        if (in.gate == gate) f(in);
  for (auto& nr : g.global_neurons)
    for (auto& in : nr.inputs)
      if (in.gate == gate) f(in);
}

}  // namespace

int skill_switch(const Genome& g, std::string_view skill) {
  for (int k = 0; k < static_cast<int>(g.global_neurons.size()); ++k)
    if (!skill.empty() && g.global_neurons[k].skill == skill) return k;
  return -1;
}

int skill_wire_count(const Genome& g, std::string_view skill) {
  const int gate = skill_switch(g, skill);
  if (gate < 0) return 0;
  int n = 0;
  each_wire(g, gate, [&](const InputGene&) { ++n; });
  return n;
}

void mutate_skill_wires(Genome& g, std::string_view skill, const OperatorDef& def, double rate, Rng& rng) {
  const int gate = skill_switch(g, skill);
  if (gate < 0) return;
  const Range w = weight_bounds(def, g.dialect);
  each_wire(g, gate, [&](InputGene& in) {
    if (rng.chance(rate)) in.weight = std::clamp(in.weight + normal(rng) * def.param_sigma * (w.hi - w.lo), w.lo, w.hi);
  });
}

Genome cross_skill_wires(const Genome& a, const Genome& b, std::string_view skill, Rng& rng) {
  Genome child = a;
  const int gate = skill_switch(a, skill);
  if (gate < 0 || gate != skill_switch(b, skill)) return child;
  std::vector<double> theirs;
  each_wire(b, gate, [&](const InputGene& in) { theirs.push_back(in.weight); });
  if (static_cast<int>(theirs.size()) != skill_wire_count(a, skill)) return child;
  std::size_t k = 0;
  each_wire(child, gate, [&](InputGene& in) {
    if (rng.chance(0.5)) in.weight = theirs[k];
    ++k;
  });
  return child;
}

}  // namespace bx
