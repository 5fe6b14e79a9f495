// Procedural meshes for the default world and for scene files' "shape" entities. All are
// centred on the origin, with outward normals, uvs and counter-clockwise front faces.
#pragma once

#include <glm/vec3.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

// A UV sphere; segments around the Y axis, rings from pole to pole.
MeshData make_sphere(float radius, int segments = 48, int rings = 24);
// An ellipsoid with semi-axes `radii` (a scaled sphere, normals corrected).
MeshData make_ellipsoid(glm::vec3 radii, int segments = 32, int rings = 16);
// A box with the given edge lengths; each face has its own vertices (flat normals).
MeshData make_box(glm::vec3 size);
// A rectangle in the XZ plane facing +Y.
MeshData make_quad(float width, float depth);
// A capsule along X: a cylinder of `length` with hemispherical caps of `radius`.
MeshData make_capsule(float length, float radius, int segments = 32, int rings = 16);
// A bunny-like shape about 0.5 tall standing on y = 0, facing +Z: body, head, ears, tail and
// feet as overlapping ellipsoids merged into one mesh.
MeshData make_bunny();

// Appends b to a (indices shifted); both must have uvs, or neither.
void append_mesh(MeshData& a, const MeshData& b);

}  // namespace lg
