#include "runtime/scene/frustum.h"

#include <glm/geometric.hpp>

#include "runtime/scene/camera_jitter.h"

namespace lg {
namespace {

glm::vec4 row(const glm::mat4& m, int r) {
  return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

// Scaled so that n.p + d is a distance; a plane with no normal (d > 0 everywhere or nowhere)
// keeps only the sign of d.
glm::vec4 normalized(glm::vec4 plane) {
  const float length = glm::length(glm::vec3(plane));
  if (length > 0.0f) return plane / length;
  return {0.0f, 0.0f, 0.0f, plane.w >= 0.0f ? 1.0f : -1.0f};
}

}  // namespace

Frustum view_frustum(const glm::mat4& m) {
  const glm::vec4 x = row(m, 0), y = row(m, 1), z = row(m, 2), w = row(m, 3);
  // Reversed Z: the near plane is z = w, the far one z = 0 (no plane at all when infinite).
  return {
      {normalized(w + x), normalized(w - x), normalized(w + y), normalized(w - y), normalized(w - z), normalized(z)}};
}

Frustum view_frustum(const CameraView& camera) {
  return view_frustum(jittered_projection(camera) * camera.view);
}

bool touches(const Frustum& frustum, const Bounds& box) {
  if (box.empty()) return false;
  for (const glm::vec4& p : frustum.planes) {
    // The box's corner farthest along the plane's normal: if even it is outside, all are.
    const glm::vec3 corner(p.x >= 0.0f ? box.max.x : box.min.x, p.y >= 0.0f ? box.max.y : box.min.y,
                           p.z >= 0.0f ? box.max.z : box.min.z);
    if (glm::dot(glm::vec3(p), corner) + p.w < 0.0f) return false;
  }
  return true;
}

bool touches(const Frustum& frustum, glm::vec3 center, float radius) {
  for (const glm::vec4& p : frustum.planes)
    if (glm::dot(glm::vec3(p), center) + p.w < -radius) return false;
  return true;
}

Bounds transform_bounds(const Bounds& box, const glm::mat4& transform) {
  if (box.empty()) return box;
  // Arvo: the centre moves with the transform, the half extents through its absolute values.
  const glm::vec3 center = glm::vec3(transform * glm::vec4(box.center(), 1.0f));
  const glm::vec3 half = 0.5f * (box.max - box.min);
  glm::vec3 extent(0.0f);
  for (int c = 0; c < 3; ++c) extent += glm::abs(glm::vec3(transform[c])) * half[c];
  Bounds out;
  out.min = center - extent;
  out.max = center + extent;
  return out;
}

std::vector<Bounds> mesh_bounds(const SceneView& scene) {
  std::vector<Bounds> out(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    if (scene.meshes[i])
      for (const glm::vec3& p : scene.meshes[i]->positions) out[i].add(p);
  return out;
}

std::vector<uint32_t> visible_draws(const SceneView& scene, std::span<const Bounds> meshes, const Frustum& frustum) {
  std::vector<uint32_t> out;
  out.reserve(scene.draws.size());
  for (uint32_t i = 0; i < scene.draws.size(); ++i) {
    const DrawItem& d = scene.draws[i];
    // A draw with a bad mesh index is kept, so that drawing it reports the error as before.
    const bool known = d.mesh >= 0 && size_t(d.mesh) < meshes.size();
    if (!known || touches(frustum, transform_bounds(meshes[size_t(d.mesh)], d.world))) out.push_back(i);
  }
  return out;
}

}  // namespace lg
