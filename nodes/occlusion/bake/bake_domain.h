// Where a bake puts its points, in a fixed order that chunks split into contiguous ranges:
// - vertex: every vertex of the world mesh (draws in order), at its position with its normal;
// - texel: every texel of a size x size lightmap, row-major from the top-left, on a generated
//   lightmap UV set (per-triangle charts, below);
// - volume: every point of a regular grid around the geometry, x fastest, then y, then z (VTK
//   image data's point order); volume points have no normal and sample the whole sphere.
//
// The lightmap UV set: the bake always generates its own, because MeshData carries one UV set,
// the texture's, which may tile or overlap. Triangle t gets the square cell (t mod G, t div G)
// of a G x G grid, G = ceil(sqrt(triangles)), each cell c = floor(size / G) texels wide. Its
// chart is the right triangle with corners (1, 1), (1 + L, 1), (1, 1 + L) in the cell's texel
// units, L = c - 3, corner k of the triangle at chart corner k: at least one texel of padding
// on the legs and 0.7 on the hypotenuse. Texels of the cell's lower-left half (centre x + y <=
// c) hold the occlusion of the chart point nearest their centre (clamped barycentrics):
// coverage 1 when the centre is inside the chart, 0.5 for padding; all other texels 0. UV
// (0, 0) is the image's top-left corner, v grows downward (glTF's convention).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nodes/occlusion/estimate/occlusion_estimate.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {

enum class BakeMode { vertex, texel, volume };
const char* bake_mode_name(BakeMode mode);
std::optional<BakeMode> parse_bake_mode(std::string_view name);

// Bounds that keep one bake's output and memory reasonable (a volume point costs 20 bytes of
// output; 2^26 points are 1.3 GB).
inline constexpr uint32_t max_lightmap_size = 8192;
inline constexpr uint32_t max_volume_axis = 1024;
inline constexpr uint64_t max_volume_points = uint64_t(1) << 26;
// Around the geometry's bounds a volume extends by this fraction of their largest extent.
inline constexpr double volume_margin = 0.1;

struct BakeSample {
  SurfacePoint point;
  float coverage = 0.0f;  // 0: nothing to bake here; texel padding 0.5; else 1
  bool sphere = false;    // a volume point: sample the whole sphere, no normal
};

class BakeDomain {
 public:
  // The mesh must outlive the domain. Throw std::invalid_argument naming what is out of range.
  static BakeDomain vertices(const WorldMesh& mesh);
  static BakeDomain lightmap(const WorldMesh& mesh, uint32_t size);
  // `dims` all given, or {n, 0, 0}: n points along the longest axis and cubic cells.
  static BakeDomain volume(const WorldMesh& mesh, std::array<uint32_t, 3> dims);

  BakeMode mode() const { return mode_; }
  uint64_t size() const;  // points
  BakeSample sample(uint64_t index) const;

  // texel: the image's side, and the lightmap UV of each triangle corner (2 floats each,
  // 6 per triangle, in triangle order).
  uint32_t lightmap_size() const { return lightmap_size_; }
  std::vector<float> lightmap_uvs() const;
  // volume: points per axis, the first point's position and the step between points.
  std::array<uint32_t, 3> dims() const { return dims_; }
  glm::dvec3 origin() const { return origin_; }
  glm::dvec3 spacing() const { return spacing_; }

 private:
  BakeDomain(BakeMode mode, const WorldMesh& mesh) : mode_(mode), mesh_(&mesh) {}
  BakeSample texel_sample(uint64_t index) const;

  BakeMode mode_;
  const WorldMesh* mesh_;
  uint32_t lightmap_size_ = 0, cells_per_row_ = 0, cell_texels_ = 0;
  std::array<uint32_t, 3> dims_{0, 0, 0};
  glm::dvec3 origin_{0.0}, spacing_{0.0};
};

}  // namespace lg
