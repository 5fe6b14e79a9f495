// Tangents for normal mapping when a file brings none: per triangle from how its uvs change
// across it, accumulated per vertex and made orthogonal to the vertex normal, in the convention
// glTF's normal textures use (MikkTSpace's: the bitangent is cross(normal, tangent.xyz) * w and
// points toward decreasing v, the image's "up").
#pragma once

#include "runtime/scene/scene_view.h"

namespace lg {

// Fills mesh.tangents (one per position) from the normals and uv set `uv_set` (0 or 1). Each
// triangle's unit tangent and bitangent are weighted by the triangle's angle at the vertex, as
// MikkTSpace does, so that splitting a face into more triangles does not change the result. A
// vertex whose triangles have no usable uvs (degenerate or missing) gets a tangent perpendicular to
// its normal and w = 1. Needs normals (one per position); without that uv set every vertex takes
// the fallback.
void generate_tangents(MeshData& mesh, int uv_set);

}  // namespace lg
