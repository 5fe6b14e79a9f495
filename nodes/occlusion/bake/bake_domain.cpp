// BakeDomain: the points of vertex, texel (generated per-triangle lightmap charts) and volume
// bakes, computed on demand from a point's index so that a chunk touches only its own range.
#include "nodes/occlusion/bake/bake_domain.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace lg {
namespace {

constexpr double chart_padding = 1.0;    // texels between a chart's legs and its cell's edges
constexpr uint32_t min_cell_texels = 4;  // a chart leg of at least one texel

glm::vec3 normalized_or_zero(glm::vec3 v) {
  const float length = glm::length(v);
  return std::isfinite(length) && length > 1e-20f ? v / length : glm::vec3(0.0f);
}

}  // namespace

const char* bake_mode_name(BakeMode mode) {
  switch (mode) {
    case BakeMode::vertex:
      return "vertex";
    case BakeMode::texel:
      return "texel";
    case BakeMode::volume:
      return "volume";
  }
  return "?";
}

std::optional<BakeMode> parse_bake_mode(std::string_view name) {
  for (BakeMode m : {BakeMode::vertex, BakeMode::texel, BakeMode::volume})
    if (name == bake_mode_name(m)) return m;
  return std::nullopt;
}

BakeDomain BakeDomain::vertices(const WorldMesh& mesh) {
  return BakeDomain(BakeMode::vertex, mesh);
}

BakeDomain BakeDomain::lightmap(const WorldMesh& mesh, uint32_t size) {
  if (size < min_cell_texels || size > max_lightmap_size)
    throw std::invalid_argument("the lightmap size must be from " + std::to_string(min_cell_texels) + " to " +
                                std::to_string(max_lightmap_size) + " texels; got " + std::to_string(size));
  BakeDomain domain(BakeMode::texel, mesh);
  const size_t triangles = mesh.triangle_count();
  domain.lightmap_size_ = size;
  domain.cells_per_row_ = std::max<uint32_t>(1, uint32_t(std::ceil(std::sqrt(double(triangles)))));
  while (uint64_t(domain.cells_per_row_) * domain.cells_per_row_ < triangles) ++domain.cells_per_row_;
  domain.cell_texels_ = size / domain.cells_per_row_;
  if (domain.cell_texels_ < min_cell_texels)
    throw std::invalid_argument("a " + std::to_string(size) + "^2 lightmap is too small for " +
                                std::to_string(triangles) + " triangles: each needs a cell of at least " +
                                std::to_string(min_cell_texels) + "^2 texels, so the size must be at least " +
                                std::to_string(min_cell_texels * domain.cells_per_row_));
  return domain;
}

BakeDomain BakeDomain::volume(const WorldMesh& mesh, std::array<uint32_t, 3> dims) {
  if (mesh.positions.empty() || mesh.indices.empty())
    throw std::invalid_argument("a volume bake needs triangles to place its grid around; the input has none");
  glm::dvec3 lo(mesh.positions[0]), hi(mesh.positions[0]);
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  const glm::dvec3 extent = hi - lo;
  const double largest = std::max({extent.x, extent.y, extent.z});
  if (!(largest > 0.0))
    throw std::invalid_argument("a volume bake needs geometry with extent; every vertex is at one point");
  const glm::dvec3 padded = extent + 2.0 * volume_margin * largest, center = (lo + hi) * 0.5;
  BakeDomain domain(BakeMode::volume, mesh);
  const bool longest_only = dims[1] == 0 && dims[2] == 0;
  if (longest_only) {
    if (dims[0] < 2 || dims[0] > max_volume_axis)
      throw std::invalid_argument("a volume needs 2 to " + std::to_string(max_volume_axis) +
                                  " points along its longest axis; got " + std::to_string(dims[0]));
    const double step = std::max({padded.x, padded.y, padded.z}) / (dims[0] - 1);
    for (int a = 0; a < 3; ++a) {
      dims[a] = std::max<uint32_t>(2, uint32_t(std::ceil(padded[a] / step - 1e-9)) + 1);
      domain.spacing_[a] = step;
    }
  } else {
    for (int a = 0; a < 3; ++a) {
      if (dims[a] < 2 || dims[a] > max_volume_axis)
        throw std::invalid_argument("a volume needs 2 to " + std::to_string(max_volume_axis) +
                                    " points along each axis; got " + std::to_string(dims[a]));
      domain.spacing_[a] = padded[a] / (dims[a] - 1);
    }
  }
  const uint64_t points = uint64_t(dims[0]) * dims[1] * dims[2];
  if (points > max_volume_points)
    throw std::invalid_argument("a volume of " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                                std::to_string(dims[2]) + " points is over the limit of " +
                                std::to_string(max_volume_points));
  domain.dims_ = dims;
  for (int a = 0; a < 3; ++a) domain.origin_[a] = center[a] - domain.spacing_[a] * (dims[a] - 1) * 0.5;
  return domain;
}

