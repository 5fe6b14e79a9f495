#include "editor/bake_legend.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkExtractVOI.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkOutlineFilter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkXMLImageDataReader.h>
#include <vtkImageData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/raytrace/world_mesh.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg {

unsigned char display_byte(double v, double exposure) {
  const double x = std::max(0.0, v * exposure);
  return static_cast<unsigned char>(std::lround(255 * std::pow(x / (1 + x), 1 / 2.2)));
}

BakeFile read_whole_bake(const std::string& path, BakeMode mode, const std::string& hint) {
  if (!std::filesystem::exists(path)) throw BakeFileError(path + ": no such file");
  BakeFile file = read_bake_file(path);
  const BakeHeader& h = file.header;
  if (h.mode != mode)
    throw BakeFileError(path + ": a " + bake_mode_name(h.mode) + " bake, expected a " + bake_mode_name(mode) +
                        " bake; " + hint);
  require_whole(path, h.chunk_index, h.chunk_count, "a bake");
  return file;
}

void require_whole(const std::string& path, uint32_t chunk_index, uint32_t chunk_count, const char* what) {
  if (chunk_count != 1)
    throw BakeFileError(path + ": chunk " + std::to_string(chunk_index) + " of " + std::to_string(chunk_count) + " of " +
                        what + "; merge the chunks first (lumagraph bake merge)");
}

WorldMesh load_baked_mesh(const std::string& mesh_path, const std::string& bake_path, uint64_t input_hash,
                          uint64_t vertices) {
  WorldMesh mesh;
  try {
    mesh = make_world_mesh(make_scene_view(load_world(mesh_path), 1.0f));
  } catch (const std::exception& e) {
    const std::string what = e.what();
    throw BakeFileError(what.find(mesh_path) == std::string::npos ? mesh_path + ": " + what : what);
  }
  if (world_mesh_hash(mesh) != input_hash || mesh.positions.size() != vertices)
    throw BakeFileError(mesh_path + ": not the geometry " + bake_path + " was baked from (" +
                        std::to_string(mesh.positions.size()) + " vertices, the bake has " + std::to_string(vertices) +
                        "; or their positions, normals or indices differ)");
  return mesh;
}

vtkSmartPointer<vtkPolyData> vtk_mesh(const WorldMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(vtkIdType(mesh.positions.size()));
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    points->SetPoint(vtkIdType(i), mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
  vtkNew<vtkCellArray> triangles;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const vtkIdType corners[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
    triangles->InsertNextCell(3, corners);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  return poly;
}

vtkSmartPointer<vtkFloatArray> vtk_array(const char* name, int components, const std::vector<float>& values) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(vtkIdType(values.size() / components));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

MaskedVisibility mask_visibility(vtkDataArray* visibility, vtkDataArray* valid) {
  MaskedVisibility masked;
  masked.shown = vtkSmartPointer<vtkFloatArray>::New();
  masked.shown->SetName(shown_visibility_name);
  const vtkIdType n = visibility->GetNumberOfTuples();
  masked.shown->SetNumberOfTuples(n);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (vtkIdType i = 0; i < n; ++i) {
    const double v = visibility->GetTuple1(i);
    if (valid->GetTuple1(i) > 0) {
      masked.shown->SetValue(i, float(v));
      low = std::min(low, v), high = std::max(high, v);
    } else {
      masked.shown->SetValue(i, std::numeric_limits<float>::quiet_NaN());
      ++masked.invalid_points;
    }
  }
  if (masked.invalid_points == n) low = high = 0;
  masked.range = {low, high};
  return masked;
}

vtkSmartPointer<vtkLookupTable> table_of(vtkColorTransferFunction* ramp) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i) {
    double rgb[3];
    ramp->GetColor(i / 255.0, rgb);
    lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1);
  }
  return lut;
}

// Viridis at five stops: perceptually even, readable in grey, and distinct from the grey mask.
vtkSmartPointer<vtkLookupTable> visibility_colours(std::array<double, 2> range) {
  vtkNew<vtkColorTransferFunction> ramp;
  const double stops[5][3] = {{0.267, 0.005, 0.329},
                              {0.229, 0.322, 0.546},
                              {0.128, 0.567, 0.551},
                              {0.369, 0.789, 0.383},
                              {0.993, 0.906, 0.144}};
  for (int i = 0; i < 5; ++i) ramp->AddRGBPoint(i / 4.0, stops[i][0], stops[i][1], stops[i][2]);
  const vtkSmartPointer<vtkLookupTable> lut = table_of(ramp);
  // A constant bake (an empty scene) still needs a range the colour map can span.
  lut->SetRange(range[0], std::max(range[1], range[0] + 1e-6));
  lut->SetNanColor(0.55, 0.55, 0.55, 1);
  return lut;
}

