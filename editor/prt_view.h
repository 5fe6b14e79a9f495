// The inspector's view of a PRT bake (`lumagraph bake --mode prt`, NAME.lgprt) on the mesh it was
// baked from: each vertex coloured by its sky visibility, the irradiance a uniform sky of radiance 1
// gives it over pi (1 where nothing shadows it; less where the scene does; interreflected transfer
// adds what the scene reflects onto it), and, for a vertex picked by a click or by index, its
// transfer function t(w) = sum_k T_k Y_k(w) (the irradiance a unit light from direction w gives
// it, band-limited to the bake's order) on a sphere beside it, blue where the SH rings below zero.
#pragma once

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include "nodes/gi/prt/prt_file.h"
#include "nodes/raytrace/world_mesh.h"

class vtkRenderer;

namespace lg {

struct PrtBake {
  std::string path, mesh_path;
  PrtFile file;
  WorldMesh mesh;  // what it was baked from
};

// The whole bake at `path` and the mesh or scene at `mesh_path`; throws BakeFileError naming the
// file that is missing, damaged, one chunk of a bake, or not the geometry the bake was made from.
PrtBake load_prt_bake(const std::string& path, const std::string& mesh_path);

// The luminance of vertex `vertex`'s transfer function in unit direction `w`.
double transfer_luminance(const PrtBake& bake, size_t vertex, const glm::dvec3& w);

// What the view shows, for the widget's caption and for tests.
struct PrtViewState {
  size_t vertices = 0, invalid = 0;
  std::array<double, 2> sky_visibility{0, 0};  // over the valid vertices
  std::optional<size_t> selected;
  std::array<double, 2> transfer_range{0, 0};  // of the selected vertex's sphere
};

class PrtView {
 public:
  // Adds the coloured mesh, its colour bar, the title and the camera to `renderer`; `bake` must
  // outlive the view.
  PrtView(vtkRenderer* renderer, const PrtBake& bake);
  ~PrtView();
  // The vertex nearest the mesh point under display point (x, y) of the renderer, if any.
  std::optional<size_t> pick(int x, int y);
  // Shows the vertex's transfer sphere; ignored past the last vertex.
  void select(size_t vertex);
  PrtViewState state() const;
  // The display point of a vertex, for tests that click on it.
  std::array<double, 2> display_point(size_t vertex) const;

 private:
  struct Pipeline;
  std::unique_ptr<Pipeline> pipeline_;
};

}  // namespace lg
