#include "nodes/gi/lpv/lpv_model.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kY0 = 0.28209479177387814;  // 1 / (2 sqrt(pi))
constexpr double kY1 = 0.4886025119029199;   // sqrt(3 / (4 pi))
// Solid angles of a unit cell's faces seen from the centre of the cell next to it: the far face
// (a unit square 1.5 away: 4 asin(1 / 10)) and a side face. The six neighbours' far and side
// faces are the outside of the cross they make with the centre cell, which every ray from the
// centre leaves once, so 6 far + 24 side = 4 pi: a side face is pi / 6 - asin(1 / 10) =
// 0.4234313544. (The value usually quoted with the method, 0.4234413544, has a digit wrong: with it
// a step gains 2e-5 of the light.)
const double kFarFaceSolidAngle = 4.0 * std::asin(0.1);
const double kSideFaceSolidAngle = std::numbers::pi / 6.0 - std::asin(0.1);

}  // namespace

ShL1 sh_l1_basis(glm::dvec3 d) {
  return {kY0, kY1 * d.y, kY1 * d.z, kY1 * d.x};
}

ShL1 sh_l1_cosine_lobe(glm::dvec3 n) {
  const ShL1 y = sh_l1_basis(n);
  return {kPi * y[0], 2.0 * kPi / 3.0 * y[1], 2.0 * kPi / 3.0 * y[2], 2.0 * kPi / 3.0 * y[3]};
}

double sh_l1_eval(const ShL1& sh, glm::dvec3 direction) {
  const ShL1 y = sh_l1_basis(direction);
  return sh[0] * y[0] + sh[1] * y[1] + sh[2] * y[2] + sh[3] * y[3];
}

double sh_l1_power(const ShL1& sh) {
  return std::sqrt(4.0 * kPi) * sh[0];
}

ShLobe sh_l1_lobe(const ShL1& sh) {
  // A cosine lobe b max(0, d . w) projects to b pi Y00 and b 2 pi / 3 Y1(d): c0 = b sqrt(pi) / 2,
  // |c1| = b sqrt(pi / 3); an isotropic a to c0 = a sqrt(4 pi).
  const glm::dvec3 band1(sh[3], sh[1], sh[2]);
  const double length = glm::length(band1), c0 = std::max(sh[0], 0.0);
  ShLobe out;
  out.b = std::min(length / std::sqrt(kPi / 3.0), c0 / (std::sqrt(kPi) / 2.0));
  out.a = std::max(c0 - std::sqrt(kPi) / 2.0 * out.b, 0.0) / std::sqrt(4.0 * kPi);
  if (length > 0.0) out.d = band1 / length;
  return out;
}

double sh_lobe_eval(const ShLobe& lobe, glm::dvec3 direction) {
  return lobe.a + lobe.b * std::max(glm::dot(lobe.d, direction), 0.0);
}

double sh_lobe_irradiance(const ShLobe& lobe, glm::dvec3 n) {
  const double c = std::clamp(glm::dot(lobe.d, -n), -1.0, 1.0), t = std::acos(c);
  return kPi * lobe.a + lobe.b * 2.0 / 3.0 * ((kPi - t) * c + std::sqrt(std::max(1.0 - c * c, 0.0)));
}

const std::array<glm::ivec3, 6>& lpv_directions() {
  static const std::array<glm::ivec3, 6> directions = {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0),
                                                       glm::ivec3(0, 1, 0), glm::ivec3(0, -1, 0),
                                                       glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)};
  return directions;
}

const std::array<std::array<LpvFace, kLpvFacesPerDirection>, 6>& lpv_faces() {
  static const auto table = [] {
    std::array<std::array<LpvFace, kLpvFacesPerDirection>, 6> out;
    // The flux re-emitted about the direction it crossed the face in (lpv_model.h, LpvFace).
    auto face = [](glm::dvec3 towards, double solid_angle) {
      LpvFace f{sh_l1_basis(towards), towards, sh_l1_cosine_lobe(towards), solid_angle};
      for (double& c : f.emitted_lobe) c *= solid_angle / kPi;
      return f;
    };
    for (int d = 0; d < 6; ++d) {
      const glm::dvec3 dir(lpv_directions()[d]);
      int f = 0;
      out[d][f++] = face(dir, kFarFaceSolidAngle);
      for (const glm::ivec3& s : lpv_directions())
        if (glm::dot(glm::dvec3(s), dir) == 0.0)
          out[d][f++] = face(glm::normalize(dir + 0.5 * glm::dvec3(s)), kSideFaceSolidAngle);
    }
    return out;
  }();
  return table;
}

double sh_lobe_sampled_outflow(glm::dvec3 d) {
  double sum = 0.0;
  for (const auto& faces : lpv_faces())
    for (const LpvFace& face : faces) sum += face.solid_angle * std::max(glm::dot(d, face.towards), 0.0);
  return sum;
}

LpvVolume::LpvVolume(glm::ivec3 c)
    : counts(c), light(size_t(c.x) * c.y * c.z, {ShL1{}, ShL1{}, ShL1{}}), occlusion(size_t(c.x) * c.y * c.z, ShL1{}) {}

size_t LpvVolume::index(glm::ivec3 c) const {
  return (size_t(c.z) * counts.y + c.y) * counts.x + c.x;
}

bool LpvVolume::inside(glm::ivec3 c) const {
  return glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) && glm::all(glm::lessThan(c, counts));
}

double lpv_transmittance(const ShL1& source, const ShL1& destination, glm::dvec3 direction) {
  const double blocked =
      0.5 * (sh_lobe_eval(sh_l1_lobe(source), -direction) + sh_lobe_eval(sh_l1_lobe(destination), -direction));
  return 1.0 - std::clamp(blocked, 0.0, 1.0);
}

LpvVolume propagate_step(const LpvVolume& in, bool occlude) {
  LpvVolume out(in.counts);
  out.occlusion = in.occlusion;
  for (int z = 0; z < in.counts.z; ++z)
    for (int y = 0; y < in.counts.y; ++y)
      for (int x = 0; x < in.counts.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        auto& sum = out.light[out.index(cell)];
        for (int d = 0; d < 6; ++d) {
          const glm::ivec3 source = cell - lpv_directions()[d];  // its light travels along d into this cell
          if (!in.inside(source)) continue;
          const auto& light = in.light[in.index(source)];
          std::array<ShLobe, 3> lobes = {sh_l1_lobe(light[0]), sh_l1_lobe(light[1]), sh_l1_lobe(light[2])};
          for (ShLobe& lobe : lobes)
            if (lobe.b > 0.0) lobe.b *= kPi / sh_lobe_sampled_outflow(lobe.d);
          for (const LpvFace& face : lpv_faces()[d]) {
            const double pass =
                occlude ? lpv_transmittance(in.occlusion[in.index(source)], in.occlusion[in.index(cell)], face.towards)
                        : 1.0;
            for (int c = 0; c < 3; ++c) {
              const double flux = sh_lobe_eval(lobes[c], face.towards) * pass;  // intensity towards the face
              for (int k = 0; k < 4; ++k) sum[c][k] += flux * face.emitted_lobe[k];
            }
          }
        }
      }
  return out;
}

}  // namespace lg
