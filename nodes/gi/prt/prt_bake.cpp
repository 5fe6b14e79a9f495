// bake_transfer(): each vertex on its own, spread over all cores (prt_bake.h).
#include "nodes/gi/prt/prt_bake.h"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "nodes/env/common/sh_basis.h"
#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/raytrace/parallel_for.h"
#include "nodes/raytrace/ray_offset.h"

namespace lg {
namespace {

constexpr int kMaxCount = sh_count(kPrtMaxOrder);
using Transfer = std::array<glm::dvec3, kMaxCount>;

// The diffuse colour where `hit` lies (what multiplies irradiance / pi there).
glm::dvec3 diffuse_color_at(const PathScene& scene, const RayHit& hit, glm::dvec3 point) {
  const SurfaceAttributes at = scene.surfaces().at(hit.primitive, point);
  const SurfaceMaterial m = sample_material(scene.view(), scene.view().draws[at.draw], at.texcoords);
  return m.base_color * (1.0 - m.metalness);
}

// One ray of a vertex and, interreflected, the diffuse path it starts; adds to `t`.
void trace_path(const PathScene& scene, const PrtSettings& s, glm::vec3 origin, glm::dvec3 direction, uint64_t seed,
                uint64_t ray, Transfer& t) {
  const int count = sh_count(s.order);
  const uint32_t max_bounces = s.kind == TransferKind::interreflected ? s.bounces : 0;
  glm::dvec3 throughput(1.0);
  for (uint32_t bounce = 0;; ++bounce) {
    const std::optional<RayHit> hit = scene.rays().intersect(origin, glm::vec3(direction), INFINITY);
    if (!hit) {
      double y[kMaxCount];
      sh_evaluate(s.order, direction, std::span(y, count));
      for (int k = 0; k < count; ++k) t[k] += throughput * y[k];
      return;
    }
    if (bounce == max_bounces) return;
    const glm::dvec3 point = glm::dvec3(origin) + double(hit->distance) * direction;
    throughput *= diffuse_color_at(scene, *hit, point);
    if (throughput == glm::dvec3(0.0)) return;
    // Reflect into the side the ray arrived from: a cosine lobe about the face's normal there.
    const glm::dvec3 facing =
        glm::dot(glm::dvec3(hit->normal), direction) > 0.0 ? -glm::dvec3(hit->normal) : glm::dvec3(hit->normal);
    const glm::dvec2 u(hashed_uniform(seed, ray, 2 * bounce), hashed_uniform(seed, ray, 2 * bounce + 1));
    direction = glm::normalize(make_frame(facing).to_world(cosine_hemisphere(u)));
    origin = offset_ray_origin(glm::vec3(point), glm::vec3(facing));
  }
}

void bake_vertex(const PathScene& scene, const PrtSettings& s, uint64_t vertex, float* out, float& valid) {
  const WorldMesh& mesh = scene.surfaces().mesh();
  const glm::dvec3 n(mesh.normals[vertex]);
  const int count = sh_count(s.order);
  if (n == glm::dvec3(0.0)) return;  // no normal: no hemisphere to integrate over
  Transfer t{};
  if (s.kind == TransferKind::unshadowed) {
    double y[kMaxCount];
    sh_evaluate(s.order, n, std::span(y, count));
    for (int l = 0; l <= s.order; ++l)
      for (int k = l * l; k < (l + 1) * (l + 1); ++k) t[k] = glm::dvec3(cosine_lobe_band(l) * y[k]);
  } else {
    const uint64_t seed = mix_bits(s.seed ^ mix_bits(vertex + 1));
    const Frame frame = make_frame(n);
    const glm::vec3 origin = offset_ray_origin(mesh.positions[vertex], glm::vec3(n));
    for (uint32_t i = 0; i < s.rays; ++i) {
      const glm::dvec3 d = glm::normalize(frame.to_world(cosine_hemisphere(stratified_point(i, s.rays, seed))));
      trace_path(scene, s, origin, d, seed, i, t);
    }
    // The cosine density is cos / pi: each ray carries pi / rays of the integral of cos x Y.
    for (int k = 0; k < count; ++k) t[k] *= std::numbers::pi / s.rays;
  }
  for (int k = 0; k < count; ++k)
    for (int c = 0; c < 3; ++c) out[3 * k + c] = float(t[k][c]);
  valid = 1.0f;
}

}  // namespace

const char* transfer_kind_name(TransferKind kind) {
  switch (kind) {
    case TransferKind::unshadowed:
      return "unshadowed";
    case TransferKind::shadowed:
      return "shadowed";
    case TransferKind::interreflected:
      return "interreflected";
  }
  return "?";
}

std::optional<TransferKind> parse_transfer_kind(std::string_view name) {
  for (TransferKind k : {TransferKind::unshadowed, TransferKind::shadowed, TransferKind::interreflected})
    if (name == transfer_kind_name(k)) return k;
  return std::nullopt;
}

void check_prt_settings(const PrtSettings& s) {
  if (s.order < kPrtMinOrder || s.order > kPrtMaxOrder)
    throw std::invalid_argument("PRT: order " + std::to_string(s.order) + " is not 2 to 4");
  if (s.rays < 1 || s.rays > kPrtMaxRays)
    throw std::invalid_argument("PRT: rays must be 1 to " + std::to_string(kPrtMaxRays));
  const bool bounces = s.kind == TransferKind::interreflected;
  if (bounces && (s.bounces < 1 || s.bounces > kPrtMaxBounces))
    throw std::invalid_argument("PRT: interreflected transfer needs 1 to " + std::to_string(kPrtMaxBounces) +
                                " bounces");
  if (!bounces && s.bounces != 0)
    throw std::invalid_argument(std::string("PRT: ") + transfer_kind_name(s.kind) + " transfer has no bounces");
}

PrtData bake_transfer(const PathScene& scene, const PrtSettings& settings, PointRange range,
                      const std::function<void(uint64_t)>& progress) {
  check_prt_settings(settings);
  const int floats = prt_vertex_floats(settings.order);
  PrtData data;
  data.transfer.assign(range.size() * floats, 0.0f);
  data.valid.assign(range.size(), 0.0f);
  parallel_for_with_progress(
      range.size(),
      [&](size_t j) {
        bake_vertex(scene, settings, range.begin + j, data.transfer.data() + j * floats, data.valid[j]);
      },
      progress);
  return data;
}

}  // namespace lg
