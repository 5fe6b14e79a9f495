#include "editor/dumped_volume_view.h"

#include <vtkColorTransferFunction.h>
#include <vtkDataSetMapper.h>
#include <vtkExtractVOI.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "editor/bake_legend.h"
#include "nodes/occlusion/bake/bake_file.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

// The log scale spans this many decades below the brightest texel: HDR light of a bounce
// fades over two to three decades from the lit surfaces; below 1e-4 of the peak nothing shows.
constexpr double kDecades = 4.0;

// NAME.vti, NAME.mip1.vti, ... beside `path` (which may be any of them), mip 0 first.
std::vector<std::string> mip_files(const fs::path& path, int* shown) {
  std::string stem = path.stem().string();  // NAME or NAME.mipK
  const size_t mip = stem.rfind(".mip");
  if (mip != std::string::npos && stem.find_first_not_of("0123456789", mip + 4) == std::string::npos &&
      mip + 4 < stem.size())
    stem = stem.substr(0, mip);
  std::vector<std::string> files;
  for (int k = 0;; ++k) {
    const fs::path file = path.parent_path() / (stem + (k > 0 ? ".mip" + std::to_string(k) : "") + ".vti");
    if (!fs::exists(file)) break;
    if (fs::equivalent(file, path)) *shown = k;
    files.push_back(file.string());
  }
  return files;
}

double channel_of(const float* rgba, VolumeChannel channel) {
  switch (channel) {
    case VolumeChannel::luminance: return 0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2];
    case VolumeChannel::red: return rgba[0];
    case VolumeChannel::green: return rgba[1];
    case VolumeChannel::blue: return rgba[2];
    case VolumeChannel::alpha: return rgba[3];
  }
  return 0.0;
}

}  // namespace

std::string channel_name(VolumeChannel channel) {
  constexpr const char* names[] = {"luminance", "red", "green", "blue", "alpha"};
  return names[int(channel)];
}

bool channel_is_log(VolumeChannel channel) {
  return channel != VolumeChannel::alpha;
}

DumpedVolume load_dumped_volume(const std::string& path) {
  if (!fs::exists(path)) throw std::runtime_error(path + ": no such file");
  if (fs::path(path).extension() != ".vti")
    throw std::runtime_error(path + ": expected a 3D texture of `lumagraph render --dump`, NAME.vti");
  DumpedVolume volume;
  volume.path = path;
  try {
    volume.image = read_vti_file(path);
  } catch (const BakeFileError& e) {
    throw std::runtime_error(e.what());
  }
  auto* rgba = vtkFloatArray::SafeDownCast(volume.image->GetPointData()->GetArray("rgba"));
  if (!rgba || rgba->GetNumberOfComponents() != 4 || rgba->GetNumberOfTuples() != volume.image->GetNumberOfPoints())
    throw std::runtime_error(path +
                             ": not a dumped 3D texture: expected a point array rgba of 4 float components a point");
  volume.mips = mip_files(fs::path(path), &volume.mip);
  return volume;
}

struct DumpedVolumeView::Pipeline {
  vtkSmartPointer<vtkImageData> image;
  std::array<int, 3> dims{0, 0, 0}, slice{0, 0, 0};
  std::array<vtkNew<vtkExtractVOI>, 3> slices;
  vtkSmartPointer<vtkLookupTable> lut;
  VolumeChannel channel = VolumeChannel::luminance;
  std::array<double, 2> value_range{0, 0};
  long long lit_points = 0;

  void place(int axis) { set_slice_voi(slices[axis], dims, axis, slice[axis]); }

  // "shown" (the slices: NaN where alpha is 0) and "volume" (the volume rendering: the scale's
  // low end there, which its opacity makes clear), in log10 for the light's channels.
  void make_arrays() {
    auto* rgba = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("rgba"));
    const vtkIdType n = rgba->GetNumberOfTuples();
    double high = 0.0;
    for (vtkIdType i = 0; i < n; ++i) {
      const float* t = rgba->GetPointer(4 * i);
      const double v = channel_of(t, channel);
      if (t[3] > 0.0f && std::isfinite(v) && v > 0.0) high = std::max(high, v), ++lit_points;
    }
    const bool log = channel_is_log(channel);
    if (log)
      value_range = {high > 0.0 ? high * std::pow(10.0, -kDecades) : 1e-4, high > 0.0 ? high : 1.0};
    else
      value_range = {0.0, 1.0};
    auto scale = [&](double v) {
      return log ? std::log10(std::clamp(v, value_range[0], value_range[1])) : std::clamp(v, 0.0, 1.0);
    };
    vtkNew<vtkFloatArray> shown, clear;
    shown->SetName("shown");
    clear->SetName("volume");
    shown->SetNumberOfTuples(n);
    clear->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) {
      const float* t = rgba->GetPointer(4 * i);
      const double v = std::isfinite(channel_of(t, channel)) ? channel_of(t, channel) : 0.0;
      clear->SetValue(i, float(t[3] > 0.0f || !log ? scale(v) : scale(0.0)));
      shown->SetValue(i, t[3] > 0.0f || !log ? float(scale(v)) : std::numeric_limits<float>::quiet_NaN());
    }
    image->GetPointData()->AddArray(shown);
    image->GetPointData()->AddArray(clear);
    image->GetPointData()->SetActiveScalars("shown");
  }

  // The middle of the texels with alpha above 0 (all of them when none has): an LPV grid over a
  // flat box fills only the lower rows of its cube, whose middle row would show nothing.
  std::array<int, 3> centre_of_content() const {
    auto* rgba = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("rgba"));
    std::array<int, 3> lo = dims, hi{-1, -1, -1};
    for (int k = 0; k < dims[2]; ++k)
      for (int j = 0; j < dims[1]; ++j)
        for (int i = 0; i < dims[0]; ++i) {
          int ijk[3] = {i, j, k};
          if (!(rgba->GetPointer(4 * image->ComputePointId(ijk))[3] > 0.0f)) continue;
          for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], ijk[a]), hi[a] = std::max(hi[a], ijk[a]);
        }
    std::array<int, 3> centre{};
    for (int a = 0; a < 3; ++a) centre[a] = hi[a] < 0 ? dims[a] / 2 : (lo[a] + hi[a] + 1) / 2;
    return centre;
  }

  double low_shown() const { return channel_is_log(channel) ? std::log10(value_range[0]) : value_range[0]; }
  double high_shown() const { return channel_is_log(channel) ? std::log10(value_range[1]) : value_range[1]; }

  // The same colours as the slices; opacity from 0 at the scale's low end, a haze through the
  // middle decades, to 0.5 at the top, so bright cells show through dimmer ones.
  void add_volume(vtkRenderer* renderer, double offset) {
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->ShallowCopy(image);
    copy->GetPointData()->SetActiveScalars("volume");
    vtkNew<vtkSmartVolumeMapper> mapper;
    mapper->SetInputData(copy);
    vtkNew<vtkColorTransferFunction> colours;
    const double lo = low_shown(), hi = high_shown();
    for (int i = 0; i <= 8; ++i) {
      const double v = lo + (hi - lo) * i / 8.0;
      double rgb[3];
      lut->GetColor(v, rgb);
      colours->AddRGBPoint(v, rgb[0], rgb[1], rgb[2]);
    }
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(lo, 0.0);
    opacity->AddPoint(lo + 0.25 * (hi - lo), 0.02);
    opacity->AddPoint(hi, 0.5);
    vtkNew<vtkVolumeProperty> property;
    property->SetColor(colours);
    property->SetScalarOpacity(opacity);
    property->SetInterpolationTypeToNearest();  // a texel is a cell or voxel: no blur across them
    property->ShadeOff();
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    volume->SetPosition(offset, 0, 0);
    renderer->AddVolume(volume);
    add_outline(renderer, image, offset);
  }
};

