#include "editor/bake_view.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCamera.h>
#include <vtkCubeAxesActor.h>
#include <vtkDataSetMapper.h>
#include <vtkExtractVOI.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3D.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "editor/bake_legend.h"
#include "nodes/occlusion/bake/bake_file.h"

namespace lg {

namespace {

vtkFloatArray* float_array(vtkImageData* image, const char* name, int components) {
  auto* array = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray(name));
  if (!array || array->GetNumberOfComponents() != components ||
      array->GetNumberOfTuples() != image->GetNumberOfPoints())
    return nullptr;
  return array;
}

vtkSmartPointer<vtkImageData> image_of_bake(const std::string& path) {
  const BakeFile file = read_whole_bake(path, BakeMode::volume, "a vertex bake opens with its mesh (--mesh)");
  const BakeHeader& h = file.header;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(int(h.dims[0]), int(h.dims[1]), int(h.dims[2]));
  image->SetOrigin(h.origin.x, h.origin.y, h.origin.z);
  image->SetSpacing(h.spacing.x, h.spacing.y, h.spacing.z);
  image->GetPointData()->AddArray(vtk_array("visibility", 1, file.data.visibility));
  image->GetPointData()->AddArray(vtk_array("bent_normal", 3, file.data.bent_normal));
  image->GetPointData()->AddArray(vtk_array("valid", 1, file.data.valid));
  return image;
}

}  // namespace

BakeVolume load_bake_volume(const std::string& path) {
  if (!std::filesystem::exists(path)) throw BakeFileError(path + ": no such file");
  const std::string extension = std::filesystem::path(path).extension().string();
  BakeVolume volume;
  volume.path = path;
  if (extension == ".vti")
    volume.image = read_vti_file(path);
  else if (extension == ".lgbake")
    volume.image = image_of_bake(path);
  else
    throw BakeFileError(path + ": expected a volume bake, NAME.vti or NAME.lgbake (lumagraph bake --mode volume)");

  vtkFloatArray* visibility = float_array(volume.image, "visibility", 1);
  vtkFloatArray* valid = float_array(volume.image, "valid", 1);
  if (!visibility || !valid || !float_array(volume.image, "bent_normal", 3))
    throw BakeFileError(path +
                        ": not an occlusion bake: expected point arrays visibility (1 component), bent_normal (3) "
                        "and valid (1) of one value per grid point");
  const MaskedVisibility masked = mask_visibility(visibility, valid);
  volume.visibility_range = masked.range;
  volume.invalid_points = masked.invalid_points;
  volume.image->GetPointData()->AddArray(masked.shown);
  volume.image->GetPointData()->SetActiveScalars(shown_visibility_name);
  volume.image->GetPointData()->SetActiveVectors("bent_normal");
  return volume;
}

struct VolumeSlices::Pipeline {
  vtkSmartPointer<vtkImageData> image;
  std::array<int, 3> dims{0, 0, 0}, slice{0, 0, 0};
  std::array<vtkNew<vtkExtractVOI>, 3> slices;
  vtkNew<vtkPolyData> arrow_points;  // the z slice's valid points, sub-sampled, with bent normals
  vtkNew<vtkGlyph3D> arrows;
  vtkSmartPointer<vtkLookupTable> lut;
  int arrow_stride = 1;

  void place(int axis) {
    set_slice_voi(slices[axis], dims, axis, slice[axis]);
    if (axis == 2) place_arrows();
  }

  void place_arrows() {
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> vectors;
    vectors->SetNumberOfComponents(3);
    auto* valid = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("valid"));
    vtkDataArray* bent = image->GetPointData()->GetVectors();
    for (int j = arrow_stride / 2; j < dims[1]; j += arrow_stride)
      for (int i = arrow_stride / 2; i < dims[0]; i += arrow_stride) {
        int ijk[3] = {i, j, slice[2]};
        const vtkIdType id = image->ComputePointId(ijk);
        if (valid->GetValue(id) < 0.75f) continue;  // inside geometry, or padding
        points->InsertNextPoint(image->GetPoint(id));
        vectors->InsertNextTuple(bent->GetTuple3(id));
      }
    arrow_points->SetPoints(points);
    arrow_points->GetPointData()->SetVectors(vectors);
    arrow_points->Modified();
  }
};

