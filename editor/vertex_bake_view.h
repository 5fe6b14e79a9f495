// The inspector's view of a vertex bake (`lumagraph bake --mode vertex`, NAME.lgbake) on the
// mesh it was baked from: the mesh in world space coloured by each vertex's ambient visibility,
// vertices with nothing baked (degenerate normals) grey.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <string>

class vtkPolyData;
class vtkRenderer;

namespace lg {

struct VertexBake {
  std::string path, mesh_path;
  // The world mesh's triangles with point arrays shown_visibility (active scalars; NaN where
  // valid is 0) and bent_normal.
  vtkSmartPointer<vtkPolyData> mesh;
  std::array<double, 2> visibility_range{0, 0};  // over the valid vertices
  long long invalid_points = 0;
  unsigned rays = 0;
};

// Reads the bake with the bake library and the mesh as `lumagraph bake` does; throws
// BakeFileError naming the file that is missing, damaged, not a whole vertex bake, or not the
// geometry the bake was made from (its input hash differs).
VertexBake load_vertex_bake(const std::string& path, const std::string& mesh_path);

// Adds the coloured mesh, the colour bar and the title to `renderer`, the camera framing it.
void add_vertex_bake(vtkRenderer* renderer, const VertexBake& bake);

}  // namespace lg
