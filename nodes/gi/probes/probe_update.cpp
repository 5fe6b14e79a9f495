#include "nodes/gi/probes/probe_update.h"

#include <algorithm>
#include <numbers>
#include <vector>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/gi/probes/probe_bake.h"
#include "nodes/gi/probes/probe_directions.h"
#include "nodes/gi/probes/probe_placement.h"
#include "nodes/gi/probes/probe_projection.h"
#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {
namespace {

size_t total_probes(std::span<const ProbeGrid> grids) {
  size_t n = 0;
  for (const ProbeGrid& g : grids) n += g.probe_count();
  return n;
}

struct ProbeRef {
  size_t volume, index;
};

ProbeRef locate(std::span<const ProbeGrid> grids, size_t global) {
  size_t volume = 0;
  while (global >= grids[volume].probe_count()) global -= grids[volume++].probe_count();
  return {volume, global};
}

// One probe's new value from what the probes hold now.
ProbeData trace_probe(const PathTransport& transport, const PathScene& scene, std::span<const ProbeGrid> grids,
                      ProbeRef at, const ProbeUpdateSettings& settings, uint64_t frame) {
  const ProbeGrid& grid = grids[at.volume];
  ProbeData out;
  glm::dvec3 offset;
  if (!place_probe(scene.rays(), grid, at.index, settings.placement_rays, probe_bake_rotation(settings.seed, at.index),
                   offset))
    return out;
  out.active = true;
  out.offset = glm::vec3(offset);
  const glm::dvec3 p = grid.grid_position(at.index) + offset;
  // This visit's own random sequence and ray rotation: a hash of (seed, frame, volume, probe).
  const uint64_t visit = mix_bits(mix_bits(mix_bits(settings.seed) ^ frame) ^ (uint64_t(at.volume) << 40 | at.index));
  const glm::dmat3 rotation = random_rotation(visit);
  const uint32_t n = settings.rays;
  ProbeProjection projection(n, probe_max_distance(grid));
  for (uint32_t i = 0; i < n; ++i) {
    const glm::dvec3 d = sphere_direction(i, n, rotation);
    const ProbeHit hit = transport.probe_hit(p, d, PathRandom(visit, i, transport.dimensions_per_bounce()));
    glm::dvec3 radiance = hit.ray.radiance;
    if (hit.surface) {
      const VisibleSurface& s = *hit.surface;
      const VolumeIrradiance e = lookup_volumes(grids, s.position, s.normal, p, settings.lookup);
      radiance += hit.albedo / std::numbers::pi * e.irradiance * e.coverage;
    }
    projection.add(d, radiance, hit.ray.distance);
  }
  projection.store(out);
  return out;
}

template <class T, size_t N>
void blend(std::array<T, N>& stored, const std::array<T, N>& fresh, float hysteresis) {
  for (size_t i = 0; i < N; ++i) stored[i] = fresh[i] + (stored[i] - fresh[i]) * hysteresis;
}

// stored = lerp(fresh, stored, hysteresis), form by form; a probe that was off starts afresh.
void blend_probe(ProbeData& stored, const ProbeData& fresh, float hysteresis) {
  if (!stored.active || !fresh.active) {
    stored = fresh;
    return;
  }
  stored.offset = fresh.offset;
  blend(stored.sh, fresh.sh, hysteresis);
  blend(stored.ambient_cube, fresh.ambient_cube, hysteresis);
  blend(stored.irradiance, fresh.irradiance, hysteresis);
  blend(stored.distance, fresh.distance, hysteresis);
}

}  // namespace

size_t first_updated_probe(std::span<const ProbeGrid> grids, const ProbeUpdateSettings& settings, uint64_t frame) {
  const size_t total = total_probes(grids);
  if (total == 0) return 0;
  const size_t budget = std::min<size_t>(settings.probes_per_update, total);
  return size_t((frame % total) * budget % total);
}

void update_probes(const PathScene& scene, std::span<ProbeGrid> grids, const ProbeUpdateSettings& settings,
                   uint64_t frame) {
  const size_t total = total_probes(grids);
  const size_t budget = std::min<size_t>(settings.probes_per_update, total);
  if (budget == 0 || settings.rays == 0) return;
  const size_t first = first_updated_probe(grids, settings, frame);
  const PathTransport transport(scene, 1);
  std::vector<ProbeData> fresh(budget);
  parallel_for(budget, [&](size_t k) {
    fresh[k] = trace_probe(transport, scene, grids, locate(grids, (first + k) % total), settings, frame);
  });
  for (size_t k = 0; k < budget; ++k) {
    const ProbeRef at = locate(grids, (first + k) % total);
    blend_probe(grids[at.volume].probes[at.index], fresh[k], float(settings.hysteresis));
  }
}

}  // namespace lg