void add_visibility_bar(vtkRenderer* renderer, vtkLookupTable* lut, const char* title, const char* masked) {
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle(title);
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%.2f");
  // The grey swatch below the ramp is the legend of the masked points.
  bar->DrawNanAnnotationOn();
  bar->SetNanAnnotation(masked);
  bar->SetWidth(0.1);
  bar->SetHeight(0.62);
  bar->SetPosition(0.87, 0.16);
  bar->UnconstrainedFontSizeOn();
  for (vtkTextProperty* text :
       {bar->GetTitleTextProperty(), bar->GetLabelTextProperty(), bar->GetAnnotationTextProperty()}) {
    text->SetItalic(false);
    text->SetBold(false);
    text->SetShadow(false);
    text->SetColor(0.92, 0.92, 0.92);
    text->SetFontSize(15);
  }
  bar->GetTitleTextProperty()->SetFontSize(18);
  renderer->AddActor2D(bar);
}

namespace {

// The last non-empty line of a VTK message, without the "vtkClass (0x...): " that starts it.
std::string last_line(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  message = message.substr(message.find_last_of('\n') + 1);
  const size_t object = message.find("): ");
  return object == std::string::npos ? message : message.substr(object + 3);
}

}  // namespace

// VTK's XML reader reports a damaged file through error events, not exceptions: the observer
// keeps the first message for ours.
vtkSmartPointer<vtkImageData> read_vti_file(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  std::string vtk_error;
  vtkNew<vtkCallbackCommand> on_error;
  on_error->SetClientData(&vtk_error);
  on_error->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
    auto* message = static_cast<std::string*>(client);
    if (message->empty() && call) *message = static_cast<const char*>(call);
  });
  reader->AddObserver(vtkCommand::ErrorEvent, on_error);
  reader->AddObserver(vtkCommand::WarningEvent, on_error);
  if (!reader->CanReadFile(path.c_str())) throw BakeFileError(path + ": not a VTK XML image data file (.vti)");
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (!vtk_error.empty() || !image || image->GetNumberOfPoints() == 0) {
    throw BakeFileError(path + ": damaged VTK image data" +
                        (vtk_error.empty() ? std::string(" (no points)") : ": " + last_line(vtk_error)));
  }
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(image);
  return copy;
}

void add_title(vtkRenderer* renderer, const std::string& text) {
  vtkNew<vtkTextActor> title;
  title->SetInput(text.c_str());
  title->GetTextProperty()->SetFontSize(16);
  title->GetTextProperty()->SetColor(0.92, 0.92, 0.92);
  title->GetTextProperty()->SetVerticalJustificationToTop();
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->GetPositionCoordinate()->SetValue(0.015, 0.98);
  renderer->AddActor2D(title);
}

vtkSmartPointer<vtkActor> add_visibility_actor(vtkRenderer* renderer, vtkMapper* mapper, vtkLookupTable* lut) {
  mapper->SetLookupTable(lut);
  mapper->UseLookupTableScalarRangeOn();
  mapper->SetColorModeToMapScalars();
  mapper->InterpolateScalarsBeforeMappingOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLighting(false);
  renderer->AddActor(actor);
  return actor;
}

std::array<double, 2> display_point_of(vtkRenderer* renderer, double x, double y, double z) {
  renderer->SetWorldPoint(x, y, z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  return {d[0], d[1]};
}

void frame_bounds(vtkRenderer* renderer, const double bounds[6], std::array<double, 3> offset) {
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOff();
  const double centre[3] = {(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2};
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + offset[0], centre[1] + offset[1], centre[2] + offset[2]);
  camera->SetViewUp(0, 1, 0);
  camera->SetWindowCenter(-0.1, 0);
  renderer->ResetCamera(bounds);
}

void add_outline(vtkRenderer* renderer, vtkImageData* image, double x_offset) {
  vtkNew<vtkOutlineFilter> outline;
  outline->SetInputData(image);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(outline->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.7, 0.7, 0.7);
  actor->SetPosition(x_offset, 0, 0);
  renderer->AddActor(actor);
}

void set_slice_voi(vtkExtractVOI* extract, const std::array<int, 3>& dims, int axis, int index) {
  int voi[6] = {0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1};
  voi[2 * axis] = voi[2 * axis + 1] = index;
  extract->SetVOI(voi);
}

}  // namespace lg
