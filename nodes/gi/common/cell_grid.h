// Where the grids of gi.lpv and gi.voxel lie: cubic cells over a box, as many along its longest
// side as the node asks and proportionally fewer along the others, the cells centred on the box.
// Cell (i, j, k) spans origin + cell x [i, i + 1] x [j, j + 1] x [k, k + 1].
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>

#include "runtime/scene/mesh_tools.h"

namespace lg {

struct CellGrid {
  glm::vec3 origin{0.0f};
  float cell = 1.0f;  // edge of a cell, metres
  glm::ivec3 counts{1};

  size_t cell_count() const { return size_t(counts.x) * size_t(counts.y) * size_t(counts.z); }
};

// `box` must not be empty; a flat or degenerate side still gets one cell, and a box of no size
// at all a cell of 1 mm.
CellGrid fit_cell_grid(const Bounds& box, int cells_on_longest_side);

// fit_cell_grid with every count rounded up to a power of two (at most `cells_on_longest_side`,
// itself a power of two), the grid still centred on the box: each level of a mip chain then
// halves every count above 1 exactly, so a texel of any level covers the same world box as the
// eight (or fewer) below it.
CellGrid fit_power_of_two_grid(const Bounds& box, int cells_on_longest_side);

}  // namespace lg
