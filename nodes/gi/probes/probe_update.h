// Dynamic probe updates, DDGI's on the CPU (Majercik et al. 2019): each update re-traces a budget
// of probes, round robin over every volume's probes in order (update f takes the `budget` probes
// after update f-1's, wrapping), and blends what they see into what they hold.
//
// A probe's ray meets one surface (PathTransport::probe_hit: what it emits and reflects of the
// lights, the scene's and the sky's sun); the light of every further bounce comes from the probes
// themselves, looked up at the hit as gi.irradiance_volume looks them up for a pixel, times the
// surface's albedo / pi (DDGI's infinite-bounce feedback: each update carries light one bounce
// further; the albedo is the directional albedo's one-sample estimate, ProbeHit::albedo, so
// the specular lobe's share is not lost at every bounce). Escaping rays see the environment, as in the bake. The sums
// go through the bake's projection into every form (probe_projection.h), and each form blends as stored = lerp(new,
// stored, hysteresis): the distance moments too. A probe is placed again each time with the bake's rays and rotation
// (probe_placement.h), so in a scene that does not change it stays where the bake put it; one that comes out of
// geometry starts from its new value alone, one that goes into geometry is off. Rays turn by a new random rotation per
// update and probe, so repeated updates integrate different directions. All probes of one update read the probes as
// they were before it (any thread order gives the same result): deterministic per seed.
#pragma once

#include <cstdint>
#include <span>

#include "nodes/gi/path_tracer/path_scene.h"
#include "nodes/gi/probes/probe_grid.h"
#include "nodes/gi/probes/probe_lookup.h"

namespace lg {

struct ProbeUpdateSettings {
  uint32_t probes_per_update = 64;  // the budget, over all volumes together
  uint32_t rays = 128;              // per probe and update
  double hysteresis = 0.5;          // the weight of what a probe held
  uint32_t placement_rays = 256;    // the bake's `rays`, so that placement matches the bake's
  uint64_t seed = 1;                // the bake's seed (placement) and the updates' random sequence
  ProbeLookupSettings lookup{};     // how a hit reads the probes for its further bounces
};

// The probes update `frame` takes: from (frame x budget) mod the probe count, `budget` of them
// (all where the budget is larger), numbered over the grids one after another.
size_t first_updated_probe(std::span<const ProbeGrid> grids, const ProbeUpdateSettings& settings, uint64_t frame);

// Re-traces update `frame`'s probes on every core and blends them into `grids`.
void update_probes(const PathScene& scene, std::span<ProbeGrid> grids, const ProbeUpdateSettings& settings,
                   uint64_t frame);

}  // namespace lg
