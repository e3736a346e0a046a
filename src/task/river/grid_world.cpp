#include "task/river/grid_world.h"

#include <cassert>

namespace bx {
namespace {

bool kills(Cell c) { return c == Cell::Water || c == Cell::Trap; }

}  // namespace

GridWorld::GridWorld(Rng rng, int first_level)
    : rng_(rng), level_(first_level), layout_(make_layout(first_level, rng_)), agent_(layout_.start) {
  assert(first_level >= 1 && first_level <= kRiverLevels);
}

void GridWorld::enter(CellIndex c) {
  if (!alive()) return;
  // the edge is a wall, not a death: a 3D body can walk past it but cannot
  // sense it (the shunting model counts cells outside as 0, so nothing
  // repels it there), and the 2D code's gradient movement is clamped alike
  c = layout_.grid.clamp(c);
  if (c == agent_) return;
  // leaving a hazard that no act() has tested: it kills where it stood
  if (kills(under_agent())) {
    die(under_agent());
    return;
  }
  agent_ = c;
  switch (under_agent()) {
    case Cell::Food:
      score_ += 1;
      ++food_eaten_;
      layout_.grid.set(agent_, Cell::Grass);
      ++changes_;
      break;
    case Cell::Resource:
      score_ += 100;
      next_level();
      break;
    default:
      // water and traps meet their death test in act(), after its put-down
      break;
  }
}

void GridWorld::act(double action) {
  if (!alive()) return;
  const Cell here = under_agent();
  if (!carrying_ && action >= kPickUpAction && here == Cell::Stone) {
    carrying_ = true;
    layout_.grid.set(agent_, Cell::Grass);
    ++changes_;
  } else if (carrying_ && action <= kPutDownAction && here == Cell::Water) {
    carrying_ = false;
    layout_.grid.set(agent_, Cell::Grass);
    bridges_.push_back(agent_);
    ++changes_;
  }
  // the death test comes after the put-down: the agent stands on its bridge
  if (kills(under_agent())) die(under_agent());
}

int GridWorld::completions(int level) const {
  assert(level >= 1 && level <= kRiverLevels);
  return completions_[level - 1];
}

void GridWorld::next_level() {
  ++completions_[level_ - 1];
  ++levels_completed_;
  level_ = level_ % kRiverLevels + 1;
  // the stone carried stays with the old layout: each level starts afresh,
  // as each of the 2D code's worlds starts with a new animat
  layout_ = make_layout(level_, rng_);
  agent_ = layout_.start;
  carrying_ = false;
  bridges_.clear();
  ++changes_;
}

}  // namespace bx
