// Irradiance at a surface point from the probes around it, on the CPU in double precision (what
// gi.irradiance_volume does per pixel, and how benchmarks measure the representations against
// the path-traced reference). As DDGI: the eight probes of the cell around the point moved off
// the surface (by `normal_bias` cells along the normal and `view_bias` cells toward the eye),
// each weighted by its trilinear weight, a wrap weight ((1 + cos)/2)^2 + 0.2 of the angle
// between the normal and the direction to the probe, and, with `visibility`, the Chebyshev bound
// of its distance moments that the point is in its view (at least 0.05); weights under 0.2 are
// crushed by their cube, so that a probe barely seen does not bleed. Probes that are off count
// nothing. nodes/gi/irradiance_volume/shaders/probe_volume.glsl is the GLSL port of this file:
// change one, change the other.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <span>
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

// A volume serves its box grown by half a cell in full (the outermost probes still serve there: a
// volume whose probes sit half a cell inside a room's walls covers the walls) and fades out over
// the next kVolumeBlendRamp cells, so that overlapping volumes blend continuously and each ends
// without a seam. The fade lies outside the fully served box, so that a denser grid of the same
// box, whose half cell is narrower, does not fade its walls toward the fallback.
inline constexpr double kVolumeServedCells = 0.5;
inline constexpr double kVolumeBlendRamp = 0.25;

// Cells from grid coordinates `g` to the fade's outer edge (negative beyond it): at least
// kVolumeBlendRamp where the volume serves in full.
double volume_margin(glm::dvec3 g, glm::ivec3 counts);

// Irradiance at `position` with unit normal n, seen from `eye`; nullopt beyond the fade's outer
// edge or when no probe around the point is on.
std::optional<glm::dvec3> lookup_irradiance(const ProbeGrid& grid, glm::dvec3 position, glm::dvec3 n, glm::dvec3 eye,
                                            const ProbeLookupSettings& settings);

// Several volumes: each one's irradiance weighted by smoothstep(0, kVolumeBlendRamp, margin).
// coverage is the weights' sum, at most 1: 0 outside every volume (or where none has a probe on),
// 1 wherever a volume serves in full.
struct VolumeIrradiance {
  glm::dvec3 irradiance{0.0};
  double coverage = 0.0;
};
VolumeIrradiance lookup_volumes(std::span<const ProbeGrid> grids, glm::dvec3 position, glm::dvec3 n, glm::dvec3 eye,
                                const ProbeLookupSettings& settings);

}  // namespace lg
