// The cube-map convention of every env node, on the CPU (nodes/env/common/shaders/cube_map.glsl
// is the same on the GPU): Vulkan's face order +X, -X, +Y, -Y, +Z, -Z (array layers 0 to 5) and
// its face-to-direction mapping (Vulkan spec, "Cube Map Face Selection"); texel (i, j) of a face
// of size N has u = (i + 0.5) / N, v = (j + 0.5) / N, row j = 0 first in memory. World up is +Y.
// Also host-side cube images with their texel solid angles and area-correct mip chains.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace lg {

// The unit direction through (u, v) in [0, 1]^2 of `face`.
glm::dvec3 cube_direction(int face, double u, double v);

struct CubeCoord {
  int face = 0;
  double u = 0, v = 0;  // in [0, 1]
};
// The face and (u, v) a direction (not necessarily unit) hits; the inverse of cube_direction.
CubeCoord cube_coord(const glm::dvec3& direction);

// The exact solid angle of texel (i, j) on a face of `size` texels (the same for every face).
double texel_solid_angle(uint32_t size, uint32_t i, uint32_t j);

// Points and solid-angle weights that integrate a smooth function over texel (i, j) of `face`:
// 4x4 Gauss-Legendre points of the face plane, weights proportional to the Jacobian and
// summing to the exact solid angle (so a constant integrates exactly).
struct TexelSample {
  glm::dvec3 direction;
  double weight;
};
std::vector<TexelSample> texel_quadrature(int face, uint32_t size, uint32_t i, uint32_t j);

// One mip of a cube map in host memory: RGBA per texel, faces in order, rows top to bottom.
struct CubeImage {
  uint32_t size = 0;
  std::vector<glm::dvec4> texels;  // 6 * size * size

  explicit CubeImage(uint32_t face_size = 0) : size(face_size), texels(6u * face_size * face_size) {}
  glm::dvec4& at(int face, uint32_t i, uint32_t j) { return texels[(uint64_t(face) * size + j) * size + i]; }
  const glm::dvec4& at(int face, uint32_t i, uint32_t j) const {
    return texels[(uint64_t(face) * size + j) * size + i];
  }
  glm::dvec3 direction(int face, uint32_t i, uint32_t j) const {
    return cube_direction(face, (i + 0.5) / size, (j + 0.5) / size);
  }
  // One face as float RGBA, for upload_image.
  std::vector<float> face_floats(int face) const;
};

// The next mip: each texel the solid-angle-weighted mean of the 2x2 it covers (the radiance
// averaged over its area, so every mip holds the same integral of radiance). `mip.size` > 1, even.
CubeImage downsample(const CubeImage& mip);
// Mip 0 and every smaller mip down to 1x1 (`mip0.size` a power of two).
std::vector<CubeImage> mip_chain(CubeImage mip0);

// Integral of radiance over the sphere, sum of texel * solid angle.
glm::dvec3 integrate(const CubeImage& cube);

}  // namespace lg
