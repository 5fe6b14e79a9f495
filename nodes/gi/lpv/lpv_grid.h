// Where gi.lpv's grid lies: cubic cells over a box, as many along its longest side as the node's
// `grid` param asks and proportionally fewer along the others, the cells centred on the box.
// Cell (i, j, k) spans origin + cell x [i, i + 1] x [j, j + 1] x [k, k + 1].
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>

#include "runtime/scene/mesh_tools.h"

namespace lg {

struct LpvGrid {
  glm::vec3 origin{0.0f};
  float cell = 1.0f;  // edge of a cell, metres
  glm::ivec3 counts{1};

  size_t cell_count() const { return size_t(counts.x) * size_t(counts.y) * size_t(counts.z); }
};

// `box` must not be empty; a flat or degenerate side still gets one cell, and a box of no size
// at all a cell of 1 mm.
LpvGrid fit_lpv_grid(const Bounds& box, int cells_on_longest_side);

}  // namespace lg
