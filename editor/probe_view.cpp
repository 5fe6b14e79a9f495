#include "editor/probe_view.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <sstream>
#include <stdexcept>

#include "editor/bake_legend.h"
#include "nodes/gi/probes/probe_lookup.h"

namespace lg {

namespace {

constexpr int kSliceStepsPerCell = 4;
constexpr int kSliceSamplesPerCell = 4;
const unsigned char kOffColour[3] = {215, 60, 50};
const unsigned char kUncoveredColour[3] = {60, 62, 66};

double luminance(glm::dvec3 rgb) {
  return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

void insert_colour(vtkUnsignedCharArray* colours, glm::dvec3 rgb, double exposure) {
  const unsigned char c[3] = {display_byte(rgb.r, exposure), display_byte(rgb.g, exposure),
                              display_byte(rgb.b, exposure)};
  colours->InsertNextTypedTuple(c);
}

vtkSmartPointer<vtkUnsignedCharArray> colour_array() {
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(3);
  return colours;
}

// An unlit actor (stored light is shown as it is) of `poly` with its own colours, or of `rgb`.
vtkSmartPointer<vtkActor> add_actor(vtkRenderer* renderer, vtkPolyData* poly, const double* rgb = nullptr) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetScalarVisibility(rgb == nullptr);
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLighting(false);
  if (rgb) actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  renderer->AddActor(actor);
  return actor;
}

glm::dvec3 probe_position(const ProbeGrid& grid, size_t probe) {
  return grid.grid_position(probe) + glm::dvec3(grid.probes[probe].offset);
}

}  // namespace

ProbeBake load_probe_bake(const std::string& path) {
  if (!std::filesystem::exists(path)) throw BakeFileError(path + ": no such file");
  ProbeBake bake;
  bake.path = path;
  bake.file = read_probe_file(path);
  const ProbeFileHeader& h = bake.file.header;
  require_whole(path, h.chunk_index, h.chunk_count, "a probe bake");
  bake.grids = probe_grids(bake.file);
  return bake;
}

struct ProbeView::Pipeline {
  vtkRenderer* renderer = nullptr;
  const ProbeBake* bake = nullptr;
  size_t volume = 0;
  const ProbeGrid* grid = nullptr;
  double cell = 1, exposure = 1, largest_offset = 0;
  size_t active = 0, relocated = 0;
  int slice = 0, slices = 1;
  size_t slice_covered = 0;
  vtkNew<vtkPolyData> spheres, slice_poly;
  vtkNew<vtkIdTypeArray> sphere_probes;  // per sphere cell: its probe
  vtkSmartPointer<vtkActor> sphere_actor;
  vtkNew<vtkSphereSource> selection;
  vtkSmartPointer<vtkActor> selection_actor;
  std::optional<size_t> selected;
  vtkNew<vtkCellPicker> picker;

  double sphere_radius(size_t probe) const { return (grid->probes[probe].active ? 0.12 : 0.07) * cell; }

  // Mean luminance of the stored irradiance over the probes that are on; 0.6 over it is the
  // display's scale, as the environment view's.
  void choose_exposure() {
    double sum = 0;
    for (const ProbeData& p : grid->probes)
      if (p.active)
        for (const glm::vec3& texel : p.irradiance) sum += luminance(glm::dvec3(texel)) / double(p.irradiance.size());
    exposure = active && sum > 0 ? 0.6 * double(active) / sum : 1;
  }

  void build_spheres() {
    vtkNew<vtkSphereSource> source;
    source->SetRadius(1);
    source->SetThetaResolution(20);
    source->SetPhiResolution(12);
    source->Update();
    vtkPolyData* unit = source->GetOutput();
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> polys;
    vtkSmartPointer<vtkUnsignedCharArray> colours = colour_array();
    for (size_t p = 0; p < grid->probe_count(); ++p) {
      const ProbeData& probe = grid->probes[p];
      const glm::dvec3 centre = probe_position(*grid, p);
      const double r = sphere_radius(p);
      const vtkIdType base = points->GetNumberOfPoints();
      for (vtkIdType i = 0; i < unit->GetNumberOfPoints(); ++i) {
        double u[3];
        unit->GetPoint(i, u);
        const glm::dvec3 n = glm::normalize(glm::dvec3(u[0], u[1], u[2]));
        const glm::dvec3 x = centre + r * n;
        points->InsertNextPoint(x.x, x.y, x.z);
        if (probe.active)
          insert_colour(colours, probe_irradiance(probe, n, ProbeRepresentation::octahedral), exposure);
        else
          colours->InsertNextTypedTuple(kOffColour);
      }
      for (vtkIdType c = 0; c < unit->GetNumberOfCells(); ++c) {
        vtkCell* cell_in = unit->GetCell(c);
        std::vector<vtkIdType> ids(size_t(cell_in->GetNumberOfPoints()));
        for (size_t k = 0; k < ids.size(); ++k) ids[k] = base + cell_in->GetPointId(vtkIdType(k));
        polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
        sphere_probes->InsertNextValue(vtkIdType(p));
      }
    }
    spheres->SetPoints(points);
    spheres->SetPolys(polys);
    spheres->GetPointData()->SetScalars(colours);
    sphere_probes->SetName("probe");
    spheres->GetCellData()->AddArray(sphere_probes);
    sphere_actor = add_actor(renderer, spheres);
  }

