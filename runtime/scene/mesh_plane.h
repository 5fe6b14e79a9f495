// The plane of a flat mesh: what a planar reflector reflects in (docs/planar-reflections.md).
#pragma once

#include <glm/vec4.hpp>
#include <optional>

#include "runtime/scene/scene_view.h"

namespace lg {

struct MeshPlane {
  glm::vec4 plane;         // xyz the unit normal its triangles face (area-weighted), w: n . p + w = 0
  double max_distance;     // of a vertex from the plane, metres in the mesh's space
  double allowed_distance; // what still counts as flat: 1e-4 of the mesh's size, at least 1e-6 m
  bool flat() const { return max_distance <= allowed_distance; }
};

// nullopt when the mesh has no triangle of any area, or its triangles face opposite ways by as
// much area as they face one (no side to reflect from).
std::optional<MeshPlane> mesh_plane(const MeshData& mesh);

// The plane after `transform` (a world matrix), its normal unit again.
glm::vec4 transform_plane(const glm::vec4& plane, const glm::mat4& transform);

}  // namespace lg
