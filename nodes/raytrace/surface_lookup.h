// What a ray hit on the flattened scene (world_mesh.h) is to shading: the interpolated unit
// vertex normal, tangent, texture coordinates and vertex colour, and the draw the triangle belongs to,
// at a point on one of its triangles (RayScene numbers triangles as make_world_mesh() does).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "nodes/raytrace/surface_material.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {

struct SurfaceAttributes {
  glm::dvec3 normal;        // unit; the geometric normal where the vertex normals cancel
  glm::dvec4 tangent{0.0};  // xyz interpolated (not unit), w the first corner's bitangent sign
  SurfaceTexcoords texcoords;
  uint32_t draw = 0;  // index into the SceneView's draws (and the mesh's parts)
};

class SurfaceLookup {
 public:
  explicit SurfaceLookup(WorldMesh mesh);

  // `point` lies on triangle `primitive` (barycentric weights come from sub-triangle areas, so
  // a point a rounding error off the plane is fine).
  SurfaceAttributes at(uint32_t primitive, glm::dvec3 point) const;
  const WorldMesh& mesh() const { return mesh_; }

 private:
  WorldMesh mesh_;
};

}  // namespace lg
