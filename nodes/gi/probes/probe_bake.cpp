#include "nodes/gi/probes/probe_bake.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <numbers>

#include "nodes/env/common/sh_basis.h"
#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/gi/probes/octahedral_map.h"
#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBackFaceLimit = 0.25;    // DDGI's fraction of back-face hits that means "inside"
constexpr double kDistanceSharpness = 50;  // DDGI's cos^50 weighting of the distance moments
constexpr int kRelocationTries = 3;

// Direction `index` of `count` of a spherical Fibonacci set (even over the sphere, far more so
// than independent or jittered points: cosine lobes integrate to a fraction of a percent with
// 256), turned by a rotation drawn from `seed`, as DDGI turns its rays anew for each update.
glm::dvec3 sphere_direction(uint32_t index, uint32_t count, const glm::dmat3& rotation) {
  const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  const double z = 1.0 - (2.0 * index + 1.0) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double turns = index / golden;
  const double phi = 2.0 * kPi * (turns - std::floor(turns));
  return rotation * glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A uniformly random rotation (Shoemake's quaternion from three uniform numbers).
glm::dmat3 random_rotation(uint64_t seed) {
  const double u1 = hashed_uniform(seed, 0, 0), u2 = hashed_uniform(seed, 0, 1), u3 = hashed_uniform(seed, 0, 2);
  const glm::dquat q(std::sqrt(u1) * std::cos(2.0 * kPi * u3), std::sqrt(1.0 - u1) * std::sin(2.0 * kPi * u2),
                     std::sqrt(1.0 - u1) * std::cos(2.0 * kPi * u2), std::sqrt(u1) * std::sin(2.0 * kPi * u3));
  return glm::mat3_cast(q);
}

struct NearestHits {
  double back_fraction = 0.0;
  glm::dvec3 back_direction{0.0}, front_direction{0.0};
  double back_distance = std::numeric_limits<double>::infinity(), front_distance = back_distance;
};

NearestHits look_around(const RayScene& rays, glm::dvec3 p, uint32_t count, const glm::dmat3& rotation) {
  NearestHits h;
  uint32_t back = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::dvec3 d = sphere_direction(i, count, rotation);
    const auto hit = rays.intersect(glm::vec3(p), glm::vec3(d), std::numeric_limits<float>::infinity());
    if (!hit) continue;
    const bool is_back = glm::dot(glm::dvec3(hit->normal), d) > 0.0;
    back += is_back;
    double& nearest = is_back ? h.back_distance : h.front_distance;
    if (hit->distance < nearest) {
      nearest = hit->distance;
      (is_back ? h.back_direction : h.front_direction) = d;
    }
  }
  h.back_fraction = double(back) / count;
  return h;
}

// Keeps an offset within half a cell along each of the grid's axes.
glm::dvec3 clamp_offset(const ProbeGrid& grid, glm::dvec3 offset) {
  glm::dvec3 out(0.0);
  for (int a = 0; a < 3; ++a) {
    const glm::dvec3 axis = grid.axis(a);
    const double length2 = glm::dot(axis, axis);
    if (!(length2 > 0.0)) continue;  // a box flat along this axis: nowhere to move
    const double t = std::clamp(glm::dot(offset, axis) / length2, -0.5, 0.5);
    out += t * axis;
  }
  return out;
}

// Where the probe goes, and whether it ends outside geometry.
bool place_probe(const RayScene& rays, const ProbeGrid& grid, size_t index, uint32_t count, const glm::dmat3& rotation,
                 glm::dvec3& offset) {
  const glm::dvec3 home = grid.grid_position(index);
  const double near = 0.1 * grid.min_spacing();
  offset = glm::dvec3(0.0);
  for (int attempt = 0; attempt <= kRelocationTries; ++attempt) {
    const NearestHits h = look_around(rays, home + offset, count, rotation);
    if (h.back_fraction > kBackFaceLimit) {
      if (attempt == kRelocationTries) return false;
      // Through the nearest back face, a little past it.
      offset = clamp_offset(grid, offset + h.back_direction * (h.back_distance + 0.05 * near));
      continue;
    }
    if (h.front_distance < near) offset = clamp_offset(grid, offset - h.front_direction * (near - h.front_distance));
    return true;
  }
  return false;
}

void bake_probe(const PathTransport& transport, const RayScene& rays, const ProbeGrid& grid, size_t index,
                const ProbeBakeSettings& settings, ProbeData& out) {
  const glm::dmat3 rotation = random_rotation(mix_bits(settings.seed ^ (uint64_t(index) << 20)));
  glm::dvec3 offset;
  out = ProbeData{};
  if (!place_probe(rays, grid, index, settings.rays, rotation, offset)) return;
  out.active = true;
  out.offset = glm::vec3(offset);
  const glm::dvec3 p = grid.grid_position(index) + offset;
  // Rays that escape count as this far for the distance moments (DDGI clamps to its ray length).
  const double max_distance = 1.5 * glm::length(grid.axis(0) + grid.axis(1) + grid.axis(2));
  const uint32_t n = settings.rays;
  const double weight = 4.0 * kPi / n;  // uniform over the sphere

  constexpr int irradiance_texels = kProbeIrradianceTexels * kProbeIrradianceTexels;
  constexpr int distance_texels = kProbeDistanceTexels * kProbeDistanceTexels;
  std::array<glm::dvec3, irradiance_texels> irradiance_normals;
  for (int t = 0; t < irradiance_texels; ++t)
    irradiance_normals[t] = octahedral_decode({(t % kProbeIrradianceTexels + 0.5) / kProbeIrradianceTexels,
                                               (t / kProbeIrradianceTexels + 0.5) / kProbeIrradianceTexels});
  std::array<glm::dvec3, distance_texels> distance_normals;
  for (int t = 0; t < distance_texels; ++t)
    distance_normals[t] = octahedral_decode({(t % kProbeDistanceTexels + 0.5) / kProbeDistanceTexels,
                                             (t / kProbeDistanceTexels + 0.5) / kProbeDistanceTexels});

  std::array<glm::dvec3, kProbeShCount> sh{};
  std::array<glm::dvec3, 6> cube{};
  std::array<glm::dvec3, irradiance_texels> irradiance{};
  std::array<glm::dvec3, distance_texels> moments{};  // sum of w, w t, w t^2
  double basis[kProbeShCount];
  for (uint32_t i = 0; i < n; ++i) {
    const glm::dvec3 d = sphere_direction(i, n, rotation);
    const ProbeRay ray = transport.probe_ray(
        p, d, PathRandom(settings.seed, uint64_t(index) * n + i, transport.dimensions_per_bounce()));
    const glm::dvec3 l =
        std::isfinite(ray.radiance.x + ray.radiance.y + ray.radiance.z) ? ray.radiance : glm::dvec3(0.0);
    sh_evaluate(2, d, basis);
    for (int c = 0; c < kProbeShCount; ++c) sh[c] += l * basis[c] * weight;
    for (int a = 0; a < 3; ++a) {
      cube[2 * a] += l * std::max(d[a], 0.0) * weight;
      cube[2 * a + 1] += l * std::max(-d[a], 0.0) * weight;
    }
    for (int t = 0; t < irradiance_texels; ++t)
      irradiance[t] += l * std::max(glm::dot(irradiance_normals[t], d), 0.0) * weight;
    const double t_hit = std::min(ray.distance, max_distance);
    for (int t = 0; t < distance_texels; ++t) {  // half the texels face away: no pow for them
      const double c = glm::dot(distance_normals[t], d);
      if (c > 0.0) moments[t] += std::pow(c, kDistanceSharpness) * glm::dvec3(1.0, t_hit, t_hit * t_hit);
    }
  }
  for (int c = 0; c < kProbeShCount; ++c) {
    const int band = c == 0 ? 0 : c < 4 ? 1 : 2;
    out.sh[c] = glm::vec3(sh[c] * cosine_lobe_band(band));  // radiance to irradiance
  }
  for (int f = 0; f < 6; ++f) out.ambient_cube[f] = glm::vec3(cube[f]);
  for (int t = 0; t < irradiance_texels; ++t) out.irradiance[t] = glm::vec3(irradiance[t]);
  for (int t = 0; t < distance_texels; ++t)
    out.distance[t] = moments[t].x > 0.0 ? glm::vec2(moments[t].y / moments[t].x, moments[t].z / moments[t].x)
                                         : glm::vec2(float(max_distance), float(max_distance * max_distance));
}

}  // namespace

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
