// The path-traced reference every global-illumination node is measured against: for each pixel
// centre of the camera (the G-buffer's pixel geometry, nodes/raytrace/camera_pixels.h), N paths
// with next-event estimation at every vertex (each light of PathLights and the environment
// sampled on its own) and BRDF sampling, the two combined by multiple importance sampling
// (power heuristic), Russian roulette after a few bounces. Materials, lights and environment are
// the raster path's (surface_material.h, path_lights.h, environment_map.h); every surface is
// two-sided, shaded on the side the ray arrives from, and reflects only into the geometric
// hemisphere it is seen from.
//
// Random numbers are hashes of (seed, pixel, sample, dimension), so a pixel's value does not
// depend on which rows or threads computed it: a chunked run merges bit-identically.
//
// The outputs (AOVs), each per pixel the mean over the paths and the standard error of that mean:
// - radiance: everything the camera sees;
// - emission: what the camera sees without a reflection: the visible surface's emission, or the
//   environment (with the sky's sun) where no surface is;
// - direct: the view's lights (directional, point, sphere, tube, rectangle) reflected once at
//   the visible surface, with shadows: what lighting.deferred computes;
// - indirect_diffuse: the diffuse lobe at the visible surface times all other light arriving
//   there (the environment, emissive surfaces and light that bounced at least once): what
//   lighting.ibl's diffuse term estimates with probes or an irradiance volume;
// - specular: the specular lobe at the visible surface times that same other light.
// radiance = emission + direct + indirect_diffuse + specular, per path.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "nodes/gi/path_tracer/path_scene.h"

namespace lg {

enum class ReferenceAov { radiance, emission, direct, indirect_diffuse, specular };
inline constexpr size_t kReferenceAovCount = 5;
const char* reference_aov_name(ReferenceAov aov);
std::optional<ReferenceAov> parse_reference_aov(const std::string& name);

struct PathTracerOptions {
  uint32_t width = 0, height = 0;
  uint32_t samples_per_pixel = 64;
  // Surface interactions on a path: 1 is direct light only, 2 adds one bounce, ...
  uint32_t max_bounces = 8;
  uint32_t russian_roulette_after = 3;  // bounces before paths may be ended at random
  uint64_t seed = 1;
  bool cull_backfaces = true;           // for the camera ray, as scene.gbuffer's param
  uint32_t row_begin = 0, row_end = 0;  // the rows to trace; row_end 0: to the last
};

struct ReferenceImage {
  uint32_t width = 0, height = 0;
  uint32_t row_begin = 0, row_end = 0;  // the rows held: pixel (x, y) at (y - row_begin) * width + x
  std::array<std::vector<glm::vec3>, kReferenceAovCount> mean, standard_error;
  uint64_t non_finite_samples = 0;  // paths whose value was NaN or Inf, counted as 0 (none expected)

  size_t pixel_count() const { return size_t(row_end - row_begin) * width; }
  const std::vector<glm::vec3>& mean_of(ReferenceAov aov) const { return mean[size_t(aov)]; }
  const std::vector<glm::vec3>& error_of(ReferenceAov aov) const { return standard_error[size_t(aov)]; }
};

// `progress`, when given, is called from the calling thread with the pixels done so far.
ReferenceImage trace_reference(const PathScene& scene, const PathTracerOptions& options,
                               const std::function<void(size_t pixels_done)>& progress = {});

}  // namespace lg
