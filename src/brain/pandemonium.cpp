// Pandemonium: each group's largest output passes, the others read 0.
// Runs in every brain step: allocates nothing.
#include "brain/pandemonium.h"

#include <cassert>

namespace bx {

void apply_pandemonium(const BrainModel& m, std::span<double> values) {
  const int n_groups = m.n_groups();
  if (n_groups == 0) return;
  assert(m.group_begin.back() == m.group_member.size());
  double* v = values.data() + m.n_sensors;  // neuron outputs
  for (int g = 0; g < n_groups; ++g) {
    const std::uint32_t b = m.group_begin[g], e = m.group_begin[g + 1];
    if (b == e) continue;
    // one pass: the best so far stays, a member that beats it silences it;
    // strictly greater, so a tie keeps the earlier member (outputs are finite:
    // eval_neuron maps non-finite results to 0)
    std::int32_t best = m.group_member[b];
    assert(best >= 0 && best < m.n_neurons());
    for (std::uint32_t j = b + 1; j < e; ++j) {
      const std::int32_t k = m.group_member[j];
      assert(k >= 0 && k < m.n_neurons());
      if (v[k] > v[best]) {
        v[best] = 0;
        best = k;
      } else {
        v[k] = 0;
      }
    }
  }
}

}  // namespace bx
