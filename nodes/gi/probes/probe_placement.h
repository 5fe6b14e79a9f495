// Where a probe sits (DDGI's classification and relocation), shared by the bake and the dynamic
// update: a geometric pass of `count` rays counts the back faces the probe sees; more than a
// quarter means it sits inside geometry, and it moves toward the nearest back face it saw,
// through it; one closer to a front face than a tenth of a cell moves away from it. Offsets stay
// within half a cell along each axis of the grid; a probe still inside after three tries is off.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "nodes/gi/probes/probe_grid.h"
#include "nodes/raytrace/ray_scene.h"

namespace lg {

// Whether probe `index` ends outside geometry; `offset` (world space) is where it moved.
bool place_probe(const RayScene& rays, const ProbeGrid& grid, size_t index, uint32_t count, const glm::dmat3& rotation,
                 glm::dvec3& offset);

}  // namespace lg
