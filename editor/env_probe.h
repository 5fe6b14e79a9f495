// An environment probe as the inspector shows it: the equirectangular image, its L2 SH and how
// far the SH reconstruction is from the image (solid-angle weighted, over the whole sphere).
#pragma once

#include <string>

#include "editor/env_sh.h"
#include "runtime/image/image_file.h"

namespace lg {

struct EnvProbe {
  std::string path;
  ImageData image;
  ShL2 sh;
  double mean_luminance = 0;      // over the sphere
  double rms_error = 0;           // of luminance, SH against image
  double relative_rms_error = 0;  // rms_error / rms luminance of the image
  double negative_fraction = 0;   // of the sphere where the SH luminance rings below zero
};

// Loads an .hdr or .exr environment; throws ImageFileError when it cannot be read.
EnvProbe load_env_probe(const std::string& path);
EnvProbe make_env_probe(std::string path, ImageData image);

// Radiance of the image in a direction, bilinear, wrapping around in azimuth.
Vec3d sample_equirect(const ImageData& image, const Vec3d& d);

double luminance(const Vec3d& rgb);

}  // namespace lg
