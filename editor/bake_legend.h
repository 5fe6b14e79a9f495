// What the inspector's views share: light shown as display bytes; reading a whole bake of one mode, the world mesh a
// per-vertex bake was made from, arrays as VTK arrays, visibility with the invalid points masked (NaN, drawn grey), the
// colour map and its bar, .vti files, the title in the view's top-left corner, and the camera's framing.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkExtractVOI;
class vtkFloatArray;
class vtkImageData;
class vtkLookupTable;
class vtkActor;
class vtkColorTransferFunction;
class vtkMapper;
class vtkPolyData;
class vtkRenderer;

namespace lg {

struct BakeFile;
struct WorldMesh;
enum class BakeMode;

// The .lgbake at `path` through the bake library; throws BakeFileError naming it when it is
// missing, damaged, a chunk of a bake, or a bake of another mode than `mode` (`hint` then says
// how to open it).
BakeFile read_whole_bake(const std::string& path, BakeMode mode, const std::string& hint);

// Throws BakeFileError naming `path` when it holds one chunk of a bake (`what`: "a bake", "a
// probe bake"), which has to be merged first.
void require_whole(const std::string& path, uint32_t chunk_index, uint32_t chunk_count, const char* what);

// The world mesh of the mesh or scene file `mesh_path` (loaded as `lumagraph bake` loads it), checked against the
// geometry a per-vertex bake at `bake_path` was made from; throws BakeFileError naming the file that is missing,
// unreadable, or not that geometry (another vertex count or hash).
WorldMesh load_baked_mesh(const std::string& mesh_path, const std::string& bake_path, uint64_t input_hash,
                          uint64_t vertices);
// The VTK XML image data (.vti) at `path`, read by VTK's reader; throws BakeFileError naming it
// when it is not such a file or is damaged.
vtkSmartPointer<vtkImageData> read_vti_file(const std::string& path);

// The mesh's triangles as VTK polygons, points in world space.
vtkSmartPointer<vtkPolyData> vtk_mesh(const WorldMesh& mesh);

// Radiance or irradiance to a display byte: scaled by `exposure`, Reinhard, then gamma 2.2.
unsigned char display_byte(double v, double exposure);

inline constexpr const char* shown_visibility_name = "shown_visibility";

// `values` as a float array of `components` per point.
vtkSmartPointer<vtkFloatArray> vtk_array(const char* name, int components, const std::vector<float>& values);

struct MaskedVisibility {
  vtkSmartPointer<vtkFloatArray> shown;  // visibility, NaN where valid is 0
  std::array<double, 2> range{0, 0};     // over the valid points
  long long invalid_points = 0;
};
MaskedVisibility mask_visibility(vtkDataArray* visibility, vtkDataArray* valid);

// 256 colours of `ramp` over [0, 1], for a lookup table.
vtkSmartPointer<vtkLookupTable> table_of(vtkColorTransferFunction* ramp);
// Viridis over `range`, NaN grey.
vtkSmartPointer<vtkLookupTable> visibility_colours(std::array<double, 2> range);
// Adds an unlit actor for `mapper` coloured by `lut` over its range: unlit so that a colour on
// screen reads on the bar; colours interpolate in the map's texture, so a masked point stays
// grey, not blended.
vtkSmartPointer<vtkActor> add_visibility_actor(vtkRenderer* renderer, vtkMapper* mapper, vtkLookupTable* lut);

// The colour bar of `title` (k_A for occlusion) at the right, with a grey "`masked`" swatch below it.
void add_visibility_bar(vtkRenderer* renderer, vtkLookupTable* lut, const char* title, const char* masked);
void add_title(vtkRenderer* renderer, const std::string& text);

// Where world point (x, y, z) is on the renderer's view, in VTK's display coordinates (origin
// bottom left): for tests that click on something.
std::array<double, 2> display_point_of(vtkRenderer* renderer, double x, double y, double z);

// Points the camera at the centre of `bounds` (xmin, xmax, ymin, ymax, zmin, zmax) from
// `offset` away, Y up, shifted left of the colour bar, and fits the bounds in view.
void frame_bounds(vtkRenderer* renderer, const double bounds[6], std::array<double, 3> offset);

// A grey outline of `image`'s bounds, moved `x_offset` along x (beside another view of it).
void add_outline(vtkRenderer* renderer, vtkImageData* image, double x_offset);

// `extract` set to the one slice `index` across `axis` of an image of `dims` points.
void set_slice_voi(vtkExtractVOI* extract, const std::array<int, 3>& dims, int axis, int index);

}  // namespace lg
