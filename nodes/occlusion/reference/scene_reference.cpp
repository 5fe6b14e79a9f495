#include "nodes/occlusion/reference/scene_reference.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>

#include "nodes/raytrace/camera_hit.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/parallel_for.h"
#include "nodes/raytrace/ray_offset.h"
#include "nodes/raytrace/surface_lookup.h"

namespace lg {
namespace {

struct SurfaceHit {
  glm::dvec3 position, normal;  // shading normal, toward the camera's side
  glm::dvec3 geometric;         // unit geometric normal on the camera's side
};

std::optional<SurfaceHit> primary_hit(const RayScene& scene, const SurfaceLookup& surfaces, glm::dvec3 eye,
                                      glm::dvec3 direction, bool cull_backfaces) {
  const std::optional<CameraHit> hit = first_camera_hit(scene, eye, direction, cull_backfaces);
  if (!hit) return std::nullopt;
  const double side = hit->front_face ? 1.0 : -1.0;
  return SurfaceHit{hit->position, surfaces.at(hit->hit.primitive, hit->position).normal * side,
                    glm::dvec3(hit->hit.normal) * side};
}

}  // namespace

AoImage trace_scene_reference(const SceneView& view, const RayScene& scene, const SceneReferenceOptions& options,
                              const AoSettings& settings) {
  const CameraPixels pixels(view.camera, options.width, options.height);
  const SurfaceLookup surfaces(make_world_mesh(view));
  const float max_distance =
      std::isfinite(settings.max_distance) ? float(settings.max_distance) : std::numeric_limits<float>::infinity();
  AoImage out(options.width, options.height);
  parallel_for(options.height, [&](size_t row) {
    const uint32_t y = uint32_t(row);
    for (uint32_t x = 0; x < options.width; ++x) {
      const std::optional<SurfaceHit> surface =
          primary_hit(scene, surfaces, pixels.eye(), pixels.ray_direction(x, y), options.cull_backfaces);
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
