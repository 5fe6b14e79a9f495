// The side files of a whole bake: a VTK image data file for volumes, PNG and EXR for lightmaps.
#include "nodes/occlusion/bake/bake_outputs.h"

#include <cstdio>
#include <filesystem>

#include "nodes/raytrace/vti_file.h"
#include "runtime/image/image_file.h"

namespace lg {
namespace {

std::string sibling(const std::string& path, const char* extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

}  // namespace

std::string encode_vti(const BakeFile& volume) {
  const BakeHeader& h = volume.header;
  VtiImage image;
  image.comment = "lumagraph occlusion bake of " + h.input + ": " + std::to_string(h.occlusion.rays) +
                  " rays a point over the sphere; valid 0 marks points inside geometry (docs/bake-format.md)";
  image.dims = h.dims;
  image.origin = h.origin, image.spacing = h.spacing;
  image.arrays = {{"visibility", 1, volume.data.visibility},
                  {"bent_normal", 3, volume.data.bent_normal},
                  {"valid", 1, volume.data.valid}};
  image.scalars = "visibility", image.vectors = "bent_normal";
  return encode_vti(image);
}

std::vector<std::string> write_bake_outputs(const std::string& path, const BakeFile& file) {
  write_bake_file(path, file);
  std::vector<std::string> written{path};
  if (file.header.mode == BakeMode::volume) {
    written.push_back(sibling(path, ".vti"));
    write_bake_bytes(written.back(), encode_vti(file));
  } else if (file.header.mode == BakeMode::texel) {
    const uint32_t size = file.header.lightmap_size;
    std::vector<float> grey(size_t(size) * size * 4), bent(size_t(size) * size * 4);
    for (size_t i = 0; i < size_t(size) * size; ++i) {
      const float k = file.data.visibility[i];
      grey[4 * i] = grey[4 * i + 1] = grey[4 * i + 2] = k, grey[4 * i + 3] = 1.0f;
      for (int c = 0; c < 3; ++c) bent[4 * i + c] = file.data.bent_normal[3 * i + c];
      bent[4 * i + 3] = k;
    }
    written.push_back(sibling(path, ".png"));
    save_image(written.back(), size, size, grey);
    written.push_back(sibling(path, ".exr"));
    save_image(written.back(), size, size, bent);
  }
  return written;
}

}  // namespace lg
