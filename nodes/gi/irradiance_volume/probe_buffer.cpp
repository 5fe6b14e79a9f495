#include "nodes/gi/irradiance_volume/probe_buffer.h"

#include <glm/matrix.hpp>

namespace lg {

ProbeBuffers pack_probes(std::span<const ProbeGrid> grids) {
  ProbeBuffers out;
  for (const ProbeGrid& grid : grids) {
    GpuProbeVolume& v = out.volumes.emplace_back();
    // The grid's own matrices are private; these are the same from its public axes.
    const glm::dvec3 origin = grid.grid_position(0);
    glm::dmat4 world_from_grid(1.0);
    for (int a = 0; a < 3; ++a) world_from_grid[a] = glm::dvec4(grid.axis(a), 0.0);
    world_from_grid[3] = glm::dvec4(origin, 1.0);
    v.world_from_grid = glm::mat4(world_from_grid);
    v.grid_from_world = glm::mat4(glm::inverse(world_from_grid));
    v.counts = glm::ivec4(grid.counts(), int(out.probes.size()));
    v.cell = glm::vec4(float(grid.min_spacing()), 0.0f, 0.0f, 0.0f);
    for (size_t i = 0; i < grid.probes.size(); ++i) {
      const ProbeData& d = grid.probes[i];
      GpuProbe& p = out.probes.emplace_back();
      p.position = glm::vec4(glm::vec3(grid.grid_position(i) + glm::dvec3(d.offset)), d.active ? 1.0f : 0.0f);
      for (int c = 0; c < kProbeShCount; ++c) p.sh[c] = glm::vec4(d.sh[size_t(c)], 0.0f);
      for (int c = 0; c < 6; ++c) p.ambient_cube[c] = glm::vec4(d.ambient_cube[size_t(c)], 0.0f);
      for (size_t t = 0; t < d.irradiance.size(); ++t) p.irradiance[t] = glm::vec4(d.irradiance[t], 0.0f);
      for (size_t t = 0; t < d.distance.size(); ++t) p.distance[t] = d.distance[t];
    }
  }
  return out;
}

}  // namespace lg
