// Writing VTK XML image data (vti_file.h).
#include "nodes/raytrace/vti_file.h"

#include <cstdio>

namespace lg {
namespace {

std::string format_numbers(std::span<const double> values) {
  std::string out;
  for (double v : values) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    out += (out.empty() ? "" : " ") + std::string(text);
  }
  return out;
}

void append_block(std::string& out, std::span<const float> values) {
  const uint64_t bytes = values.size() * sizeof(float);
  for (int b = 0; b < 8; ++b) out.push_back(char((bytes >> (8 * b)) & 0xff));
  out.append(reinterpret_cast<const char*>(values.data()), bytes);
}

}  // namespace

std::string encode_vti(const VtiImage& image) {
  const std::string extent = "0 " + std::to_string(image.dims[0] - 1) + " 0 " + std::to_string(image.dims[1] - 1) +
                             " 0 " + std::to_string(image.dims[2] - 1);
  // VTK writes the direction matrix row by row.
  const glm::dmat3& d = image.direction;
  const double direction[9] = {d[0][0], d[1][0], d[2][0], d[0][1], d[1][1], d[2][1], d[0][2], d[1][2], d[2][2]};
  const double origin[3] = {image.origin.x, image.origin.y, image.origin.z};
  const double spacing[3] = {image.spacing.x, image.spacing.y, image.spacing.z};
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  if (!image.comment.empty()) {
    std::string comment = image.comment;  // XML comments may not hold "--" (a node id may)
    for (size_t at; (at = comment.find("--")) != std::string::npos;) comment.replace(at, 2, "- -");
    out += "<!-- " + comment + " -->\n";
  }
  out += "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <ImageData WholeExtent=\"" + extent + "\" Origin=\"" + format_numbers(origin) + "\" Spacing=\"" +
         format_numbers(spacing) + "\" Direction=\"" + format_numbers(direction) + "\">\n";
  out += "    <Piece Extent=\"" + extent + "\">\n";
  out += "      <PointData";
  if (!image.scalars.empty()) out += " Scalars=\"" + image.scalars + "\"";
  if (!image.vectors.empty()) out += " Vectors=\"" + image.vectors + "\"";
  out += ">\n";
  uint64_t offset = 0;
  for (const VtiArray& a : image.arrays) {
    out += "        <DataArray type=\"Float32\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    offset += 8 + a.values.size() * sizeof(float);
  }
  out += "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n";
  out += "  <AppendedData encoding=\"raw\">\n   _";
  for (const VtiArray& a : image.arrays) append_block(out, a.values);
  out += "\n  </AppendedData>\n</VTKFile>\n";
  return out;
}

}  // namespace lg
