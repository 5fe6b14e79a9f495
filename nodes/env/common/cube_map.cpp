#include "nodes/env/common/cube_map.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace lg {

glm::dvec3 cube_direction(int face, double u, double v) {
  const double a = 2 * u - 1, b = 2 * v - 1;
  glm::dvec3 d;
  switch (face) {
    case 0:
      d = {1, -b, -a};
      break;
    case 1:
      d = {-1, -b, a};
      break;
    case 2:
      d = {a, 1, b};
      break;
    case 3:
      d = {a, -1, -b};
      break;
    case 4:
      d = {a, -b, 1};
      break;
    default:
      d = {-a, -b, -1};
      break;
  }
  return glm::normalize(d);
}

CubeCoord cube_coord(const glm::dvec3& d) {
  const glm::dvec3 m = glm::abs(d);
  int face;
  double sc, tc, ma;
  if (m.x >= m.y && m.x >= m.z) {
    face = d.x >= 0 ? 0 : 1, ma = m.x, sc = d.x >= 0 ? -d.z : d.z, tc = -d.y;
  } else if (m.y >= m.z) {
    face = d.y >= 0 ? 2 : 3, ma = m.y, sc = d.x, tc = d.y >= 0 ? d.z : -d.z;
  } else {
    face = d.z >= 0 ? 4 : 5, ma = m.z, sc = d.z >= 0 ? d.x : -d.x, tc = -d.y;
  }
  return {face, 0.5 * (sc / ma + 1), 0.5 * (tc / ma + 1)};
}

namespace {
// Solid angle subtended by [0, x] x [0, y] of the face plane at distance 1.
double corner_area(double x, double y) {
  return std::atan2(x * y, std::sqrt(x * x + y * y + 1));
}
}  // namespace

double texel_solid_angle(uint32_t size, uint32_t i, uint32_t j) {
  const double x0 = 2.0 * i / size - 1, x1 = 2.0 * (i + 1) / size - 1;
  const double y0 = 2.0 * j / size - 1, y1 = 2.0 * (j + 1) / size - 1;
  return corner_area(x1, y1) - corner_area(x0, y1) - corner_area(x1, y0) + corner_area(x0, y0);
}

std::vector<TexelSample> texel_quadrature(int face, uint32_t size, uint32_t i, uint32_t j) {
  const double nodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double weights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  std::vector<TexelSample> samples;
  double sum = 0;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const double u = (i + 0.5 + 0.5 * nodes[a]) / size, v = (j + 0.5 + 0.5 * nodes[b]) / size;
      const double x = 2 * u - 1, y = 2 * v - 1;
      const double w = weights[a] * weights[b] / std::pow(1 + x * x + y * y, 1.5);
      samples.push_back({cube_direction(face, u, v), w});
      sum += w;
    }
  const double omega = texel_solid_angle(size, i, j);
  for (TexelSample& s : samples) s.weight *= omega / sum;
  return samples;
}

std::vector<float> CubeImage::face_floats(int face) const {
  std::vector<float> out;
  out.reserve(uint64_t(size) * size * 4);
  for (uint32_t j = 0; j < size; ++j)
    for (uint32_t i = 0; i < size; ++i)
      for (int c = 0; c < 4; ++c) out.push_back(float(at(face, i, j)[c]));
  return out;
}

CubeImage downsample(const CubeImage& mip) {
  if (mip.size < 2 || mip.size % 2) throw std::invalid_argument("downsample: face size must be even");
  CubeImage next(mip.size / 2);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < next.size; ++j)
      for (uint32_t i = 0; i < next.size; ++i) {
        glm::dvec4 sum(0.0);
        double area = 0;
        for (uint32_t dj = 0; dj < 2; ++dj)
          for (uint32_t di = 0; di < 2; ++di) {
            const double w = texel_solid_angle(mip.size, 2 * i + di, 2 * j + dj);
            sum += w * mip.at(f, 2 * i + di, 2 * j + dj);
            area += w;
          }
        next.at(f, i, j) = sum / area;
      }
  return next;
}

std::vector<CubeImage> mip_chain(CubeImage mip0) {
  std::vector<CubeImage> mips;
  mips.push_back(std::move(mip0));
  while (mips.back().size > 1) mips.push_back(downsample(mips.back()));
  return mips;
}

glm::dvec3 integrate(const CubeImage& cube) {
  glm::dvec3 sum(0.0);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < cube.size; ++j)
      for (uint32_t i = 0; i < cube.size; ++i) sum += texel_solid_angle(cube.size, i, j) * glm::dvec3(cube.at(f, i, j));
  return sum;
}

}  // namespace lg
