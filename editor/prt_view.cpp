#include "editor/prt_view.h"

#include <vtkActor.h>
#include <vtkCellPicker.h>
#include <vtkColorTransferFunction.h>
#include <vtkFloatArray.h>
#include <vtkLineSource.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>
#include <span>
#include <sstream>

#include "editor/bake_legend.h"
#include "nodes/env/common/sh_basis.h"
#include "nodes/raytrace/bake_container.h"

namespace lg {

namespace {

double luminance(const float* rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

const float* transfer_of(const PrtBake& bake, size_t vertex) {
  return &bake.file.data.transfer[vertex * size_t(prt_vertex_floats(bake.file.header.settings.order))];
}

// A uniform sky of radiance 1 has the single coefficient L_0 = sqrt(4 pi), so E = T_0 sqrt(4 pi);
// an open vertex gets pi.
double sky_visibility(const PrtBake& bake, size_t vertex) {
  return luminance(transfer_of(bake, vertex)) * std::sqrt(4 * std::numbers::pi) / std::numbers::pi;
}

// Blue below zero, light grey at zero, red above: the sign of the band-limited function reads at
// a glance (a transfer function is never negative; its SH's ringing is).
vtkSmartPointer<vtkLookupTable> signed_colours(double magnitude) {
  vtkNew<vtkColorTransferFunction> ramp;
  ramp->AddRGBPoint(0.0, 0.23, 0.30, 0.75);
  ramp->AddRGBPoint(0.5, 0.87, 0.87, 0.87);
  ramp->AddRGBPoint(1.0, 0.71, 0.02, 0.15);
  const vtkSmartPointer<vtkLookupTable> lut = table_of(ramp);
  const double m = std::max(magnitude, 1e-6);
  lut->SetRange(-m, m);
  return lut;
}

}  // namespace

PrtBake load_prt_bake(const std::string& path, const std::string& mesh_path) {
  if (!std::filesystem::exists(path)) throw BakeFileError(path + ": no such file");
  PrtBake bake;
  bake.path = path;
  bake.mesh_path = mesh_path;
  bake.file = read_prt_file(path);
  const PrtFileHeader& h = bake.file.header;
  require_whole(path, h.chunk_index, h.chunk_count, "a PRT bake");
  bake.mesh = load_baked_mesh(mesh_path, path, h.input_hash, h.vertices);
  return bake;
}

double transfer_luminance(const PrtBake& bake, size_t vertex, const glm::dvec3& w) {
  const int order = bake.file.header.settings.order;
  double y[sh_count(kMaxShOrder)];
  sh_evaluate(order, w, std::span(y, size_t(sh_count(order))));
  const float* t = transfer_of(bake, vertex);
  double sum = 0;
  for (int k = 0; k < sh_count(order); ++k) sum += y[k] * luminance(t + 3 * k);
  return sum;
}

struct PrtView::Pipeline {
  vtkRenderer* renderer = nullptr;
  const PrtBake* bake = nullptr;
  vtkSmartPointer<vtkPolyData> mesh;
  vtkSmartPointer<vtkActor> mesh_actor;
  PrtViewState state;
  double radius = 1;  // of the transfer sphere
  vtkNew<vtkCellPicker> picker;
  vtkNew<vtkPolyData> sphere;
  vtkNew<vtkPolyDataMapper> sphere_mapper;
  vtkNew<vtkActor> sphere_actor;
  vtkNew<vtkLineSource> stem;
  vtkNew<vtkActor> stem_actor;
  vtkNew<vtkScalarBarActor> sphere_bar;

  void build_mesh() {
    const size_t n = bake->mesh.positions.size();
    mesh = vtk_mesh(bake->mesh);
    std::vector<float> visibility(n);
    for (size_t i = 0; i < n; ++i) visibility[i] = float(sky_visibility(*bake, i));
    const MaskedVisibility masked =
        mask_visibility(vtk_array("sky_visibility", 1, visibility), vtk_array("valid", 1, bake->file.data.valid));
    state.vertices = n;
    state.invalid = size_t(masked.invalid_points);
    state.sky_visibility = masked.range;
    mesh->GetPointData()->AddArray(masked.shown);
    mesh->GetPointData()->SetActiveScalars(shown_visibility_name);
    const vtkSmartPointer<vtkLookupTable> lut = visibility_colours(masked.range);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    mesh_actor = add_visibility_actor(renderer, mapper, lut);
    add_visibility_bar(renderer, lut, "sky visibility", "no normal");
  }

  // The selected vertex's sphere, hidden until one is selected, with its own colour bar at the left.
  void build_sphere() {
    sphere_mapper->SetInputData(sphere);
    sphere_mapper->SetColorModeToMapScalars();
    sphere_mapper->UseLookupTableScalarRangeOn();
    sphere_actor->SetMapper(sphere_mapper);
    sphere_actor->GetProperty()->SetLighting(false);
    sphere_actor->VisibilityOff();
    renderer->AddActor(sphere_actor);
    vtkNew<vtkPolyDataMapper> stem_mapper;
    stem_mapper->SetInputConnection(stem->GetOutputPort());
    stem_actor->SetMapper(stem_mapper);
    stem_actor->GetProperty()->SetColor(1.0, 0.85, 0.2);
    stem_actor->GetProperty()->SetLineWidth(2);
    stem_actor->GetProperty()->SetLighting(false);
    stem_actor->VisibilityOff();
    renderer->AddActor(stem_actor);
    sphere_bar->SetTitle("t(w)");
    sphere_bar->SetNumberOfLabels(3);
    sphere_bar->SetLabelFormat("%.2f");
    sphere_bar->SetWidth(0.08);
    sphere_bar->SetHeight(0.45);
    sphere_bar->SetPosition(0.02, 0.1);
    sphere_bar->UnconstrainedFontSizeOn();
    for (vtkTextProperty* text : {sphere_bar->GetTitleTextProperty(), sphere_bar->GetLabelTextProperty()}) {
      text->SetItalic(false);
      text->SetShadow(false);
      text->SetColor(0.92, 0.92, 0.92);
      text->SetFontSize(15);
    }
    sphere_bar->VisibilityOff();
    renderer->AddActor2D(sphere_bar);
  }

