// The inspector's view of a node's 3D texture as `lumagraph render --dump` writes it (NAME.vti,
// NAME.mip1.vti, ...: cli/dump_outputs.cpp), such as gi.lpv's and gi.voxel's volume outputs:
// one channel of its rgba (the colour's luminance, red, green or blue on a log scale, as HDR
// light spans decades; alpha linear) as three orthogonal slices with sliders, and beside them
// as a volume rendering whose opacity rises with the same scale. Texels with alpha 0 (gi.lpv:
// past the grid's counts; gi.voxel: empty voxels) are grey in the slices and clear in the volume.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

class vtkImageData;
class vtkRenderer;

namespace lg {

struct DumpedVolume {
  std::string path;                // the mip shown
  std::vector<std::string> mips;   // the files of every mip found beside it, mip 0 first
  int mip = 0;                     // which of them `path` is
  vtkSmartPointer<vtkImageData> image;  // point array "rgba", 4 components
};

// Reads a dumped 3D texture; throws std::runtime_error naming `path` when it is missing, not VTK
// image data, or has no 4-component "rgba" point array.
DumpedVolume load_dumped_volume(const std::string& path);

enum class VolumeChannel { luminance, red, green, blue, alpha };
std::string channel_name(VolumeChannel channel);
bool channel_is_log(VolumeChannel channel);

// What the view shows, for the widget's caption and for tests.
struct DumpedVolumeState {
  std::array<int, 3> dims{0, 0, 0};
  std::array<int, 3> slice{0, 0, 0};  // each axis's slice, first through the middle of alpha > 0
  VolumeChannel channel = VolumeChannel::luminance;
  std::array<double, 2> value_range{0, 0};   // the colour map's ends, in the channel's units
  long long slice_points = 0, masked_points = 0;  // over the three slices; masked: alpha 0, grey
  long long lit_points = 0;                  // over the whole volume: alpha > 0 and the channel > 0
};

class DumpedVolumeView {
 public:
  // Adds the slices, the volume rendering beside them, outlines, the colour bar and the title.
  DumpedVolumeView(vtkRenderer* renderer, const DumpedVolume& volume, VolumeChannel channel);
  ~DumpedVolumeView();

  void set_slice(int axis, int index);  // clamped to the grid
  DumpedVolumeState state() const;
  std::string caption() const;  // where the slices are and what the colours mean

 private:
  struct Pipeline;
  std::unique_ptr<Pipeline> pipeline_;
};

}  // namespace lg
