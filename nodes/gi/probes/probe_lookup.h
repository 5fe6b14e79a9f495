// Irradiance at a surface point from the probes around it, on the CPU in double precision (what
// gi.irradiance_volume does per pixel, and how benchmarks measure the representations against
// the path-traced reference). As DDGI: the eight probes of the cell around the point moved off
// the surface (by `normal_bias` cells along the normal and `view_bias` cells toward the eye),
// each weighted by its trilinear weight, a wrap weight ((1 + cos)/2)^2 + 0.2 of the angle
// between the normal and the direction to the probe, and, with `visibility`, the Chebyshev bound
// of its distance moments that the point is in its view (at least 0.05); weights under 0.2 are
// crushed by their cube, so that a probe barely seen does not bleed. Probes that are off count
// nothing.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "nodes/gi/probes/probe_grid.h"

namespace lg {

enum class ProbeRepresentation { sh_l1, sh_l2, ambient_cube, octahedral };
const char* probe_representation_name(ProbeRepresentation r);
std::optional<ProbeRepresentation> parse_probe_representation(const std::string& name);

struct ProbeLookupSettings {
  ProbeRepresentation representation = ProbeRepresentation::octahedral;
  bool visibility = true;
  double normal_bias = 0.1;  // in cells (the grid's smallest spacing)
  double view_bias = 0.3;
};

// One probe's irradiance for normal n in the chosen form.
glm::dvec3 probe_irradiance(const ProbeData& probe, glm::dvec3 n, ProbeRepresentation representation);

// Irradiance at `position` with unit normal n, seen from `eye`; nullopt outside the grid's box
// grown by half a cell (where the outermost probes still serve: a volume whose probes sit half a
// cell inside a room's walls covers the room) or when no probe around the point is on.
std::optional<glm::dvec3> lookup_irradiance(const ProbeGrid& grid, glm::dvec3 position, glm::dvec3 n, glm::dvec3 eye,
                                            const ProbeLookupSettings& settings);

}  // namespace lg
