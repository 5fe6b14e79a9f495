// RayScene: one Embree triangle geometry holding every triangle, in robust (watertight) mode so
// rays through shared edges of closed meshes cannot slip between triangles.
#include "nodes/raytrace/ray_scene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <stdexcept>

#include "nodes/raytrace/world_mesh.h"

namespace lg {

struct RayScene::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string error;  // the first error Embree reported, if any
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void record_embree_error(void* user, RTCError code, const char* message) {
  auto* first_error = static_cast<std::string*>(user);
  if (first_error->empty())
    first_error->assign("Embree error " + std::to_string(int(code)) + ": " + (message ? message : ""));
}

void check_finite(std::span<const glm::vec3> positions, const std::string& name) {
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::invalid_argument(name + ": vertex " + std::to_string(i) + " has a non-finite position (" +
                                  std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) +
                                  "); positions must be finite numbers");
  }
}

RTCRay make_ray(glm::vec3 origin, glm::vec3 direction, float t_max) {
  RTCRay ray{};
  ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
  ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
  ray.tnear = 0.0f;
  ray.tfar = t_max;
  ray.mask = std::numeric_limits<unsigned>::max();
  return ray;
}

}  // namespace

RayScene::RayScene(const SceneView& view) {
  WorldMesh mesh = make_world_mesh(view);
  positions_ = std::move(mesh.positions);
  indices_ = std::move(mesh.indices);
  build();
}

RayScene::RayScene(std::span<const glm::vec3> positions, std::span<const uint32_t> indices, const std::string& name)
    : positions_(positions.begin(), positions.end()), indices_(indices.begin(), indices.end()) {
  if (indices_.size() % 3 != 0)
    throw std::invalid_argument(name + ": " + std::to_string(indices_.size()) +
                                " indices is not a multiple of 3 (three per triangle)");
  for (size_t i = 0; i < indices_.size(); ++i)
    if (indices_[i] >= positions_.size())
      throw std::invalid_argument(name + ": index " + std::to_string(i) + " is " + std::to_string(indices_[i]) +
                                  ", past the " + std::to_string(positions_.size()) + " positions");
  check_finite(positions_, name);
  build();
}

RayScene::~RayScene() = default;
RayScene::RayScene(RayScene&&) noexcept = default;
RayScene& RayScene::operator=(RayScene&&) noexcept = default;

void RayScene::build() {
  for (const glm::vec3& p : positions_) bounds_min_ = glm::min(bounds_min_, p), bounds_max_ = glm::max(bounds_max_, p);
  embree_ = std::make_unique<Embree>();
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(embree_->device, record_embree_error, &embree_->error);
  embree_->scene = rtcNewScene(embree_->device);
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  if (!indices_.empty()) {
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), positions_.size()));
    auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), indices_.size() / 3));
    if (!vertices || !triangles) {
      rtcReleaseGeometry(geometry);
      throw std::runtime_error("cannot allocate Embree buffers for " + std::to_string(indices_.size() / 3) +
                               " triangles: " + embree_->error);
    }
    for (size_t i = 0; i < positions_.size(); ++i)
      vertices[3 * i] = positions_[i].x, vertices[3 * i + 1] = positions_[i].y, vertices[3 * i + 2] = positions_[i].z;
    std::copy(indices_.begin(), indices_.end(), triangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(embree_->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(embree_->scene);
  if (!embree_->error.empty()) throw std::runtime_error("building the ray-tracing scene: " + embree_->error);
}

std::array<glm::vec3, 3> RayScene::triangle(uint32_t primitive) const {
  return {positions_[indices_[3 * size_t(primitive)]], positions_[indices_[3 * size_t(primitive) + 1]],
          positions_[indices_[3 * size_t(primitive) + 2]]};
}

std::optional<RayHit> RayScene::intersect(glm::vec3 origin, glm::vec3 direction, float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray = make_ray(origin, direction, t_max);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return make_hit(query.ray.tfar, query.hit.primID, {query.hit.u, query.hit.v}, direction);
}

RayHit RayScene::make_hit(float distance, uint32_t primitive, glm::vec2 barycentric, glm::vec3 direction) const {
  const std::array<glm::vec3, 3> corners = triangle(primitive);
  // Our own normal rather than Embree's Ng, so that its orientation is the documented one.
  const glm::vec3 n = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
  const float length = glm::length(n);
  return RayHit{distance, length > 0.0f ? n / length : -direction, primitive, barycentric};
}

bool RayScene::occluded(glm::vec3 origin, glm::vec3 direction, float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_max);
  rtcOccluded1(embree_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

namespace {

// Fills an 8-wide packet with rays from `origin`; lanes past the directions are switched off.
template <class Packet>
void fill_packet(Packet& rays, int (&valid)[8], glm::vec3 origin, std::span<const glm::vec3> directions, float t_max) {
  for (size_t i = 0; i < 8; ++i) {
    const bool used = i < directions.size();
    valid[i] = used ? -1 : 0;
    const glm::vec3 d = used ? directions[i] : glm::vec3(0.0f, 0.0f, 1.0f);
    rays.org_x[i] = origin.x, rays.org_y[i] = origin.y, rays.org_z[i] = origin.z;
    rays.dir_x[i] = d.x, rays.dir_y[i] = d.y, rays.dir_z[i] = d.z;
    rays.tnear[i] = 0.0f, rays.tfar[i] = t_max;
    rays.mask[i] = std::numeric_limits<unsigned>::max();
  }
}

}  // namespace

void RayScene::occluded_packet(glm::vec3 origin, std::span<const glm::vec3> directions, float t_max,
                               std::span<bool> occluded) const {
  static_assert(packet_size == 8, "the packet is Embree's RTCRay8");
  alignas(32) int valid[8];
  alignas(32) RTCRay8 rays{};
  fill_packet(rays, valid, origin, directions, t_max);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcOccluded8(valid, embree_->scene, &context, &rays);
  for (size_t i = 0; i < directions.size(); ++i) occluded[i] = rays.tfar[i] < 0.0f;
}

void RayScene::intersect_packet(glm::vec3 origin, std::span<const glm::vec3> directions, float t_max,
                                std::span<std::optional<RayHit>> hits) const {
  alignas(32) int valid[8];
  alignas(32) RTCRayHit8 query{};
  fill_packet(query.ray, valid, origin, directions, t_max);
  for (size_t i = 0; i < 8; ++i) query.hit.geomID[i] = query.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect8(valid, embree_->scene, &context, &query);
  for (size_t i = 0; i < directions.size(); ++i)
    hits[i] = query.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID
                  ? std::nullopt
                  : std::optional(make_hit(query.ray.tfar[i], query.hit.primID[i], {query.hit.u[i], query.hit.v[i]},
                                           directions[i]));
}

}  // namespace lg
