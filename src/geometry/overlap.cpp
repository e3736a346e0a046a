// Overlap of solids at rest (geometry/overlap.h).
#include "geometry/overlap.h"

#include <algorithm>
#include <array>
#include <vector>

#include "geometry/ode.h"

namespace bx {

std::pair<int, int> first_overlap(std::span<const Solid> solids, double margin) {
  ensure_ode_initialized();
  int n = static_cast<int>(solids.size());
  std::vector<dGeomID> geoms(n);
  std::vector<std::array<double, 6>> box(n);  // AABB: min x, max x, min y, max y, min z, max z
  for (int i = 0; i < n; ++i) {
    geoms[i] = make_geom(nullptr, solids[i].shape, solids[i].size, margin);
    place_geom(geoms[i], solids[i].shape, solids[i].pose);
    dGeomGetAABB(geoms[i], box[i].data());
    // widened a little: colliders may report touching within rounding
    for (int a = 0; a < 3; ++a) {
      double pad = 1e-9 * (1 + box[i][2 * a + 1] - box[i][2 * a]);
      box[i][2 * a] -= pad;
      box[i][2 * a + 1] += pad;
    }
  }
  // sweep along the axis where the parts spread most
  int axis = 0;
  double best = -1;
  for (int a = 0; a < 3; ++a) {
    double lo = 1e300, hi = -1e300;
    for (const auto& b : box) lo = std::min(lo, b[2 * a]), hi = std::max(hi, b[2 * a + 1]);
    if (hi - lo > best) best = hi - lo, axis = a;
  }
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return box[a][2 * axis] < box[b][2 * axis] || (box[a][2 * axis] == box[b][2 * axis] && a < b);
  });
  auto overlap = [&](int i, int j) {
    for (int a = 0; a < 3; ++a)
      if (box[i][2 * a] > box[j][2 * a + 1] || box[j][2 * a] > box[i][2 * a + 1]) return false;
    return true;
  };
  // solids joined by a joint may touch
  auto joined = [&](int i, int j) { return solids[j].joined_to == i || solids[i].joined_to == j; };
  dContactGeom contact;
  auto collide = [&](int i, int j) { return dCollide(geoms[i], geoms[j], 1, &contact, sizeof(dContactGeom)) > 0; };
  // candidate pairs (i < j) whose boxes overlap, tested in all-pairs order;
  // parts piled up in one place (more pairs to look at than the budget) are
  // tested pair by pair instead, where the first few usually overlap
  const std::size_t budget = 64 * static_cast<std::size_t>(n) + 4096;
  std::size_t looked = 0;
  std::vector<std::pair<int, int>> pairs;
  for (int s = 0; s < n && looked <= budget; ++s) {
    int i = order[s];
    for (int t = s + 1; t < n && box[order[t]][2 * axis] <= box[i][2 * axis + 1]; ++t) {
      int j = order[t];
      ++looked;
      if (overlap(i, j) && !joined(i, j)) pairs.push_back({std::min(i, j), std::max(i, j)});
    }
  }
  std::pair<int, int> hit{-1, -1};
  if (looked <= budget) {
    std::sort(pairs.begin(), pairs.end());
    for (auto [i, j] : pairs)
      if (collide(i, j)) {
        hit = {i, j};
        break;
      }
  } else {
    for (int i = 0; i < n && hit.first < 0; ++i)
      for (int j = i + 1; j < n; ++j)
        if (!joined(i, j) && collide(i, j)) {
          hit = {i, j};
          break;
        }
  }
  for (dGeomID g : geoms) dGeomDestroy(g);
  return hit;
}

}  // namespace bx
