#include "brain/river/river_brain.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <utility>

namespace bx {

Result<RiverBrainModel> make_river_brain_model(const RiverBrainDef& def, const Motif& motif,
                                               std::span<const double> genes) {
  if (Status ok = check_shunting_def(def.landscape); !ok) return Error{ok.error()};
  if (Status ok = check_motif(motif); !ok) return Error{ok.error()};
  Result<RiverWeights> w = unpack_river_genes(def.shape, genes);
  if (!w) return Error{w.error()};
  return RiverBrainModel{def, motif, std::move(*w)};
}

RiverBrain::RiverBrain(const RiverBrainModel& m)
    : dn_(m.weights.dn_input_hidden, m.weights.dn_hidden_output),
      sm_(m.def.landscape),
      pn_(m.weights.pn_input_hidden, m.weights.pn_hidden_output),
      pg_(m.motif, m.weights.pg_input, m.weights.pg_motor),
      grid_(sm_.values().size(), river_cell::kGrass),
      show_resource_(m.def.resource_iota == ResourceIota::Shown) {}

bool RiverBrain::decide(int cell, bool carrying) {
  // the DN is a function of these two inputs: the same ones, the same decision
  if (decided_ && cell == cell_ && carrying == carrying_) return false;
  decided_ = true;
  cell_ = cell;
  carrying_ = carrying;
  std::array<int, river_cell::kCount> iota = dn_.decide(cell, carrying).iota;
  if (show_resource_) iota[river_cell::kResource] = 1;
  if (iota == iota_) return false;
  iota_ = iota;
  sm_.shape(grid_, iota_);
  return true;
}

bool RiverBrain::set_grid(std::span<const int> cells) {
  assert(cells.size() == grid_.size());
  if (std::equal(cells.begin(), cells.end(), grid_.begin())) return false;
  std::copy(cells.begin(), cells.end(), grid_.begin());
  sm_.shape(grid_, iota_);
  return true;
}

void RiverBrain::step(std::span<const GridPoint> sensors, double dt) {
  assert(static_cast<int>(sensors.size()) == kRiverSensors);
  // the landscape under each sensor, normalised by maxI
  std::array<double, kRiverSensors> readings{};
  for (std::size_t k = 0; k < readings.size(); ++k)
    readings[k] = sm_.activity_at(sensors[k]) / sm_.def().max_activity;
  pg_.step(pn_.run(readings), dt);
}

}  // namespace bx
