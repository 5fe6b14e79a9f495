#include "nodes/gi/lpv/lpv_grid.h"

#include <algorithm>
#include <cmath>

namespace lg {

LpvGrid fit_lpv_grid(const Bounds& box, int cells_on_longest_side) {
  const glm::vec3 extent = box.max - box.min;
  const int n = std::max(cells_on_longest_side, 1);
  LpvGrid g;
  g.cell = std::max(std::max({extent.x, extent.y, extent.z}) / float(n), 1e-3f);
  for (int a = 0; a < 3; ++a) g.counts[a] = std::clamp(int(std::ceil(extent[a] / g.cell - 1e-4f)), 1, n);
  g.origin = box.center() - 0.5f * g.cell * glm::vec3(g.counts);
  return g;
}

}  // namespace lg
