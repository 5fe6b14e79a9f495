// VTK XML image data (.vti), what the CPU bakes write beside their own files so that ParaView and
// VTK's vtkXMLImageDataReader show a grid of points: version 1.0, little-endian, UInt64 block
// headers, Float32 point arrays in raw appended data.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

namespace lg {

struct VtiArray {
  std::string name;
  uint32_t components = 1;
  std::span<const float> values;  // components per point, points x fastest, then y, then z
};

struct VtiImage {
  std::string comment;  // one line, written as an XML comment (each "--" in it as "- -")
  std::array<uint32_t, 3> dims{1, 1, 1};
  glm::dvec3 origin{0.0}, spacing{1.0};
  glm::dmat3 direction{1.0};  // columns: the unit grid axes in world space
  std::vector<VtiArray> arrays;
  std::string scalars, vectors;  // the active arrays' names; empty: none
};

std::string encode_vti(const VtiImage& image);

}  // namespace lg
