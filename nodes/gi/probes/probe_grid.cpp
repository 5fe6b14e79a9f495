#include "nodes/gi/probes/probe_grid.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace lg {

size_t probe_count(const IrradianceVolumeData& volume) {
  return size_t(std::max(volume.probe_counts.x, 1)) * std::max(volume.probe_counts.y, 1) *
         std::max(volume.probe_counts.z, 1);
}

ProbeGrid::ProbeGrid(const IrradianceVolumeData& volume)
    : probes(lg::probe_count(volume)), volume_(volume), counts_(glm::max(volume.probe_counts, glm::ivec3(1))) {
  const glm::dvec3 size(volume.size);
  for (int a = 0; a < 3; ++a) spacing_[a] = counts_[a] > 1 ? size[a] / (counts_[a] - 1) : size[a];
  // Grid coordinates to the box's local frame: probe 0 at -size / 2 (the centre when alone).
  glm::dvec3 origin;
  for (int a = 0; a < 3; ++a) origin[a] = counts_[a] > 1 ? -0.5 * size[a] : 0.0;
  const glm::dmat4 local_from_grid = glm::scale(glm::translate(glm::dmat4(1.0), origin), spacing_);
  world_from_grid_ = glm::dmat4(volume.world) * local_from_grid;
  grid_from_world_ = glm::inverse(world_from_grid_);
  for (int a = 0; a < 3; ++a) axes_[a] = glm::dvec3(world_from_grid_[a]);
}

glm::ivec3 ProbeGrid::cell(size_t index) const {
  const int x = int(index % counts_.x), y = int(index / counts_.x % counts_.y), z = int(index / counts_.x / counts_.y);
  return {x, y, z};
}

glm::dvec3 ProbeGrid::grid_position(size_t index) const {
  return glm::dvec3(world_from_grid_ * glm::dvec4(glm::dvec3(cell(index)), 1.0));
}

double ProbeGrid::min_spacing() const {
  double m = 0.0;
  for (int a = 0; a < 3; ++a)
    if (const double l = glm::length(axes_[a]); l > 0.0) m = m > 0.0 ? std::min(m, l) : l;
  return m > 0.0 ? m : 1.0;  // a box of no size: any unit will do
}

glm::dvec3 ProbeGrid::grid_coordinates(glm::dvec3 world) const {
  return glm::dvec3(grid_from_world_ * glm::dvec4(world, 1.0));
}

}  // namespace lg
