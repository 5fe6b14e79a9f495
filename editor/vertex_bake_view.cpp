#include "editor/vertex_bake_view.h"

#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <filesystem>
#include <sstream>

#include "editor/bake_legend.h"
#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {

VertexBake load_vertex_bake(const std::string& path, const std::string& mesh_path) {
  const BakeFile file = read_whole_bake(path, BakeMode::vertex, "a volume bake opens without --mesh");
  const BakeHeader& h = file.header;
  const WorldMesh mesh = load_baked_mesh(mesh_path, path, h.input_hash, h.points);

  VertexBake bake;
  bake.path = path;
  bake.mesh_path = mesh_path;
  bake.rays = unsigned(h.occlusion.rays);
  bake.mesh = vtk_mesh(mesh);
  const auto visibility = vtk_array("visibility", 1, file.data.visibility);
  const auto valid = vtk_array("valid", 1, file.data.valid);
  const MaskedVisibility masked = mask_visibility(visibility, valid);
  bake.visibility_range = masked.range;
  bake.invalid_points = masked.invalid_points;
  bake.mesh->GetPointData()->AddArray(masked.shown);
  bake.mesh->GetPointData()->SetActiveScalars(shown_visibility_name);
  bake.mesh->GetPointData()->AddArray(vtk_array("bent_normal", 3, file.data.bent_normal));
  return bake;
}

void add_vertex_bake(vtkRenderer* renderer, const VertexBake& bake) {
  const vtkSmartPointer<vtkLookupTable> lut = visibility_colours(bake.visibility_range);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(bake.mesh);
  add_visibility_actor(renderer, mapper, lut);
  add_visibility_bar(renderer, lut, "k_A", "no normal");

  double bounds[6];
  bake.mesh->GetBounds(bounds);
  frame_bounds(renderer, bounds, {0.5, 0.4, 1.6});  // from the front (+Z), a little to the side and above

  std::ostringstream title;
  title.precision(3);
  title << "Ambient visibility k_A of " << std::filesystem::path(bake.path).filename().string() << " on "
        << std::filesystem::path(bake.mesh_path).filename().string() << "\n"
        << bake.mesh->GetNumberOfPoints() << " vertices, " << bake.rays << " rays each, k_A from "
        << bake.visibility_range[0] << " to " << bake.visibility_range[1] << "\n"
        << "grey: nothing baked (degenerate normal, " << bake.invalid_points << " vertices)";
  add_title(renderer, title.str());
}

}  // namespace lg
