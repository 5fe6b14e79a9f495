#include "nodes/occlusion/reference/height_field_reference.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "nodes/common/gbuffer_normal.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {
namespace {

// A hit must lie behind the buffer by this fraction of its depth: float depth and the
// bilinear reconstruction are exact to far better than that, and real occluders are far
// thicker.
constexpr double kBehindTolerance = 1e-5;

// The first of the two texel centres that bracket (or, at the border, are nearest) `f`.
uint32_t cell(double f, uint32_t size) {
  return size < 2 ? 0u : uint32_t(std::clamp(std::floor(f), 0.0, double(size - 2)));
}

class HeightField {
 public:
  HeightField(const CameraPixels& pixels, const GbufferReadback& g) : pixels_(pixels), g_(g) {}

  // Linear depth of the buffer at continuous pixel coordinates, bilinear in device depth; in
  // the half pixel along the image's border it extrapolates the nearest cell linearly (exact on
  // planes too, where clamping would not be).
  double linear_depth(double px, double py) const {
    const double fx = px - 0.5, fy = py - 0.5;
    const uint32_t x0 = cell(fx, g_.width), y0 = cell(fy, g_.height);
    const uint32_t x1 = std::min(x0 + 1, g_.width - 1), y1 = std::min(y0 + 1, g_.height - 1);
    const double ax = fx - x0, ay = fy - y0;
    const auto d = [&](uint32_t x, uint32_t y) { return double(g_.depth[size_t(y) * g_.width + x]); };
    const double top = d(x0, y0) + ax * (d(x1, y0) - d(x0, y0));
    const double bottom = d(x0, y1) + ax * (d(x1, y1) - d(x0, y1));
    const double device = top + ay * (bottom - top);
    return device > 0.0 ? pixels_.near_plane() / device : INFINITY;
  }

  // Distance along view-space ray p + t dir to its first point behind the height field within
  // max_distance, or infinity when it escapes (off screen, in front of the near plane).
  double hit_distance(glm::dvec3 p, glm::dvec3 dir, double max_distance) const {
    const double near = pixels_.near_plane();
    double length = std::isfinite(max_distance) ? max_distance : 1e6 * std::max(1.0, glm::length(p));
    if (dir.z > 0.0) length = std::min(length, (-p.z - near * 1.001) / dir.z);  // stay beyond the near plane
    if (!(length > 0.0)) return INFINITY;
    const glm::dvec4 a = pixels_.project(p), b = pixels_.project(p + dir * length);
    // Screen-space march over the projected segment, clipped to the image, at half-pixel
    // steps; s is linear on the screen, alpha the matching (perspective-correct) ray fraction.
    double s_end = 1.0;
    const double lo[2] = {0.0, 0.0}, hi[2] = {double(g_.width), double(g_.height)};
    for (int k = 0; k < 2; ++k) {
      const double d = b[k] - a[k];
      if (d > 0.0) s_end = std::min(s_end, (hi[k] - a[k]) / d);
      if (d < 0.0) s_end = std::min(s_end, (lo[k] - a[k]) / d);
    }
    const double pixels_long = std::hypot(b.x - a.x, b.y - a.y) * s_end;
    const int steps = std::max(1, int(std::ceil(2.0 * pixels_long)));
    for (int k = 1; k <= steps; ++k) {
      const double s = s_end * k / steps;
      const double alpha = s * a.w / ((1.0 - s) * b.w + s * a.w);
      const double ray_depth = a.w + alpha * (b.w - a.w);
      const double px = a.x + s * (b.x - a.x), py = a.y + s * (b.y - a.y);
      if (ray_depth > linear_depth(px, py) * (1.0 + kBehindTolerance)) return alpha * length;
    }
    return INFINITY;
  }

 private:
  const CameraPixels& pixels_;
  const GbufferReadback& g_;
};

}  // namespace

AoImage trace_height_field_reference(const CameraView& camera, const GbufferReadback& gbuffer,
                                     const AoSettings& settings, uint32_t stride) {
  const size_t n = size_t(gbuffer.width) * gbuffer.height;
  if (gbuffer.depth.size() != n || gbuffer.normal.size() != 4 * n)
    throw std::invalid_argument("trace_height_field_reference: a " + std::to_string(gbuffer.width) + "x" +
                                std::to_string(gbuffer.height) + " G-buffer needs " + std::to_string(n) +
                                " depths and " + std::to_string(4 * n) + " normal values, got " +
                                std::to_string(gbuffer.depth.size()) + " and " + std::to_string(gbuffer.normal.size()));
  stride = std::max(1u, stride);
  const CameraPixels pixels(camera, gbuffer.width, gbuffer.height);
  const HeightField field(pixels, gbuffer);
  const glm::dmat3 to_view(pixels.view_from_world());
  AoImage out(gbuffer.width, gbuffer.height);
  parallel_for((gbuffer.height + stride - 1) / stride, [&](size_t row) {
    const uint32_t y = uint32_t(row) * stride;
    for (uint32_t x = 0; x < gbuffer.width; x += stride) {
      const size_t i = size_t(y) * gbuffer.width + x;
      const double depth = gbuffer.depth[i];
      if (!(depth > 0.0)) continue;  // nothing there: no reference
      const glm::dvec3 p = pixels.view_position(x + 0.5, y + 0.5, depth);
      const glm::dvec3 normal = decode_gbuffer_normal(&gbuffer.normal[4 * i]);
      OcclusionSum sum;
      for (const glm::dvec3& d : cosine_directions(normal, settings, i))
        sum.add(d, occlusion_weight(field.hit_distance(p, to_view * d, settings.max_distance), settings));
      out.visibility[i] = float(sum.visibility());
      out.bent[i] = glm::vec4(sum.bent_normal_and_cone(normal));
    }
  });
  return out;
}

}  // namespace lg