VolumeSlices::VolumeSlices(vtkRenderer* renderer, const BakeVolume& volume) : pipeline_(std::make_unique<Pipeline>()) {
  Pipeline& p = *pipeline_;
  p.image = volume.image;
  p.image->GetDimensions(p.dims.data());
  // About 16 arrows across the z slice's longer side, on its valid points only.
  p.arrow_stride = std::max(1, std::max(p.dims[0], p.dims[1]) / 16);
  p.lut = visibility_colours(volume.visibility_range);
  for (int axis = 0; axis < 3; ++axis) {
    p.slice[axis] = p.dims[axis] / 2;
    p.slices[axis]->SetInputData(p.image);
    p.place(axis);
    vtkNew<vtkDataSetMapper> mapper;
    mapper->SetInputConnection(p.slices[axis]->GetOutputPort());
    add_visibility_actor(renderer, mapper, p.lut);
  }

  vtkNew<vtkArrowSource> arrow;
  arrow->SetShaftRadius(0.04);
  arrow->SetTipRadius(0.12);
  double spacing[3];
  p.image->GetSpacing(spacing);
  p.arrows->SetInputData(p.arrow_points);
  p.arrows->SetSourceConnection(arrow->GetOutputPort());
  p.arrows->SetVectorModeToUseVector();
  p.arrows->SetScaleModeToDataScalingOff();
  p.arrows->SetScaleFactor(0.9 * p.arrow_stride * std::max(spacing[0], spacing[1]));
  p.arrows->OrientOn();
  vtkNew<vtkPolyDataMapper> arrow_mapper;
  arrow_mapper->SetInputConnection(p.arrows->GetOutputPort());
  arrow_mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> arrow_actor;
  arrow_actor->SetMapper(arrow_mapper);
  arrow_actor->GetProperty()->SetColor(0.95, 0.95, 0.95);
  renderer->AddActor(arrow_actor);

  add_outline(renderer, p.image, 0.0);

  double bounds[6];
  p.image->GetBounds(bounds);
  // A three-quarter view from above and in front (+Z), Y up (the scenes' convention), so all
  // three slices face the viewer.
  frame_bounds(renderer, bounds, {1.1, 0.8, 1.6});

  vtkNew<vtkCubeAxesActor> axes;
  axes->SetBounds(bounds);
  axes->SetCamera(renderer->GetActiveCamera());
  axes->SetFlyModeToOuterEdges();
  axes->SetXTitle("x");
  axes->SetYTitle("y");
  axes->SetZTitle("z");
  axes->SetScreenSize(9);
  for (int a = 0; a < 3; ++a) {
    axes->GetTitleTextProperty(a)->SetColor(0.8, 0.8, 0.8);
    axes->GetLabelTextProperty(a)->SetColor(0.8, 0.8, 0.8);
  }
  axes->GetXAxesLinesProperty()->SetColor(0.5, 0.5, 0.5);
  axes->GetYAxesLinesProperty()->SetColor(0.5, 0.5, 0.5);
  axes->GetZAxesLinesProperty()->SetColor(0.5, 0.5, 0.5);
  renderer->AddActor(axes);

  add_visibility_bar(renderer, p.lut, "k_A", "inside");

  std::ostringstream title;
  title.precision(3);
  title << "Ambient visibility k_A of " << std::filesystem::path(volume.path).filename().string() << "\n"
        << p.dims[0] << " x " << p.dims[1] << " x " << p.dims[2] << " points, k_A from " << volume.visibility_range[0]
        << " to " << volume.visibility_range[1] << " over the valid points\n"
        << "grey: inside geometry (" << volume.invalid_points << " points) - arrows: bent normals on the z slice";
  add_title(renderer, title.str());
}

VolumeSlices::~VolumeSlices() = default;

void VolumeSlices::set_slice(int axis, int index) {
  Pipeline& p = *pipeline_;
  p.slice[axis] = std::clamp(index, 0, p.dims[axis] - 1);
  p.place(axis);
}

VolumeSliceState VolumeSlices::state() const {
  const Pipeline& p = *pipeline_;
  VolumeSliceState s;
  s.dims = p.dims;
  s.slice = p.slice;
  const double* range = p.lut->GetRange();
  s.colour_range = {range[0], range[1]};
  for (const auto& slice : p.slices) {
    slice->Update();
    vtkDataArray* shown = slice->GetOutput()->GetPointData()->GetScalars();
    s.slice_points += shown->GetNumberOfTuples();
    for (vtkIdType i = 0; i < shown->GetNumberOfTuples(); ++i) s.masked_points += std::isnan(shown->GetTuple1(i));
  }
  s.arrows = p.arrow_points->GetNumberOfPoints();
  return s;
}

std::string VolumeSlices::slice_caption() const {
  const Pipeline& p = *pipeline_;
  double origin[3], spacing[3];
  p.image->GetOrigin(origin);
  p.image->GetSpacing(spacing);
  std::ostringstream caption;
  caption.precision(3);
  const char* names = "xyz";
  for (int a = 0; a < 3; ++a)
    caption << (a ? "   " : "") << names[a] << " = " << origin[a] + p.slice[a] * spacing[a] << " (point "
            << p.slice[a] + 1 << " of " << p.dims[a] << ")";
  return caption.str();
}

}  // namespace lg
