#include "nodes/occlusion/reference/scene_reference.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>

#include "nodes/raytrace/parallel_for.h"
#include "nodes/raytrace/ray_offset.h"
#include "nodes/raytrace/world_mesh.h"
#include "nodes/raytrace/camera_pixels.h"

namespace lg {
namespace {

// Back faces the primary ray passes through when culling; more would mean the pixel looks
// through a stack of inside-out geometry, which no test scene has.
constexpr int kMaxCulledFaces = 16;

struct SurfaceHit {
  glm::dvec3 position, normal;  // shading normal, toward the camera's side
  glm::dvec3 geometric;         // unit geometric normal on the camera's side
};

// The interpolated world-space vertex normal at `point` on triangle `primitive` of the scene's
// flattened geometry (RayScene(view) numbers its triangles as make_world_mesh(view) does).
class ShadingNormals {
 public:
  explicit ShadingNormals(const SceneView& view) : mesh_(make_world_mesh(view)) {}

  glm::dvec3 at(uint32_t primitive, glm::dvec3 point) const {
    const uint32_t* corner = &mesh_.indices[3 * size_t(primitive)];
    const glm::dvec3 a(mesh_.positions[corner[0]]), b(mesh_.positions[corner[1]]), c(mesh_.positions[corner[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double area2 = glm::dot(n, n);
    if (!(area2 > 0.0)) return glm::dvec3(0.0, 0.0, 1.0);  // never hit: zero area
    // Barycentric coordinates of the point by sub-triangle areas.
    const double wb = glm::dot(glm::cross(point - a, c - a), n) / area2;
    const double wc = glm::dot(glm::cross(b - a, point - a), n) / area2;
    const glm::dvec3 interpolated = (1.0 - wb - wc) * glm::dvec3(mesh_.normals[corner[0]]) +
                                    wb * glm::dvec3(mesh_.normals[corner[1]]) +
                                    wc * glm::dvec3(mesh_.normals[corner[2]]);
    const double length = glm::length(interpolated);
    return length > 1e-12 ? interpolated / length : n / std::sqrt(area2);
  }

 private:
  WorldMesh mesh_;
};

std::optional<SurfaceHit> primary_hit(const RayScene& scene, const ShadingNormals& normals, glm::dvec3 eye,
                                      glm::dvec3 direction, bool cull_backfaces) {
  glm::vec3 origin(eye);
  const glm::vec3 dir(direction);
  for (int k = 0; k <= kMaxCulledFaces; ++k) {
    const std::optional<RayHit> hit = scene.intersect(origin, dir, std::numeric_limits<float>::infinity());
    if (!hit) return std::nullopt;
    const glm::dvec3 position = glm::dvec3(origin) + glm::dvec3(dir) * double(hit->distance);
    const bool front = glm::dot(glm::dvec3(hit->normal), direction) < 0.0;
    if (!front && cull_backfaces) {
      origin = offset_ray_origin(glm::vec3(position), dir);  // continue behind the culled face
      continue;
    }
    const double side = front ? 1.0 : -1.0;
    const glm::dvec3 n = normals.at(hit->primitive, position);
    return SurfaceHit{position, n * side, glm::dvec3(hit->normal) * side};
  }
  return std::nullopt;
}

}  // namespace

AoImage trace_scene_reference(const SceneView& view, const RayScene& scene, const SceneReferenceOptions& options,
                              const AoSettings& settings) {
  const CameraPixels pixels(view.camera, options.width, options.height);
  const ShadingNormals normals(view);
  const float max_distance =
      std::isfinite(settings.max_distance) ? float(settings.max_distance) : std::numeric_limits<float>::infinity();
  AoImage out(options.width, options.height);
  parallel_for(options.height, [&](size_t row) {
    const uint32_t y = uint32_t(row);
    for (uint32_t x = 0; x < options.width; ++x) {
      const std::optional<SurfaceHit> surface =
          primary_hit(scene, normals, pixels.eye(), pixels.ray_direction(x, y), options.cull_backfaces);
      if (!surface) continue;
      const size_t i = size_t(y) * options.width + x;
      // Rays leave from just above the triangle itself; those the shading normal sends below
      // it meet the mesh they start on, as they would on the real geometry.
      const glm::vec3 origin = offset_ray_origin(glm::vec3(surface->position), glm::vec3(surface->geometric));
      OcclusionSum sum;
      for (const glm::dvec3& d : cosine_directions(surface->normal, settings, i)) {
        const std::optional<RayHit> hit = scene.intersect(origin, glm::vec3(d), max_distance);
        sum.add(d, hit ? occlusion_weight(hit->distance, settings) : 0.0);
      }
      out.visibility[i] = float(sum.visibility());
      out.bent[i] = glm::vec4(sum.bent_normal_and_cone(surface->normal));
    }
  });
  return out;
}

}  // namespace lg
