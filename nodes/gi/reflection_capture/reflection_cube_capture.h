// Capturing a reflection probe's cube on the CPU with the path tracer's transport
// (path_transport.h), the decision docs/reflection-probes.md explains: each texel of each face is
// the mean of `samples` probe rays through random points of the texel from the probe's position,
// each carrying what arrives along it other than straight from the scene's lights (the
// environment, emissive surfaces, surfaces with all the light they reflect, up to `bounces`
// surface interactions): exactly the light the path tracer's `specular` AOV reflects, so the
// prefiltered cube is comparable to the reference. Lights reflected straight off the visible
// surface are lighting.deferred's, as in the reference's `direct`.
//
// Deterministic: a texel's paths are hashes of (seed, probe, face, texel, sample), whatever
// thread traced them.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "nodes/env/common/cube_map.h"
#include "nodes/gi/path_tracer/path_scene.h"

namespace lg {

struct ReflectionCaptureSettings {
  uint32_t face_size = 32;
  uint32_t samples = 16;  // paths per texel
  uint32_t bounces = 3;   // surface interactions after the probe's ray meets a surface
  uint64_t seed = 1;
};

// The radiance arriving at `position` from every direction, as one cube (Vulkan's faces, cube_map.h).
CubeImage capture_reflection_cube(const PathScene& scene, glm::dvec3 position, uint32_t probe_index,
                                  const ReflectionCaptureSettings& settings);

}  // namespace lg
