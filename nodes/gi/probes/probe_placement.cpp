#include "nodes/gi/probes/probe_placement.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>

#include "nodes/gi/probes/probe_directions.h"

namespace lg {
namespace {

constexpr double kBackFaceLimit = 0.25;  // DDGI's fraction of back-face hits that means "inside"
constexpr int kRelocationTries = 3;

struct NearestHits {
  double back_fraction = 0.0;
  glm::dvec3 back_direction{0.0}, front_direction{0.0};
  double back_distance = std::numeric_limits<double>::infinity(), front_distance = back_distance;
};

NearestHits look_around(const RayScene& rays, glm::dvec3 p, uint32_t count, const glm::dmat3& rotation) {
  NearestHits h;
  uint32_t back = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::dvec3 d = sphere_direction(i, count, rotation);
    const auto hit = rays.intersect(glm::vec3(p), glm::vec3(d), std::numeric_limits<float>::infinity());
    if (!hit) continue;
    const bool is_back = glm::dot(glm::dvec3(hit->normal), d) > 0.0;
    back += is_back;
    double& nearest = is_back ? h.back_distance : h.front_distance;
    if (hit->distance < nearest) {
      nearest = hit->distance;
      (is_back ? h.back_direction : h.front_direction) = d;
    }
  }
  h.back_fraction = double(back) / count;
  return h;
}

// Keeps an offset within half a cell along each of the grid's axes.
glm::dvec3 clamp_offset(const ProbeGrid& grid, glm::dvec3 offset) {
  glm::dvec3 out(0.0);
  for (int a = 0; a < 3; ++a) {
    const glm::dvec3 axis = grid.axis(a);
    const double length2 = glm::dot(axis, axis);
    if (!(length2 > 0.0)) continue;  // a box flat along this axis: nowhere to move
    const double t = std::clamp(glm::dot(offset, axis) / length2, -0.5, 0.5);
    out += t * axis;
  }
  return out;
}

}  // namespace

bool place_probe(const RayScene& rays, const ProbeGrid& grid, size_t index, uint32_t count, const glm::dmat3& rotation,
                 glm::dvec3& offset) {
  const glm::dvec3 home = grid.grid_position(index);
  const double near = 0.1 * grid.min_spacing();
  offset = glm::dvec3(0.0);
  for (int attempt = 0; attempt <= kRelocationTries; ++attempt) {
    const NearestHits h = look_around(rays, home + offset, count, rotation);
    if (h.back_fraction > kBackFaceLimit) {
      if (attempt == kRelocationTries) return false;
      // Through the nearest back face, a little past it.
      offset = clamp_offset(grid, offset + h.back_direction * (h.back_distance + 0.05 * near));
      continue;
    }
    if (h.front_distance < near) offset = clamp_offset(grid, offset - h.front_direction * (near - h.front_distance));
    return true;
  }
  return false;
}

}  // namespace lg
