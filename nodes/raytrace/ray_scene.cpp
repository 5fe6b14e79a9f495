// RayScene: one Embree triangle geometry holding the opaque triangles and one holding the
// alpha-tested ones, whose filter function rejects hits where the alpha is below the cutoff (so
// opaque geometry stays on Embree's fast path), sharing one vertex buffer; in robust
// (watertight) mode so rays through shared edges of closed meshes cannot slip between triangles.
#include "nodes/raytrace/ray_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <stdexcept>

#include "nodes/raytrace/alpha_coverage.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {

struct RayScene::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string error;                        // the first error Embree reported, if any
  std::unique_ptr<AlphaCoverage> coverage;  // the tested geometry's filter data, if there is one
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

// Embree's filter for the alpha-tested geometry (intersect and occluded alike): hits where the
// surface is transparent are rejected, so the traversal goes on past them.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* coverage = static_cast<const AlphaCoverage*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const glm::vec2 barycentric(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
    if (coverage->transparent(RTCHitN_primID(args->hit, args->N, i), barycentric)) args->valid[i] = 0;
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

RayScene::RayScene(const SceneView& view) : RayScene(make_world_mesh(view), view) {}

RayScene::RayScene(const WorldMesh& mesh, const SceneView& view) : positions_(mesh.positions), indices_(mesh.indices) {
  double_sided_.assign(triangle_count(), 0);
  for (size_t d = 0; d < mesh.parts.size() && d < view.draws.size(); ++d)
    if (view.material_of(view.draws[d]).double_sided)
      std::fill_n(double_sided_.begin() + mesh.parts[d].first_triangle, mesh.parts[d].triangle_count, 1);
  build(&view, &mesh);
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
  build(nullptr, nullptr);
}

RayScene::~RayScene() = default;
RayScene::RayScene(RayScene&&) noexcept = default;
RayScene& RayScene::operator=(RayScene&&) noexcept = default;

void RayScene::build(const SceneView* view, const WorldMesh* mesh) {
  for (const glm::vec3& p : positions_) bounds_min_ = glm::min(bounds_min_, p), bounds_max_ = glm::max(bounds_max_, p);
  embree_ = std::make_unique<Embree>();
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(embree_->device, record_embree_error, &embree_->error);
  embree_->scene = rtcNewScene(embree_->device);
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  if (view && mesh) {
    embree_->coverage = std::make_unique<AlphaCoverage>(*mesh, *view);
    if (embree_->coverage->tested_triangles().empty()) embree_->coverage.reset();
    if (embree_->coverage && !rtcGetDeviceProperty(embree_->device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
      throw std::runtime_error("this Embree was built without filter functions, which alpha-tested materials need");
  }
  // Triangles of each geometry: the opaque ones, then the alpha-tested ones.
  std::vector<uint32_t> opaque;
  if (embree_->coverage) {
    const std::vector<uint32_t>& tested = embree_->coverage->tested_triangles();
    for (uint32_t t = 0, next = 0; t < triangle_count(); ++t)
      if (next < tested.size() && tested[next] == t)
        ++next;
      else
        opaque.push_back(t);
  } else {
    opaque.resize(triangle_count());
    for (uint32_t t = 0; t < opaque.size(); ++t) opaque[t] = t;
  }
  if (!indices_.empty()) {
    // Embree reads vertices with 16-byte loads: one float of padding after the last.
    RTCBuffer vertices = rtcNewBuffer(embree_->device, (3 * positions_.size() + 1) * sizeof(float));
    auto* v = vertices ? static_cast<float*>(rtcGetBufferData(vertices)) : nullptr;
    if (!v) throw std::runtime_error("cannot allocate Embree's vertex buffer: " + embree_->error);
    for (size_t i = 0; i < positions_.size(); ++i)
      v[3 * i] = positions_[i].x, v[3 * i + 1] = positions_[i].y, v[3 * i + 2] = positions_[i].z;
    auto add_geometry = [&](std::vector<uint32_t> triangles, const AlphaCoverage* coverage) {
      if (triangles.empty()) return;
      RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0, 3 * sizeof(float),
                           positions_.size());
      auto* corners = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
          geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles.size()));
      if (!corners) {
        rtcReleaseGeometry(geometry);
        throw std::runtime_error("cannot allocate Embree buffers for " + std::to_string(triangles.size()) +
                                 " triangles: " + embree_->error);
      }
      for (size_t i = 0; i < triangles.size(); ++i)
        std::copy_n(&indices_[3 * size_t(triangles[i])], 3, &corners[3 * i]);
      if (coverage) {
        rtcSetGeometryUserData(geometry, const_cast<AlphaCoverage*>(coverage));
        rtcSetGeometryIntersectFilterFunction(geometry, alpha_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, alpha_filter);
      }
      rtcCommitGeometry(geometry);
      const unsigned id = rtcAttachGeometry(embree_->scene, geometry);
      rtcReleaseGeometry(geometry);
      geometry_triangles_.resize(std::max<size_t>(geometry_triangles_.size(), id + 1));
      geometry_triangles_[id] = std::move(triangles);
    };
    add_geometry(std::move(opaque), nullptr);
    if (embree_->coverage) add_geometry(embree_->coverage->tested_triangles(), embree_->coverage.get());
    rtcReleaseBuffer(vertices);
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
  return make_hit(query.ray.tfar, primitive(query.hit.geomID, query.hit.primID), {query.hit.u, query.hit.v}, direction);
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
                  : std::optional(make_hit(query.ray.tfar[i], primitive(query.hit.geomID[i], query.hit.primID[i]),
                                           {query.hit.u[i], query.hit.v[i]}, directions[i]));
}

}  // namespace lg
