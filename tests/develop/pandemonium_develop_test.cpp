// Development of pandemonium groups (lessin2015 IV-C): every developed copy
// of the neurons of one genome group forms one brain group, groups by id,
// members in development order; the developed brain then lets only each
// group's largest sigma through to the muscles.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "brain/brain_model.h"
#include "develop/develop.h"
#include "genome/genome_json.h"
#include "support/creatures.h"

namespace bx {
namespace {

// a root with two sigmas of group 3 (0.2, 0.7), an ungrouped constant and a
// sigma of group 1 (0.9); a limb grown twice (reflected) with a sigma of
// group 3 (0.5) and two muscles, reading the root's first and second sigma;
// a global sigma of group 1 (0.1)
constexpr const char* kGrouped = R"({
  "format": "bestiary-genome", "version": 1, "dialect": "lessin2015",
  "nodes": [
    {
      "shape": "box", "size": [0.4, 0.2, 0.1],
      "neurons": [
        {"fn": "sigma", "bias": 0.2, "group": 3},
        {"fn": "constant", "params": {"V": 0.5}},
        {"fn": "sigma", "bias": 0.7, "group": 3},
        {"fn": "sigma", "bias": 0.9, "group": 1}
      ],
      "edges": [{"to": 1, "face": "+x", "at": [0.5, 0], "reflect": ["y"]}]
    },
    {
      "shape": "box", "size": [0.3, 0.1, 0.1],
      "joint": {"type": "hinge", "axis1": [0, 1, 0]},
      "neurons": [{"fn": "sigma", "bias": 0.5, "group": 3}],
      "effectors": [
        {"muscle": {"parent_dir": [1, 0, 1], "child_dir": [-1, 0, 1], "strength": 2000},
         "inputs": [{"from": "root", "neuron": 0}]},
        {"muscle": {"parent_dir": [1, 0.5, -1], "child_dir": [-1, 0.5, -1], "strength": 2000},
         "inputs": [{"from": "root", "neuron": 2}]}
      ]
    }
  ],
  "global_neurons": [{"fn": "sigma", "bias": 0.1, "group": 1}]
})";

CreatureModel grow(const Genome& g) {
  Development d = develop(g);
  EXPECT_TRUE(d.viable()) << d.reason;
  return d.viable() ? *d.model : CreatureModel{};
}

TEST(PandemoniumDevelop, EachGenomeGroupBecomesOneBrainGroupOfAllItsCopies) {
  auto g = genome_from_string(kGrouped, "grouped.json");
  ASSERT_TRUE(g.ok()) << g.error();
  CreatureModel m = grow(*g);
  const BrainModel& b = m.brain;
  // neurons in development order: the root's four (0-3), each limb copy's
  // sigma (4, 5), the global sigma (6)
  ASSERT_EQ(m.n_parts(), 3);
  ASSERT_EQ(b.n_neurons(), 7);
  EXPECT_EQ(b.neuron_part, (std::vector<std::int32_t>{0, 0, 0, 0, 1, 2, -1}));
  // group 1 (the root's 0.9 sigma, the global one), then group 3 (the root's
  // two, then each limb copy's)
  ASSERT_EQ(b.n_groups(), 2);
  EXPECT_EQ(b.group_begin, (std::vector<std::uint32_t>{0, 2, 6}));
  EXPECT_EQ(b.group_member, (std::vector<std::int32_t>{3, 6, 0, 2, 4, 5}));
  EXPECT_TRUE(m.warnings.empty());
}

TEST(PandemoniumDevelop, TheDevelopedBrainLetsOnlyEachGroupsLargestSigmaDriveTheMuscles) {
  auto g = genome_from_string(kGrouped, "grouped.json");
  ASSERT_TRUE(g.ok()) << g.error();
  CreatureModel m = grow(*g);
  const BrainModel& b = m.brain;
  BrainState s = make_brain_state(b);
  brain_step(b, s, 1.0 / 60);
  const std::vector<double> neurons(s.values.begin() + b.n_sensors, s.values.end());
  // group 3: 0.7 passes over 0.2 and the limbs' 0.5; group 1: 0.9 over 0.1
  EXPECT_EQ(neurons, (std::vector<double>{0, 0.5, 0.7, 0.9, 0, 0, 0}));
  // each limb's first muscle reads the suppressed 0.2 sigma, its second the 0.7
  ASSERT_EQ(b.n_effectors(), 4);
  EXPECT_EQ(s.effector_out, (std::vector<double>{0, 0.7, 0, 0.7}));
}

TEST(PandemoniumDevelop, AGenomeWithoutGroupsDevelopsABrainWithoutGroups) {
  CreatureModel m = grow(bxtest::load_creature("lessin_pair.json"));
  EXPECT_EQ(m.brain.n_groups(), 0);
  EXPECT_TRUE(m.brain.group_begin.empty());
  EXPECT_TRUE(m.brain.group_member.empty());
}

}  // namespace
}  // namespace bx
