// The side files of a whole bake: a VTK image data file for volumes, PNG and EXR for lightmaps.
#include "nodes/occlusion/bake/bake_outputs.h"

#include <cstdio>
#include <filesystem>

#include "graph/json_writer.h"
#include "runtime/image/image_file.h"

namespace lg {
namespace {

std::string format_vector(glm::dvec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "%.17g %.17g %.17g", v.x, v.y, v.z);
  return text;
}

void append_block(std::string& out, const std::vector<float>& values) {
  const uint64_t bytes = values.size() * sizeof(float);
  for (int b = 0; b < 8; ++b) out.push_back(char((bytes >> (8 * b)) & 0xff));
  out.append(reinterpret_cast<const char*>(values.data()), bytes);
}

void write_or_throw(const std::string& path, const std::string& bytes) {
  std::string error;
  if (!write_file_atomically(path, bytes, &error)) throw BakeFileError(path + ": " + error);
}

std::string sibling(const std::string& path, const char* extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

}  // namespace

std::string encode_vti(const BakeFile& volume) {
  const BakeHeader& h = volume.header;
  const std::string extent = "0 " + std::to_string(h.dims[0] - 1) + " 0 " + std::to_string(h.dims[1] - 1) + " 0 " +
                             std::to_string(h.dims[2] - 1);
  const uint64_t scalar_block = 8 + h.points * sizeof(float), vector_block = 8 + 3 * h.points * sizeof(float);
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<!-- lumagraph occlusion bake of " + h.input + ": " + std::to_string(h.occlusion.rays) +
         " rays a point over the sphere; valid 0 marks points inside geometry (docs/bake-format.md) -->\n";
  out += "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <ImageData WholeExtent=\"" + extent + "\" Origin=\"" + format_vector(h.origin) + "\" Spacing=\"" +
         format_vector(h.spacing) + "\" Direction=\"1 0 0 0 1 0 0 0 1\">\n";
  out += "    <Piece Extent=\"" + extent + "\">\n";
  out += "      <PointData Scalars=\"visibility\" Vectors=\"bent_normal\">\n";
  out +=
      "        <DataArray type=\"Float32\" Name=\"visibility\" NumberOfComponents=\"1\" format=\"appended\" "
      "offset=\"0\"/>\n";
  out +=
      "        <DataArray type=\"Float32\" Name=\"bent_normal\" NumberOfComponents=\"3\" format=\"appended\" "
      "offset=\"" +
      std::to_string(scalar_block) + "\"/>\n";
  out +=
      "        <DataArray type=\"Float32\" Name=\"valid\" NumberOfComponents=\"1\" format=\"appended\" "
      "offset=\"" +
      std::to_string(scalar_block + vector_block) + "\"/>\n";
  out += "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n";
  out += "  <AppendedData encoding=\"raw\">\n   _";
  append_block(out, volume.data.visibility);
  append_block(out, volume.data.bent_normal);
  append_block(out, volume.data.valid);
  out += "\n  </AppendedData>\n</VTKFile>\n";
  return out;
}

std::vector<std::string> write_bake_outputs(const std::string& path, const BakeFile& file) {
  write_bake_file(path, file);
  std::vector<std::string> written{path};
  if (file.header.mode == BakeMode::volume) {
    written.push_back(sibling(path, ".vti"));
    write_or_throw(written.back(), encode_vti(file));
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