  // Yellow lines from each moved probe's grid point to where it sits, and the box of grid points.
  void build_lines() {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> offsets, box;
    auto line = [&](vtkCellArray* cells, glm::dvec3 a, glm::dvec3 b) {
      const vtkIdType ids[2] = {points->InsertNextPoint(a.x, a.y, a.z), points->InsertNextPoint(b.x, b.y, b.z)};
      cells->InsertNextCell(2, ids);
    };
    for (size_t p = 0; p < grid->probe_count(); ++p) {
      const double moved = glm::length(glm::dvec3(grid->probes[p].offset));
      if (!(moved > 1e-6 * cell)) continue;
      ++relocated;
      largest_offset = std::max(largest_offset, moved);
      line(offsets, grid->grid_position(p), probe_position(*grid, p));
    }
    const glm::ivec3 last = grid->counts() - 1;
    const glm::dvec3 origin = grid->grid_position(0);
    auto corner = [&](int c) {
      glm::dvec3 x = origin;
      for (int a = 0; a < 3; ++a)
        if (c >> a & 1) x += grid->axis(a) * double(last[a]);
      return x;
    };
    for (int c = 0; c < 8; ++c)
      for (int a = 0; a < 3; ++a)
        if (!(c >> a & 1)) line(box, corner(c), corner(c | 1 << a));
    vtkNew<vtkPolyData> offset_poly, box_poly;
    offset_poly->SetPoints(points);
    offset_poly->SetLines(offsets);
    box_poly->SetPoints(points);
    box_poly->SetLines(box);
    const double yellow[3] = {1.0, 0.85, 0.2}, grey[3] = {0.6, 0.6, 0.6};
    add_actor(renderer, offset_poly, yellow)->GetProperty()->SetLineWidth(2);
    add_actor(renderer, box_poly, grey);
  }

  double slice_height() const { return double(slice) / kSliceStepsPerCell; }

  // The lookup's irradiance for surfaces facing the volume's up axis, seen from a cell above,
  // on a plane across the volume's box and half a cell around it (where the lookup still
  // serves); grey where it does not reach.
  void build_slice() {
    const glm::ivec3 counts = grid->counts();
    const glm::dvec3 up = glm::normalize(grid->axis(1));
    const int nx = kSliceSamplesPerCell * counts.x + 1, nz = kSliceSamplesPerCell * counts.z + 1;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> quads;
    vtkSmartPointer<vtkUnsignedCharArray> colours = colour_array();
    slice_covered = 0;
    const glm::dvec3 origin = grid->grid_position(0);
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        const double gx = -0.5 + double(i) / kSliceSamplesPerCell, gz = -0.5 + double(k) / kSliceSamplesPerCell;
        const glm::dvec3 x = origin + grid->axis(0) * gx + grid->axis(1) * slice_height() + grid->axis(2) * gz;
        points->InsertNextPoint(x.x, x.y, x.z);
        const std::optional<glm::dvec3> e = lookup_irradiance(*grid, x, up, x + up * cell, {});
        if (e) {
          ++slice_covered;
          insert_colour(colours, *e, exposure);
        } else {
          colours->InsertNextTypedTuple(kUncoveredColour);
        }
        if (i + 1 < nx && k + 1 < nz) {
          const vtkIdType at = vtkIdType(k) * nx + i;
          const vtkIdType ids[4] = {at, at + 1, at + 1 + nx, at + nx};
          quads->InsertNextCell(4, ids);
        }
      }
    slice_poly->SetPoints(points);
    slice_poly->SetPolys(quads);
    slice_poly->GetPointData()->SetScalars(colours);
    slice_poly->Modified();
  }
};