DumpedVolumeView::DumpedVolumeView(vtkRenderer* renderer, const DumpedVolume& volume, VolumeChannel channel)
    : pipeline_(std::make_unique<Pipeline>()) {
  Pipeline& p = *pipeline_;
  p.image = vtkSmartPointer<vtkImageData>::New();
  p.image->DeepCopy(volume.image);  // the arrays added below stay out of the loaded volume
  p.image->GetDimensions(p.dims.data());
  p.channel = channel;
  p.make_arrays();
  p.lut = visibility_colours({p.low_shown(), p.high_shown()});
  const std::array<int, 3> start = p.centre_of_content();
  for (int axis = 0; axis < 3; ++axis) {
    p.slice[axis] = start[axis];
    p.slices[axis]->SetInputData(p.image);
    p.place(axis);
    vtkNew<vtkDataSetMapper> mapper;
    mapper->SetInputConnection(p.slices[axis]->GetOutputPort());
    add_visibility_actor(renderer, mapper, p.lut);
  }
  add_outline(renderer, p.image, 0.0);
  double bounds[6];
  p.image->GetBounds(bounds);
  // The volume rendering to the right of the slices, a fifth of the grid's width apart.
  const double offset = 1.2 * (bounds[1] - bounds[0] + 1.0);
  p.add_volume(renderer, offset);
  bounds[1] += offset;
  frame_bounds(renderer, bounds, {0.4 * (bounds[1] - bounds[0]), 0.5 * (bounds[3] - bounds[2] + 1),
                                  1.6 * (bounds[1] - bounds[0])});

  const std::string unit = channel_is_log(channel) ? "log10 " + channel_name(channel) : channel_name(channel);
  add_visibility_bar(renderer, p.lut, unit.c_str(), "alpha 0");
  std::ostringstream title;
  title.precision(3);
  title << fs::path(volume.path).filename().string() << " (mip " << volume.mip << " of " << volume.mips.size()
        << ") - " << p.dims[0] << " x " << p.dims[1] << " x " << p.dims[2] << " texels\n"
        << channel_name(channel);
  if (channel_is_log(channel))
    title << " from " << p.value_range[0] << " to " << p.value_range[1] << " (log scale, " << kDecades
          << " decades below the brightest)";
  title << "\nleft: three slices (grey: alpha 0) - right: volume rendering";
  add_title(renderer, title.str());
}

DumpedVolumeView::~DumpedVolumeView() = default;

void DumpedVolumeView::set_slice(int axis, int index) {
  Pipeline& p = *pipeline_;
  p.slice[axis] = std::clamp(index, 0, p.dims[axis] - 1);
  p.place(axis);
}

DumpedVolumeState DumpedVolumeView::state() const {
  const Pipeline& p = *pipeline_;
  DumpedVolumeState s;
  s.dims = p.dims;
  s.slice = p.slice;
  s.channel = p.channel;
  s.value_range = p.value_range;
  s.lit_points = p.lit_points;
  for (const auto& slice : p.slices) {
    slice->Update();
    vtkDataArray* shown = slice->GetOutput()->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < shown->GetNumberOfTuples(); ++i) s.masked_points += std::isnan(shown->GetTuple1(i));
    s.slice_points += shown->GetNumberOfTuples();
  }
  return s;
}

std::string DumpedVolumeView::caption() const {
  const Pipeline& p = *pipeline_;
  std::ostringstream out;
  out << "slices at texel x " << p.slice[0] << ", y " << p.slice[1] << ", z " << p.slice[2] << " of " << p.dims[0]
      << " x " << p.dims[1] << " x " << p.dims[2];
  return out.str();
}

}  // namespace lg
