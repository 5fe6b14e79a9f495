#include "nodes/gi/common/cell_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace lg {

CellGrid fit_cell_grid(const Bounds& box, int cells_on_longest_side) {
  const glm::vec3 extent = box.max - box.min;
  const int n = std::max(cells_on_longest_side, 1);
  CellGrid g;
  g.cell = std::max(std::max({extent.x, extent.y, extent.z}) / float(n), 1e-3f);
  for (int a = 0; a < 3; ++a) g.counts[a] = std::clamp(int(std::ceil(extent[a] / g.cell - 1e-4f)), 1, n);
  g.origin = box.center() - 0.5f * g.cell * glm::vec3(g.counts);
  return g;
}

CellGrid fit_power_of_two_grid(const Bounds& box, int cells_on_longest_side) {
  CellGrid g = fit_cell_grid(box, cells_on_longest_side);
  for (int a = 0; a < 3; ++a) g.counts[a] = int(std::bit_ceil(unsigned(g.counts[a])));
  g.origin = box.center() - 0.5f * g.cell * glm::vec3(g.counts);
  return g;
}

}  // namespace lg
