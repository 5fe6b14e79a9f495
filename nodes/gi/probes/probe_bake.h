// Baking the probes of irradiance volumes with the path tracer's transport (path_transport.h):
// per probe, `rays` directions of a randomly turned spherical Fibonacci set
// (probe_directions.h), each carrying what arrives along it other than straight from the scene's
// lights (the environment, emissive surfaces, every bounce up to `bounces` surface
// interactions), projected into every form ProbeData holds (probe_projection.h).
//
// Before that, each probe is placed (probe_placement.h): a cheap geometric pass of `rays` rays
// counts the back faces it sees; more than a quarter means it sits inside geometry, and it moves
// toward the nearest back face it saw, through it (DDGI's relocation); one closer to a front face
// than a tenth of a cell moves away from it. Offsets stay within half a cell along each axis; a
// probe still inside after three tries is off, and its data stays zero.
//
// Deterministic: a probe's rotation and paths are hashes of (seed, probe, ray), so a bake split
// into ranges of probes (chunks) gives the same probes as one run.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/mat3x3.hpp>

#include "nodes/gi/path_tracer/path_scene.h"
#include "nodes/gi/probes/probe_grid.h"

namespace lg {

struct ProbeBakeSettings {
  uint32_t rays = 256;
  uint32_t bounces = 3;  // surface interactions after the probe's ray meets a surface
  uint64_t seed = 1;
};

// The rotation of probe `index`'s rays in a bake of `seed` (its placement's too, in the bake and
// in the dynamic update, so that a scene that does not change keeps its probes where they are).
glm::dmat3 probe_bake_rotation(uint64_t seed, size_t index);

// Bakes probes [begin, end) of `grid` (end clamped to its count). `progress`, when given, is
// called from the calling thread with the probes done.
void bake_probes(const PathScene& scene, ProbeGrid& grid, const ProbeBakeSettings& settings, size_t begin, size_t end,
                 const std::function<void(size_t done)>& progress = {});

}  // namespace lg
