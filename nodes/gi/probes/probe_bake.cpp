#include "nodes/gi/probes/probe_bake.h"

#include <algorithm>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/gi/probes/probe_directions.h"
#include "nodes/gi/probes/probe_placement.h"
#include "nodes/gi/probes/probe_projection.h"
#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {
namespace {

void bake_probe(const PathTransport& transport, const RayScene& rays, const ProbeGrid& grid, size_t index,
                const ProbeBakeSettings& settings, ProbeData& out) {
  const glm::dmat3 rotation = probe_bake_rotation(settings.seed, index);
  glm::dvec3 offset;
  out = ProbeData{};
  if (!place_probe(rays, grid, index, settings.rays, rotation, offset)) return;
  out.active = true;
  out.offset = glm::vec3(offset);
  const glm::dvec3 p = grid.grid_position(index) + offset;
  const uint32_t n = settings.rays;
  ProbeProjection projection(n, probe_max_distance(grid));
  for (uint32_t i = 0; i < n; ++i) {
    const glm::dvec3 d = sphere_direction(i, n, rotation);
    const ProbeRay ray = transport.probe_ray(
        p, d, PathRandom(settings.seed, uint64_t(index) * n + i, transport.dimensions_per_bounce()));
    projection.add(d, ray.radiance, ray.distance);
  }
  projection.store(out);
}

}  // namespace

glm::dmat3 probe_bake_rotation(uint64_t seed, size_t index) {
  return random_rotation(mix_bits(seed ^ (uint64_t(index) << 20)));
}

void bake_probes(const PathScene& scene, ProbeGrid& grid, const ProbeBakeSettings& settings, size_t begin, size_t end,
                 const std::function<void(size_t)>& progress) {
  end = std::min(end, grid.probe_count());
  if (begin >= end) return;
  const PathTransport transport(scene, std::max(settings.bounces, 1u));
  auto body = [&](size_t i) { bake_probe(transport, scene.rays(), grid, begin + i, settings, grid.probes[begin + i]); };
  if (progress)
    parallel_for_with_progress(end - begin, body, progress);
  else
    parallel_for(end - begin, body);
}

}  // namespace lg
