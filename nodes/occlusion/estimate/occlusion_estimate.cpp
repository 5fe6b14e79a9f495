// estimate_occlusion(): N stratified cosine rays per point, summed in sample order in double
// precision so the result does not depend on how points are spread over threads.
#include "nodes/occlusion/estimate/occlusion_estimate.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/parallel_for.h"
#include "nodes/raytrace/ray_offset.h"

namespace lg {
namespace {

// rho for a ray that hit at `distance` (within max_distance).
double hit_weight(const OcclusionSettings& settings, float distance) {
  if (settings.falloff == OcclusionFalloff::none) return 0.0;
  const double x = std::min(1.0, double(distance) / settings.max_distance);
  return x * (2.0 - x);
}

// Traces `count` rays from `origin` in packets of consecutive sample indices (the same packets on
// every run, so results do not depend on threads): `direction(i)` is ray i's unit direction;
// `visit(direction, ray, hit)` sees every ray in order (its double and float directions) with
// its closest hit, when `need_hits`, or with any hit (distance and normal then unset) otherwise.
template <class Direction, class Visit>
void trace_rays(const RayScene& scene, glm::vec3 origin, uint32_t count, float t_max, bool need_hits,
                Direction direction, Visit visit) {
  constexpr size_t packet = RayScene::packet_size;
  glm::dvec3 directions[packet];
  glm::vec3 rays[packet];
  bool blocked[packet];
  std::optional<RayHit> hits[packet];
  for (uint32_t first = 0; first < count; first += packet) {
    const size_t n = std::min<size_t>(packet, count - first);
    for (size_t j = 0; j < n; ++j) {
      directions[j] = direction(first + uint32_t(j));
      rays[j] = glm::normalize(glm::vec3(directions[j]));
    }
    if (need_hits) {
      scene.intersect_packet(origin, std::span(rays, n), t_max, std::span(hits, n));
    } else {
      scene.occluded_packet(origin, std::span(rays, n), t_max, std::span(blocked, n));
      for (size_t j = 0; j < n; ++j) hits[j] = blocked[j] ? std::optional(RayHit{}) : std::nullopt;
    }
    for (size_t j = 0; j < n; ++j) visit(directions[j], rays[j], hits[j]);
  }
}

}  // namespace

void check_occlusion_settings(const OcclusionSettings& settings) {
  if (settings.rays < 1 || settings.rays > max_rays_per_point)
    throw std::invalid_argument("rays must be from 1 to " + std::to_string(max_rays_per_point) + " per point; got " +
                                std::to_string(settings.rays));
  if (!(settings.max_distance > 0.0f))
    throw std::invalid_argument("max distance must be positive (or infinite); got " +
                                std::to_string(settings.max_distance));
  if (settings.falloff == OcclusionFalloff::obscurance && std::isinf(settings.max_distance))
    throw std::invalid_argument("the obscurance falloff needs a finite max distance");
}

OcclusionResult estimate_occlusion(const RayScene& scene, glm::vec3 point, glm::vec3 normal,
                                   const OcclusionSettings& settings, uint64_t seed) {
  const Frame frame = make_frame(glm::dvec3(normal));
  const glm::vec3 origin = offset_ray_origin(point, normal);
  const uint32_t count = uint32_t(settings.rays);
  double visible = 0.0;
  glm::dvec3 bent{0.0};
  trace_rays(
      scene, origin, count, settings.max_distance, settings.falloff == OcclusionFalloff::obscurance,
      [&](uint32_t i) { return frame.to_world(cosine_hemisphere(stratified_point(i, count, seed))); },
      [&](glm::dvec3 direction, glm::vec3, const std::optional<RayHit>& hit) {
        const double weight = hit ? hit_weight(settings, hit->distance) : 1.0;
        visible += weight;
        bent += weight * direction;
      });
  OcclusionResult result;
  const double k = std::clamp(visible / count, 0.0, 1.0);
  result.visibility = float(k);
  const double bent_length = glm::length(bent);
  result.bent_normal = bent_length > 0.0 ? glm::vec3(bent / bent_length) : normal;
  result.cone_cos = float(std::sqrt(1.0 - k));
  result.cone_angle = float(std::asin(std::sqrt(k)));
  return result;
}

SphereVisibility estimate_sphere_visibility(const RayScene& scene, glm::vec3 point, const OcclusionSettings& settings,
                                            uint64_t seed) {
  const uint32_t count = uint32_t(settings.rays);
  double visible = 0.0;
  glm::dvec3 bent{0.0};
  uint32_t backfaces = 0;
  float nearest = std::numeric_limits<float>::infinity();
  auto direction = [&](uint32_t i) {
    const glm::dvec2 u = stratified_point(i, count, seed);
    const double z = 1.0 - 2.0 * u.y, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * u.x;
    return glm::dvec3{r * std::cos(phi), r * std::sin(phi), z};
  };
  trace_rays(scene, point, count, settings.max_distance, true, direction,
             [&](glm::dvec3 d, glm::vec3 ray, const std::optional<RayHit>& hit) {
               if (hit && glm::dot(hit->normal, ray) > 0.0f) ++backfaces;
               if (hit) nearest = std::min(nearest, hit->distance);
               const double weight = hit ? hit_weight(settings, hit->distance) : 1.0;
               visible += weight;
               bent += weight * d;
             });
  SphereVisibility result;
  result.visibility = float(std::clamp(visible / count, 0.0, 1.0));
  const double bent_length = glm::length(bent);
  if (bent_length > 0.0) result.bent_normal = glm::vec3(bent / bent_length);
  result.mean_direction = glm::vec3(bent / double(count));
  result.nearest_hit = nearest;
  result.backface_fraction = float(double(backfaces) / count);
  return result;
}

uint64_t point_seed(uint64_t seed, uint64_t index) {
  return mix_bits(seed ^ mix_bits(index + 0x9e3779b97f4a7c15ull));
}

std::vector<OcclusionResult> estimate_occlusion_many(const RayScene& scene, std::span<const SurfacePoint> points,
                                                     const OcclusionSettings& settings, uint64_t seed,
                                                     uint64_t first_index,
                                                     const std::function<void(size_t)>& progress) {
  check_occlusion_settings(settings);
  std::vector<OcclusionResult> results(points.size());
  parallel_for_with_progress(
      points.size(),
      [&](size_t i) {
        results[i] = estimate_occlusion(scene, points[i].position, points[i].normal, settings,
                                        point_seed(seed, first_index + i));
      },
      progress);
  return results;
}

}  // namespace lg
