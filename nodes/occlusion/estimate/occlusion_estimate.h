// Ray-traced ambient occlusion and bent normals at one surface point: cosine-weighted,
// stratified Monte Carlo over the hemisphere of the point's normal (cosine_sampling.h), with
// infinite rays or a maximum distance, optionally with an obscurance falloff.
//
// k_A (ambient visibility) = (1/N) sum_i rho(ray i), the cosine-weighted fraction of the
// hemisphere that is unoccluded: rho = 1 for a ray that escapes (or hits beyond max_distance),
// 0 for a hit with falloff none, and the obscurance curve rho(t) = x (2 - x), x = t /
// max_distance, with falloff obscurance (0 at contact, 1 with zero slope at max_distance). An
// open plane gives exactly 1, the inside of a closed box exactly 0.
//
// The bent normal is the normalised mean of the sampled directions weighted by rho (the mean
// unoccluded direction, cosine-weighted); the normal itself when nothing is visible. The
// visibility cone is GTAO's (Jimenez et al. 2016): the cone about the bent normal whose
// cosine-weighted solid angle fraction equals k_A, sin^2(angle) = k_A, so cos(angle) =
// sqrt(1 - k_A).
//
// Deterministic: the directions depend only on (seed, sample index); estimate_occlusion_many
// seeds point i with point_seed(seed, first_index + i), so any split of a batch into chunks,
// on any number of threads, gives bit-identical results.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

#include "nodes/raytrace/ray_scene.h"

namespace lg {

enum class OcclusionFalloff { none, obscurance };

struct OcclusionSettings {
  int rays = 256;                                               // per point, 1 to max_rays_per_point
  float max_distance = std::numeric_limits<float>::infinity();  // positive; infinite: rays never end
  OcclusionFalloff falloff = OcclusionFalloff::none;            // obscurance needs a finite max_distance
};

// Rays per point are bounded so that one point's work stays bounded (and its count fits the
// stratification's 32-bit indices with room): 1,048,576 = 1024^2.
inline constexpr int max_rays_per_point = 1 << 20;

// Throws std::invalid_argument naming the setting when one is out of range.
void check_occlusion_settings(const OcclusionSettings& settings);

struct OcclusionResult {
  float visibility = 1.0f;                  // k_A in [0, 1]
  glm::vec3 bent_normal{0.0f, 0.0f, 1.0f};  // unit
  float cone_cos = 0.0f;                    // cos of the visibility cone's half-angle: sqrt(1 - k_A)
  float cone_angle = 0.0f;                  // radians: asin(sqrt(k_A))
};

// `normal` must be unit length; rays start at offset_ray_origin(point, normal).
OcclusionResult estimate_occlusion(const RayScene& scene, glm::vec3 point, glm::vec3 normal,
                                   const OcclusionSettings& settings, uint64_t seed);

// Visibility at a point in space, with no surface: uniform over the whole sphere of directions
// (stratified: z = 1 - 2 u, phi = 2 pi v is equal-area), rho as above. An empty scene gives 1.
struct SphereVisibility {
  float visibility = 1.0f;                  // the weighted fraction of directions unoccluded
  glm::vec3 bent_normal{0.0f, 0.0f, 1.0f};  // unit mean unoccluded direction; +Z if none
  // (1/N) sum rho_i w_i, not normalised: with `visibility` the L1 spherical-harmonic projection
  // of visibility, V(w) ~ visibility + 3 mean_direction . w.
  glm::vec3 mean_direction{0.0f};
  float nearest_hit = std::numeric_limits<float>::infinity();  // the closest hit's distance; infinite if none
  float backface_fraction = 0.0f;  // rays whose first hit is a back face (inside a closed mesh: 1)
};
SphereVisibility estimate_sphere_visibility(const RayScene& scene, glm::vec3 point, const OcclusionSettings& settings,
                                            uint64_t seed);

struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit
};

// The seed estimate_occlusion_many gives point `index` of a bake seeded with `seed`.
uint64_t point_seed(uint64_t seed, uint64_t index);

// estimate_occlusion for every point on all cores; point i is seeded with point_seed(seed,
// first_index + i). `progress`, when given, is called now and then from the calling thread with
// the number of points done so far.
std::vector<OcclusionResult> estimate_occlusion_many(const RayScene& scene, std::span<const SurfacePoint> points,
                                                     const OcclusionSettings& settings, uint64_t seed,
                                                     uint64_t first_index = 0,
                                                     const std::function<void(size_t done)>& progress = {});

}  // namespace lg
