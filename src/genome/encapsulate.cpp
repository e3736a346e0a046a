#include "genome/encapsulate.h"

#include <algorithm>

#include "brain/neuron_set.h"
#include "genome/dialect.h"
#include "genome/locks.h"

namespace bx {

namespace {

// The neuron set's constant function: a positional function without inputs
// whose one parameter is its output (lessin2015's "constant").
constexpr std::string_view kConstantFn = "constant";

// the index of a locked global constant-1 neuron of `g`, added if it has none
int constant_one(Genome& g) {
  for (int k = 0; k < static_cast<int>(g.global_neurons.size()); ++k) {
    const NeuronGene& nr = g.global_neurons[k];
    if (nr.locked && nr.skill.empty() && nr.fn == kConstantFn && nr.inputs.empty() && nr.params == std::vector{1.0})
      return k;
  }
  NeuronGene one;
  one.fn = std::string(kConstantFn);
  one.params = {1.0};
  one.locked = true;
  g.global_neurons.push_back(one);
  return static_cast<int>(g.global_neurons.size()) - 1;
}

// every ungated input of `ins` gated by `gate`, in place and order
void gate_all(std::vector<InputGene>& ins, int gate) {
  for (InputGene& in : ins)
    if (in.gate == InputGene::kNoGate) in.gate = gate;
}

}  // namespace

std::vector<std::string> skills_of(const Genome& g) {
  std::vector<std::string> out;
  for (const NeuronGene& nr : g.global_neurons)
    if (!nr.skill.empty()) out.push_back(nr.skill);
  return out;
}

Result<Genome> encapsulate(const Genome& g, const SkillDef& skill) {
  const DialectRules& r = dialect_rules(g.dialect);
  if (r.group_fn.empty() || !r.global_neurons)
    return Error{"encapsulate: dialect " + std::string(to_string(g.dialect)) + " has no skill switches"};
  const NeuronFnSpec* constant = find_neuron_fn(r.neuron_set, kConstantFn);
  if (!constant || constant->params.size() != 1 || constant->params[0].max < 1)
    return Error{"encapsulate: dialect " + std::string(to_string(g.dialect)) + " has no constant neuron of output 1"};
  if (skill.name.empty()) return Error{"encapsulate: a skill needs a name"};
  const std::vector<std::string> had = skills_of(g);
  if (std::find(had.begin(), had.end(), skill.name) != had.end())
    return Error{"encapsulate: the genome already has a skill named \"" + skill.name + "\""};

  Genome out = g;
  // the skill's neurons and sensors: everything the genome has learned; a
  // node whose units read through its edges keeps them, so each wire still
  // reads the part it read (genome/locks.h)
  for (NodeGene& node : out.nodes) {
    for (NeuronGene& nr : node.neurons) nr.locked = true;
    for (SensorGene& s : node.sensors) s.locked = true;
    auto reads_through = [&](const std::vector<InputGene>& ins) {
      for (const InputGene& in : ins) {
        if (in.place == SourcePlace::Child) node.lock |= kLockOutEdges;
        if (in.place == SourcePlace::Parent) node.lock |= kLockInEdges;
      }
    };
    for (const NeuronGene& nr : node.neurons) reads_through(nr.inputs);
    for (const EffectorGene& ef : node.effectors) reads_through(ef.inputs);
  }
  for (NeuronGene& nr : out.global_neurons)
    if (nr.skill.empty()) nr.locked = true;

  const int one = constant_one(out);
  NeuronGene sw;
  sw.fn = std::string(r.group_fn);
  sw.skill = skill.name;
  sw.group = skill.group;
  sw.locked = true;  // closed until a stage that uses it opens it (open_switches)
  out.global_neurons.push_back(sw);
  const int gate = static_cast<int>(out.global_neurons.size()) - 1;

  // the wires leaving the skill: into effectors (their bias with them) and
  // into the switches of the skills it drives
  for (NodeGene& node : out.nodes)
    for (EffectorGene& ef : node.effectors) {
      gate_all(ef.inputs, gate);
      if (ef.bias != 0) {
        InputGene bias;
        bias.place = SourcePlace::Global;
        bias.kind = SourceKind::Neuron;
        bias.index = one;
        bias.weight = ef.bias;
        bias.gate = gate;
        ef.inputs.insert(ef.inputs.begin(), bias);
        ef.bias = 0;
      }
      // a muscle no wire drives stays as it is, whole (a locked neuron may read its length)
      if (ef.inputs.empty()) ef.locked = true;
    }
  for (int k = 0; k < gate; ++k)
    if (!out.global_neurons[k].skill.empty()) gate_all(out.global_neurons[k].inputs, gate);
  return out;
}

void open_switches(Genome& g, const std::vector<std::string>& uses) {
  for (NeuronGene& nr : g.global_neurons) {
    if (nr.skill.empty()) continue;
    const bool used = std::find(uses.begin(), uses.end(), nr.skill) != uses.end();
    const bool has_free = gated_prefix(nr.inputs) < static_cast<int>(nr.inputs.size());
    nr.locked = !used && !has_free;
  }
}

}  // namespace bx
