// The river crossing's pre-evolved CTRNN motif, as our search found it.
#pragma once

#include "brain/river/pattern_generator.h"

namespace bx {

/// The motif the pattern generator copies until the motif run
/// (rivercrossing-motif) ships its own: found by the paper's search
/// (population 1000, tournaments of 3, 10^6 of them, seed 20150720:
/// MotifSearch.DISABLED_EvolveAMotif) under motif_fitness's measure; 1.00 Hz
/// under an input of 1, quiescent without (fitness 0.899; docs/rivercrossing.md,
/// "The motif's fitness").
inline Motif found_motif() {
  Motif m;
  m.w = {{{-0.78630925075382407, 3.6669557859373043, -4.7247363080404803},
          {-8.8162795527556366, 12.705745667407337, -7.2059718682943936},
          {15.864952637365167, 2.5488696262760624, -3.6057886851183731}}};
  m.tau = {1.7837384832752037, 0.39452987811361484, 0.19103254352260157};
  m.alpha = {-0.065087467485112405, -10.369384569603891, -2.148256443495506};
  m.input = 0;
  m.output = 2;
  return m;
}

}  // namespace bx
