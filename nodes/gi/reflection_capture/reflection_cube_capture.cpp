#include "nodes/gi/reflection_capture/reflection_cube_capture.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {

CubeImage capture_reflection_cube(const PathScene& scene, glm::dvec3 position, uint32_t probe_index,
                                  const ReflectionCaptureSettings& settings) {
  const uint32_t n = std::max(settings.face_size, 1u), spp = std::max(settings.samples, 1u);
  const PathTransport transport(scene, std::max(settings.bounces, 1u));
  const uint32_t dims = transport.dimensions_per_bounce();
  CubeImage cube(n);
  const size_t texels = cube.texels.size();
  parallel_for(texels, [&](size_t t) {
    const int face = int(t / (size_t(n) * n));
    const uint32_t i = uint32_t(t % n), j = uint32_t(t / n % n);
    glm::dvec3 sum(0.0);
    for (uint32_t s = 0; s < spp; ++s) {
      const uint64_t path = ((uint64_t(probe_index) * texels + t) * spp + s);
      // The point in the texel from a sequence of its own (another seed), apart from the path's.
      const PathRandom jitter(settings.seed ^ 0x5bd1e995u, path, 2);
      const glm::dvec2 uv = jitter.pair(0, 0);
      const glm::dvec3 d = glm::normalize(cube_direction(face, (i + uv.x) / n, (j + uv.y) / n));
      const ProbeRay ray = transport.probe_ray(position, d, PathRandom(settings.seed, path, dims));
      // A non-finite path (none expected) counts as black rather than poisoning the cube.
      if (std::isfinite(ray.radiance.x + ray.radiance.y + ray.radiance.z)) sum += ray.radiance;
    }
    cube.texels[t] = glm::dvec4(sum / double(spp), 1.0);
  });
  return cube;
}

}  // namespace lg