uint64_t BakeDomain::size() const {
  switch (mode_) {
    case BakeMode::vertex:
      return mesh_->positions.size();
    case BakeMode::texel:
      return uint64_t(lightmap_size_) * lightmap_size_;
    case BakeMode::volume:
      return uint64_t(dims_[0]) * dims_[1] * dims_[2];
  }
  return 0;
}

BakeSample BakeDomain::sample(uint64_t index) const {
  BakeSample s;
  switch (mode_) {
    case BakeMode::vertex:
      s.point = {mesh_->positions[index], mesh_->normals[index]};
      s.coverage = glm::length(s.point.normal) > 0.0f ? 1.0f : 0.0f;
      return s;
    case BakeMode::texel:
      return texel_sample(index);
    case BakeMode::volume: {
      const uint64_t x = index % dims_[0], y = (index / dims_[0]) % dims_[1],
                     z = index / (uint64_t(dims_[0]) * dims_[1]);
      s.point.position = glm::vec3(origin_ + spacing_ * glm::dvec3(double(x), double(y), double(z)));
      s.coverage = 1.0f;
      s.sphere = true;
      return s;
    }
  }
  return s;
}

BakeSample BakeDomain::texel_sample(uint64_t index) const {
  BakeSample s;
  const uint32_t x = uint32_t(index % lightmap_size_), y = uint32_t(index / lightmap_size_);
  const uint32_t cx = x / cell_texels_, cy = y / cell_texels_;
  const uint64_t triangle = uint64_t(cy) * cells_per_row_ + cx;
  if (cx >= cells_per_row_ || cy >= cells_per_row_ || triangle >= mesh_->triangle_count()) return s;
  const double lx = x % cell_texels_ + 0.5, ly = y % cell_texels_ + 0.5;
  if (lx + ly > cell_texels_) return s;  // the cell's other half
  const double leg = cell_texels_ - 3.0;
  double b1 = (lx - chart_padding) / leg, b2 = (ly - chart_padding) / leg;
  const bool inside = b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0;
  b1 = std::max(0.0, b1), b2 = std::max(0.0, b2);
  if (b1 + b2 > 1.0) {
    const double sum = b1 + b2;
    b1 /= sum, b2 /= sum;
  }
  const double b0 = 1.0 - b1 - b2;
  const uint32_t* corner = &mesh_->indices[3 * triangle];
  const glm::dvec3 p0(mesh_->positions[corner[0]]), p1(mesh_->positions[corner[1]]), p2(mesh_->positions[corner[2]]);
  s.point.position = glm::vec3(b0 * p0 + b1 * p1 + b2 * p2);
  glm::vec3 normal = normalized_or_zero(float(b0) * mesh_->normals[corner[0]] + float(b1) * mesh_->normals[corner[1]] +
                                        float(b2) * mesh_->normals[corner[2]]);
  if (normal == glm::vec3(0.0f)) normal = normalized_or_zero(glm::vec3(glm::cross(p1 - p0, p2 - p0)));
  if (normal == glm::vec3(0.0f)) return s;  // a degenerate triangle with no usable normal
  s.point.normal = normal;
  s.coverage = inside ? 1.0f : 0.5f;
  return s;
}

std::vector<float> BakeDomain::lightmap_uvs() const {
  std::vector<float> uvs;
  if (mode_ != BakeMode::texel) return uvs;
  const double leg = cell_texels_ - 3.0;
  const double chart[3][2] = {
      {chart_padding, chart_padding}, {chart_padding + leg, chart_padding}, {chart_padding, chart_padding + leg}};
  uvs.reserve(mesh_->triangle_count() * 6);
  for (size_t t = 0; t < mesh_->triangle_count(); ++t) {
    const double cell_x = double(t % cells_per_row_) * cell_texels_, cell_y = double(t / cells_per_row_) * cell_texels_;
    for (const auto& c : chart) {
      uvs.push_back(float((cell_x + c[0]) / lightmap_size_));
      uvs.push_back(float((cell_y + c[1]) / lightmap_size_));
    }
  }
  return uvs;
}

}  // namespace lg