ProbeView::ProbeView(vtkRenderer* renderer, const ProbeBake& bake, size_t volume, std::optional<double> exposure)
    : pipeline_(std::make_unique<Pipeline>()) {
  if (volume >= bake.grids.size())
    throw std::out_of_range(bake.path + ": no volume " + std::to_string(volume + 1) + "; the bake holds " +
                            std::to_string(bake.grids.size()));
  Pipeline& p = *pipeline_;
  p.renderer = renderer;
  p.bake = &bake;
  p.volume = volume;
  p.grid = &bake.grids[volume];
  p.cell = p.grid->min_spacing();
  for (const ProbeData& probe : p.grid->probes) p.active += probe.active;
  p.slices = kSliceStepsPerCell * (p.grid->counts().y - 1) + 1;
  p.slice = p.slices / 2;
  if (exposure)
    p.exposure = *exposure;
  else
    p.choose_exposure();
  p.build_spheres();
  p.build_lines();
  p.build_slice();
  add_actor(renderer, p.slice_poly)->GetProperty()->SetOpacity(0.85);

  p.selection->SetThetaResolution(16);
  p.selection->SetPhiResolution(8);
  vtkNew<vtkPolyDataMapper> selection_mapper;
  selection_mapper->SetInputConnection(p.selection->GetOutputPort());
  p.selection_actor = vtkSmartPointer<vtkActor>::New();
  p.selection_actor->SetMapper(selection_mapper);
  p.selection_actor->GetProperty()->SetRepresentationToWireframe();
  p.selection_actor->GetProperty()->SetColor(1, 1, 1);
  p.selection_actor->GetProperty()->SetLighting(false);
  p.selection_actor->VisibilityOff();
  renderer->AddActor(p.selection_actor);

  p.picker->SetTolerance(0.0005);
  p.picker->PickFromListOn();
  p.picker->AddPickList(p.sphere_actor);

  double bounds[6];
  p.slice_poly->GetBounds(bounds);
  double sphere_bounds[6];
  p.spheres->GetBounds(sphere_bounds);
  for (int a = 0; a < 3; ++a) {
    bounds[2 * a] = std::min(bounds[2 * a], sphere_bounds[2 * a]);
    bounds[2 * a + 1] = std::max(bounds[2 * a + 1], sphere_bounds[2 * a + 1]);
  }
  frame_bounds(renderer, bounds, {1.1, 0.8, 1.6});

  const glm::ivec3 c = p.grid->counts();
  std::ostringstream title;
  title.precision(3);
  title << "Probes of volume " << volume + 1 << " of " << bake.grids.size() << " in "
        << std::filesystem::path(bake.path).filename().string() << ": " << c.x << " x " << c.y << " x " << c.z
        << ", spheres shaded by stored irradiance\n"
        << p.active << " on, " << p.grid->probe_count() - p.active << " off (red, inside geometry), " << p.relocated
        << " moved (yellow lines, at most " << p.largest_offset << ")\n"
        << "slice: irradiance of up-facing surfaces, grey where no probe reaches - click a probe for its maps";
  add_title(renderer, title.str());
}

ProbeView::~ProbeView() = default;

void ProbeView::set_slice(int step) {
  Pipeline& p = *pipeline_;
  p.slice = std::clamp(step, 0, p.slices - 1);
  p.build_slice();
}

std::optional<size_t> ProbeView::pick(int x, int y) {
  Pipeline& p = *pipeline_;
  if (!p.picker->Pick(x, y, 0, p.renderer)) return std::nullopt;
  const vtkIdType cell = p.picker->GetCellId();
  if (cell < 0 || cell >= p.sphere_probes->GetNumberOfTuples()) return std::nullopt;
  return size_t(p.sphere_probes->GetValue(cell));
}

void ProbeView::select(size_t probe) {
  Pipeline& p = *pipeline_;
  if (probe >= p.grid->probe_count()) return;
  p.selected = probe;
  const glm::dvec3 centre = probe_position(*p.grid, probe);
  p.selection->SetCenter(centre.x, centre.y, centre.z);
  p.selection->SetRadius(1.6 * p.sphere_radius(probe));
  p.selection_actor->VisibilityOn();
}

ProbeMaps ProbeView::maps(size_t probe) const {
  const ProbeGrid& grid = *pipeline_->grid;
  const ProbeData& data = grid.probes.at(probe);
  ProbeMaps m;
  m.probe = probe;
  m.cell = grid.cell(probe);
  m.position = probe_position(grid, probe);
  m.active = data.active;
  m.irradiance.assign(data.irradiance.begin(), data.irradiance.end());
  for (const glm::vec2& moments : data.distance) m.distance.push_back(moments.x);
  return m;
}

ProbeViewState ProbeView::state() const {
  const Pipeline& p = *pipeline_;
  ProbeViewState s;
  s.volume = p.volume;
  s.volumes = p.bake->grids.size();
  s.counts = p.grid->counts();
  s.probes = p.grid->probe_count();
  s.active = p.active;
  s.relocated = p.relocated;
  s.largest_offset = p.largest_offset;
  s.slice = p.slice;
  s.slices = p.slices;
  s.slice_height = p.slice_height();
  s.slice_samples = size_t(p.slice_poly->GetNumberOfPoints());
  s.slice_covered = p.slice_covered;
  s.exposure = p.exposure;
  s.selected = p.selected;
  return s;
}

std::array<double, 2> ProbeView::display_point(size_t probe) const {
  const Pipeline& p = *pipeline_;
  const glm::dvec3 x = probe_position(*p.grid, probe);
  return display_point_of(p.renderer, x.x, x.y, x.z);
}

}  // namespace lg
