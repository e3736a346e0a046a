// The river crossing's hybrid controller (Stanton & Channon 2015, "Neural
// Architecture", Fig. 2) as one object per evaluation: the decision network
// sets the iotas, the shunting model turns them and the grid into a
// landscape, and each step the physical network reads the landscape at the
// four sensors and drives the pattern generator, whose motor neurons give
// the joints' targets. Pure math: it knows cell codes and points in cell
// widths, no world and no body. docs/rivercrossing.md ("The controller") gives every
// rule and the choices where the paper is silent.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "brain/river/decision_network.h"
#include "brain/river/pattern_generator.h"
#include "brain/river/physical_network.h"
#include "brain/river/river_genome.h"
#include "brain/river/shunting_model.h"
#include "core/result.h"

namespace bx {

/// Who sets the resource's iota (config river.resource_iota).
enum class ResourceIota {
  Decided,  ///< the decision network, as every other iota (the paper)
  /// 1 whatever the decision network decides (food, passed as the resource,
  /// too): the landscape always shows the resource, so a walker cannot
  /// escape its senses by a flat landscape (no sensor flagged: one constant
  /// drive). Ours, a bootstrap (docs/rivercrossing.md, "What evolves on one
  /// machine").
  Shown,
};

/// The controller's constants: layer sizes, the shunting model's, and who
/// sets the resource's iota.
struct RiverBrainDef {
  RiverShape shape;
  ShuntingDef landscape;
  ResourceIota resource_iota = ResourceIota::Decided;
  friend bool operator==(const RiverBrainDef&, const RiverBrainDef&) = default;
};

/// One individual's controller, immutable and shared by its evaluations:
/// the constants, the pre-evolved motif and the weights from its genes.
struct RiverBrainModel {
  RiverBrainDef def;
  Motif motif;
  RiverWeights weights;
};

/// A model from a def, a motif and a genome; an error naming the field and
/// value of a bad def or motif, or the expected and given gene counts.
Result<RiverBrainModel> make_river_brain_model(const RiverBrainDef& def, const Motif& motif,
                                               std::span<const double> genes);

/// The controller during one evaluation. It starts on an all-grass grid
/// with every iota 0, so an all-zero landscape, the motifs at rest and the
/// motors at the motifs' resting outputs. The landscape always reflects the
/// last grid and the last decision: it is recomputed, from zero, exactly when
/// either changes.
class RiverBrain {
 public:
  /// Copies what it needs from the model.
  explicit RiverBrain(const RiverBrainModel& m);

  /// Runs the DN on the code of the cell the agent stands on (river_cell)
  /// and whether it carries a stone (unless both are the last call's: the
  /// same inputs give the same decision); when the iotas change, recomputes
  /// the landscape. Returns whether the iotas changed. (Under
  /// ResourceIota::Shown the landscape's resource iota is 1 whatever the
  /// decision says.)
  bool decide(int cell, bool carrying);
  /// The grid: a river_cell code per cell, row-major (cell (i, j) at
  /// j * width + i); the caller passes food as kResource. When it differs
  /// from the last grid, recomputes the landscape. Returns whether it did.
  bool set_grid(std::span<const int> cells);
  /// One controller step of `dt` seconds: the landscape at the four sensors
  /// (points in cell widths, in a fixed sensor order), divided by maxI, into
  /// the PN; the PN's outputs into one Euler step of the PG; the motors.
  void step(std::span<const GridPoint> sensors, double dt);

  /// The last decision's action: 1 pick up, -1 put down, 0 neither.
  int action() const { return dn_.decision().action; }
  /// The last decision: the action and the iotas by cell code.
  const Decision& decision() const { return dn_.decision(); }
  /// The decision network and its last values.
  const DecisionNetwork& dn() const { return dn_; }
  /// The landscape (its values() and inputs() are row-major by cell).
  const ShuntingModel& landscape() const { return sm_; }
  /// The physical network and its last values; its inputs() start with the
  /// sensors' normalised readings.
  const PhysicalNetwork& pn() const { return pn_; }
  /// The pattern generator: motifs, their outputs and the motors.
  const PatternGenerator& pg() const { return pg_; }
  /// Each motor neuron's value in (0, 1), one per joint degree of freedom.
  std::span<const double> motors() const { return pg_.motors(); }

 private:
  DecisionNetwork dn_;
  ShuntingModel sm_;
  PhysicalNetwork pn_;
  PatternGenerator pg_;
  std::vector<int> grid_;
  bool show_resource_;  // ResourceIota::Shown
  // the iotas the landscape was last shaped with: the decision's, or under
  // ResourceIota::Shown with the resource's 1
  std::array<int, river_cell::kCount> iota_{};
  // the DN's last inputs (decide() runs it again only when they change)
  bool decided_ = false;
  int cell_ = 0;
  bool carrying_ = false;
};

}  // namespace bx
