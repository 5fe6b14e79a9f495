// The inspector's view of a baked occlusion volume (`lumagraph bake --mode volume`): the bake
// as VTK image data, read from its NAME.vti by VTK's own reader or from its NAME.lgbake by the
// bake library's reader, and three orthogonal slices through it coloured by ambient
// visibility, points inside geometry in grey, with the bent normals as arrows on the z slice.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <string>

class vtkImageData;
class vtkRenderer;

namespace lg {

struct BakeVolume {
  std::string path;
  // Point arrays visibility, bent_normal (the active vectors), valid, and shown_visibility (the
  // active scalars): visibility with NaN where valid is 0, so the colour map masks those points.
  vtkSmartPointer<vtkImageData> image;
  std::array<double, 2> visibility_range{0, 0};  // over the valid points
  long long invalid_points = 0;
};

// Throws BakeFileError naming `path` when it is missing, damaged or not a whole volume bake.
BakeVolume load_bake_volume(const std::string& path);

// What the slices show, for the widget's caption and for tests.
struct VolumeSliceState {
  std::array<int, 3> dims{0, 0, 0};
  std::array<int, 3> slice{0, 0, 0};              // the point index of each axis's slice
  std::array<double, 2> colour_range{0, 0};       // the colour map's visibility range
  long long slice_points = 0, masked_points = 0;  // over the three slices, masked: shown as NaN
  long long arrows = 0;                           // bent normals drawn
};

class VolumeSlices {
 public:
  // Adds the slices, an outline, axes, the colour bar and the title to `renderer`.
  VolumeSlices(vtkRenderer* renderer, const BakeVolume& volume);
  ~VolumeSlices();

  void set_slice(int axis, int index);  // clamped to the grid
  VolumeSliceState state() const;
  std::string slice_caption() const;  // where the slices are, in points and world units

 private:
  struct Pipeline;
  std::unique_ptr<Pipeline> pipeline_;
};

}  // namespace lg
