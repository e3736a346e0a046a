// Pandemonium (lessin2015 IV-C) as a stage of brain_step, on hand-built
// lessin2015 brains: in each group only the largest sigma passes, the others
// read 0, for the effectors of the same step and the neurons of the next.
#include "brain/pandemonium.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "brain/brain_model.h"

namespace bx {
namespace {

/// Builds a lessin2015 BrainModel one neuron, effector and group at a time.
struct Builder {
  BrainModel m;

  explicit Builder(int n_sensors) {
    m.set = NeuronSetId::Lessin2015;
    m.n_sensors = n_sensors;
    m.param_begin = {0};
    m.state_begin = {0};
    m.input_begin = {0};
    m.effector_input_begin = {0};
  }
  /// Adds a sigma (weighted sum of its inputs plus bias); inputs are (slot,
  /// weight). Returns its neuron index (its value slot is n_sensors + it).
  int sigma(double bias, std::vector<std::pair<int, double>> inputs = {}) {
    const NeuronFnSpec* f = find_neuron_fn(m.set, "sigma");
    if (!f) throw std::runtime_error("no sigma");
    m.fn.push_back(f->id);
    m.bias.push_back(bias);
    m.param_begin.push_back(static_cast<std::uint32_t>(m.params.size()));
    m.state_begin.push_back(m.state_begin.back());
    for (auto [src, w] : inputs) {
      m.input_src.push_back(src);
      m.input_weight.push_back(w);
    }
    m.input_begin.push_back(static_cast<std::uint32_t>(m.input_src.size()));
    m.neuron_part.push_back(-1);
    return m.n_neurons() - 1;
  }
  int slot(int neuron) const { return m.n_sensors + neuron; }
  /// Adds an effector reading one slot with weight 1; returns its index.
  int effector(int src) {
    m.effector_bias.push_back(0);
    m.effector_input_src.push_back(src);
    m.effector_input_weight.push_back(1.0);
    m.effector_input_begin.push_back(static_cast<std::uint32_t>(m.effector_input_src.size()));
    return m.n_effectors() - 1;
  }
  /// Adds a group of these neurons, in this order.
  void group(std::vector<int> members) {
    if (m.group_begin.empty()) m.group_begin = {0};
    m.group_member.insert(m.group_member.end(), members.begin(), members.end());
    m.group_begin.push_back(static_cast<std::uint32_t>(m.group_member.size()));
  }
};

constexpr double kDt = 1.0 / 60;

std::vector<double> neuron_values(const BrainModel& m, const BrainState& s) {
  return {s.values.begin() + m.n_sensors, s.values.end()};
}

// three sigmas of biases 0.2, 0.7 and 0.5 in one group, a 0.9 sigma alone in
// another, an ungrouped 0.4 sigma; effectors read the first three; a sigma
// reads the suppressed 0.5 one
TEST(Pandemonium, OnlyTheLargestOfAGroupPassesForEffectorsAndTheNextStep) {
  Builder b(1);
  const int a = b.sigma(0.2), c = b.sigma(0.7), d = b.sigma(0.5);
  const int alone = b.sigma(0.9), ungrouped = b.sigma(0.4);
  const int reader = b.sigma(0, {{b.slot(d), 1.0}});
  b.group({a, c, d});
  b.group({alone});
  const int ea = b.effector(b.slot(a)), ec = b.effector(b.slot(c)), ed = b.effector(b.slot(d));
  const BrainModel& m = b.m;
  ASSERT_EQ(m.n_groups(), 2);

  BrainState s = make_brain_state(m);
  brain_step(m, s, kDt);
  // the reader read the zeros of the fresh state
  EXPECT_EQ(neuron_values(m, s), (std::vector<double>{0, 0.7, 0, 0.9, 0.4, 0}));
  EXPECT_EQ(s.effector_out[ea], 0.0);  // reads the suppressed sigma
  EXPECT_EQ(s.effector_out[ec], 0.7);
  EXPECT_EQ(s.effector_out[ed], 0.0);
  EXPECT_EQ(s.values[b.slot(alone)], 0.9);  // a group of one always passes
  EXPECT_EQ(s.values[b.slot(ungrouped)], 0.4);
  brain_step(m, s, kDt);
  EXPECT_EQ(s.values[b.slot(reader)], 0.0);  // 0.5 was computed, 0 was published
  EXPECT_EQ(neuron_values(m, s), (std::vector<double>{0, 0.7, 0, 0.9, 0.4, 0}));

  // the same brain without groups: every sigma passes
  BrainModel open = m;
  open.group_begin.clear();
  open.group_member.clear();
  BrainState t = make_brain_state(open);
  brain_step(open, t, kDt);
  brain_step(open, t, kDt);
  EXPECT_EQ(neuron_values(open, t), (std::vector<double>{0.2, 0.7, 0.5, 0.9, 0.4, 0.5}));
  EXPECT_EQ(t.effector_out[ea], 0.2);
  EXPECT_EQ(t.effector_out[ed], 0.5);
}

// equal outputs: the first in the group's order passes, whatever the
// neurons' order in the brain
TEST(Pandemonium, ATieGoesToTheFirstMemberInTheGroupsOrder) {
  Builder b(0);
  const int x = b.sigma(0.6), y = b.sigma(0.3), z = b.sigma(0.6);
  b.group({x, y, z});
  BrainState s = make_brain_state(b.m);
  brain_step(b.m, s, kDt);
  EXPECT_EQ(neuron_values(b.m, s), (std::vector<double>{0.6, 0, 0}));

  Builder r(0);
  for (double bias : {0.6, 0.3, 0.6}) r.sigma(bias);
  r.group({z, x, y});
  BrainState t = make_brain_state(r.m);
  brain_step(r.m, t, kDt);
  EXPECT_EQ(neuron_values(r.m, t), (std::vector<double>{0, 0, 0.6}));

  // all silent: the first keeps its 0, the others are 0 too
  Builder q(0);
  q.sigma(0);
  q.sigma(0);
  q.group({1, 0});
  BrainState u = make_brain_state(q.m);
  brain_step(q.m, u, kDt);
  EXPECT_EQ(neuron_values(q.m, u), (std::vector<double>{0, 0}));
}

// a sigma driven by a sensor against a constant 0.5 sigma: the winner
// follows the sensor from step to step; a tie at 0.5 goes to the first
TEST(Pandemonium, TheWinnerChangesWhenTheInputsDo) {
  Builder b(1);
  const int driven = b.sigma(0, {{0, 1.0}}), steady = b.sigma(0.5);
  b.group({driven, steady});
  const int e_driven = b.effector(b.slot(driven)), e_steady = b.effector(b.slot(steady));
  const BrainModel& m = b.m;
  BrainState s = make_brain_state(m);
  struct Row {
    double sensor, driven, steady;
  };
  for (Row r : {Row{0.2, 0, 0.5}, Row{0.8, 0.8, 0}, Row{0.3, 0, 0.5}, Row{0.5, 0.5, 0}, Row{1.0, 1.0, 0}}) {
    s.values[0] = r.sensor;
    brain_step(m, s, kDt);
    EXPECT_EQ(s.values[b.slot(driven)], r.driven) << "sensor " << r.sensor;
    EXPECT_EQ(s.values[b.slot(steady)], r.steady) << "sensor " << r.sensor;
    EXPECT_EQ(s.effector_out[e_driven], r.driven) << "sensor " << r.sensor;
    EXPECT_EQ(s.effector_out[e_steady], r.steady) << "sensor " << r.sensor;
  }
}

// the stage on its own: sensor slots are never touched, and a model with an
// explicit but empty group list (group_begin {0}) changes nothing
TEST(Pandemonium, TheStageTouchesOnlyItsGroupsNeuronSlots) {
  Builder b(2);
  for (int k = 0; k < 3; ++k) b.sigma(0);
  b.group({0, 2});
  std::vector<double> values{0.9, 0.8, 0.1, 0.4, 0.3};  // two sensors, three neurons
  apply_pandemonium(b.m, values);
  EXPECT_EQ(values, (std::vector<double>{0.9, 0.8, 0, 0.4, 0.3}));

  Builder none(2);
  none.sigma(0);
  none.m.group_begin = {0};
  EXPECT_EQ(none.m.n_groups(), 0);
  std::vector<double> v{0.9, 0.8, 0.1};
  apply_pandemonium(none.m, v);
  EXPECT_EQ(v, (std::vector<double>{0.9, 0.8, 0.1}));
}

}  // namespace
}  // namespace bx