  void frame_and_title() {
    double bounds[6];
    mesh->GetBounds(bounds);
    const double diagonal =
        std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
    radius = 0.06 * std::max(diagonal, 1e-6);
    frame_bounds(renderer, bounds, {0.5, 0.4, 1.6});
    const PrtSettings& s = bake->file.header.settings;
    std::ostringstream title;
    title.precision(3);
    title << "PRT transfer of " << std::filesystem::path(bake->path).filename().string() << " on "
          << std::filesystem::path(bake->mesh_path).filename().string() << ": " << transfer_kind_name(s.kind)
          << ", order " << s.order << ", " << s.rays << " rays, " << s.bounces << " bounces\n"
          << "colour: sky visibility (irradiance under a uniform sky of radiance 1, over pi), " << state.sky_visibility[0]
          << " to " << state.sky_visibility[1] << "\n"
          << "click a vertex: its transfer t(w) on a sphere (the irradiance a unit light from w gives it)";
    add_title(renderer, title.str());
  }
};

PrtView::PrtView(vtkRenderer* renderer, const PrtBake& bake) : pipeline_(std::make_unique<Pipeline>()) {
  Pipeline& p = *pipeline_;
  p.renderer = renderer;
  p.bake = &bake;
  p.build_mesh();
  p.build_sphere();
  p.frame_and_title();
  p.picker->SetTolerance(0.0005);
  p.picker->PickFromListOn();
  p.picker->AddPickList(p.mesh_actor);
}

PrtView::~PrtView() = default;

std::optional<size_t> PrtView::pick(int x, int y) {
  Pipeline& p = *pipeline_;
  if (!p.picker->Pick(x, y, 0, p.renderer)) return std::nullopt;
  const vtkIdType cell = p.picker->GetCellId();
  if (cell < 0 || size_t(cell) >= p.bake->mesh.triangle_count()) return std::nullopt;
  double at[3];
  p.picker->GetPickPosition(at);
  const glm::vec3 hit(at[0], at[1], at[2]);
  size_t nearest = p.bake->mesh.indices[3 * size_t(cell)];
  for (int c = 1; c < 3; ++c) {
    const size_t v = p.bake->mesh.indices[3 * size_t(cell) + c];
    if (glm::distance(p.bake->mesh.positions[v], hit) < glm::distance(p.bake->mesh.positions[nearest], hit))
      nearest = v;
  }
  return nearest;
}

void PrtView::select(size_t vertex) {
  Pipeline& p = *pipeline_;
  if (vertex >= p.state.vertices) return;
  const glm::dvec3 at(p.bake->mesh.positions[vertex]);
  glm::dvec3 n(p.bake->mesh.normals[vertex]);
  n = glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0, 1, 0);
  // Out along the normal, far enough that the sphere does not sink into the surface.
  const glm::dvec3 centre = at + 2.2 * p.radius * n;

  vtkNew<vtkSphereSource> source;
  source->SetRadius(1);
  source->SetThetaResolution(64);
  source->SetPhiResolution(32);
  source->Update();
  vtkPolyData* unit = source->GetOutput();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> values;
  values->SetName("transfer");
  double magnitude = 0, low = INFINITY, high = -INFINITY;
  for (vtkIdType i = 0; i < unit->GetNumberOfPoints(); ++i) {
    double u[3];
    unit->GetPoint(i, u);
    const glm::dvec3 w = glm::normalize(glm::dvec3(u[0], u[1], u[2]));
    const glm::dvec3 x = centre + p.radius * w;
    points->InsertNextPoint(x.x, x.y, x.z);
    const double t = transfer_luminance(*p.bake, vertex, w);
    values->InsertNextValue(float(t));
    magnitude = std::max(magnitude, std::abs(t));
    low = std::min(low, t), high = std::max(high, t);
  }
  p.sphere->SetPoints(points);
  p.sphere->SetPolys(unit->GetPolys());
  p.sphere->GetPointData()->SetScalars(values);
  const vtkSmartPointer<vtkLookupTable> lut = signed_colours(magnitude);
  p.sphere_mapper->SetLookupTable(lut);
  p.sphere_bar->SetLookupTable(lut);
  p.stem->SetPoint1(at.x, at.y, at.z);
  p.stem->SetPoint2(centre.x - p.radius * n.x, centre.y - p.radius * n.y, centre.z - p.radius * n.z);
  p.sphere_actor->VisibilityOn();
  p.stem_actor->VisibilityOn();
  p.sphere_bar->VisibilityOn();
  p.state.selected = vertex;
  p.state.transfer_range = {low, high};
  p.renderer->ResetCameraClippingRange();
}

PrtViewState PrtView::state() const {
  return pipeline_->state;
}

std::array<double, 2> PrtView::display_point(size_t vertex) const {
  const Pipeline& p = *pipeline_;
  const glm::vec3 x = p.bake->mesh.positions[vertex];
  return display_point_of(p.renderer, x.x, x.y, x.z);
}

}  // namespace lg
