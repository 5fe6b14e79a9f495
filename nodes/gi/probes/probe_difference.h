// How far one set of probes is from another (a reference, e.g. a full bake), two ways:
// - per texel: the RMS difference of the octahedral irradiance over every texel and colour
//   channel of the probes on in both, over the reference's mean there (what each probe stores,
//   its noise included);
// - looked up: the RMS difference of what lookup_volumes() gives (irradiance x coverage) at
//   surface points the volumes serve, over the reference's mean there (what surfaces receive;
//   the lookup averages neighbouring probes and texels, so each probe's noise counts less).
// What the dynamic update's convergence is measured by (tests, lumagraph-bench-probe-update).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "nodes/gi/path_tracer/path_scene.h"
#include "nodes/gi/probes/probe_grid.h"
#include "nodes/gi/probes/probe_lookup.h"

namespace lg {

// The grids must be the same volumes; 0 when no probe is on in both.
double probe_relative_rms(std::span<const ProbeGrid> probes, std::span<const ProbeGrid> reference);

struct ServedPoint {
  glm::dvec3 position, normal, eye;
};

// The surfaces that `per_probe` rays (a turned spherical Fibonacci set) from each probe that is on
// meet first, each seen from its probe.
std::vector<ServedPoint> served_points(const PathScene& scene, std::span<const ProbeGrid> grids, uint32_t per_probe);

struct LookupDifference {
  double relative_rms = 0.0;
  double mean_ratio = 0.0;  // the probes' mean over the reference's: below 1 darker
};
LookupDifference lookup_difference(std::span<const ProbeGrid> probes, std::span<const ProbeGrid> reference,
                                   std::span<const ServedPoint> points, const ProbeLookupSettings& settings);

}  // namespace lg
