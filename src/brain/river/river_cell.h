// The cell kinds the river crossing's controller tells apart (Stanton &
// Channon 2015, after Robinson et al. 2007), by the integer codes the world
// passes in. The codes are also the order of the decision network's one-hot
// inputs and of the iotas, so they are fixed, not configurable.
#pragma once

namespace bx::river_cell {

/// Neutral ground; its iota is always 0.
inline constexpr int kGrass = 0;
/// The goal. The world passes its food cells under this code too.
inline constexpr int kResource = 1;
/// A stone that can be picked up.
inline constexpr int kStone = 2;
/// Water: kills, and becomes a bridge (grass) when a stone is put down on it.
inline constexpr int kWater = 3;
/// A trap: kills.
inline constexpr int kTrap = 4;
/// How many kinds there are.
inline constexpr int kCount = 5;

}  // namespace bx::river_cell
