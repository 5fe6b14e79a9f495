// lighting.ibl's occlusion formulas (nodes/lighting/ibl/ibl_occlusion.h) against brute-force
// quadrature in double precision (nodes/lighting/ibl/ibl_occlusion_reference.h), on random SH
// radiance and random cones from fixed seeds: the cone folded into the SH cosine lobe with its
// limits, the exact cap intersection and the specular occlusion built on it, and the range of
// the multi-bounce fit.
#include "nodes/lighting/ibl/ibl_occlusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "nodes/env/common/sh_basis.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "nodes/lighting/ibl/ibl_occlusion_reference.h"

namespace lg::test {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
}

// Random radiance SH of `order` with a dominant constant band, so that the radiance stays
// positive; band 3 is 0 (irradiance coefficients cannot carry it, see cone_lobe_irradiance).
std::vector<glm::dvec3> random_radiance_sh(std::mt19937_64& rng, int order) {
  std::normal_distribution<double> normal;
  std::vector<glm::dvec3> sh(sh_count(order));
  sh[0] = glm::dvec3(8.0, 6.0, 5.0);
  for (int l = 1; l <= order; ++l)
    for (int k = l * l; k < (l + 1) * (l + 1); ++k)
      sh[k] = l == 3 ? glm::dvec3(0.0) : glm::dvec3(normal(rng), normal(rng), normal(rng)) * (0.6 / l);
  return sh;
}

std::vector<glm::dvec3> irradiance_of(std::vector<glm::dvec3> radiance) {
  const int order = int(std::lround(std::sqrt(double(radiance.size())))) - 1;
  for (int l = 0; l <= order; ++l)
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) radiance[k] *= cosine_lobe_band(l);
  return radiance;
}

double max_component(const glm::dvec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// The cone folded into the cosine lobe against the integral itself: order 2 with the normal
// anywhere the cone stays above its horizon (the formula's bands 0 to 2 are exact there), and
// order 4 with the normal on the cone's axis (band 4's zonal factor is exact there). Tolerance
// 5e-6 of the unoccluded irradiance: the quadrature's phi sum is exact for these degrees on the
// axis (a polynomial of degree 5 in cos theta is left, whose midpoint rule errs by h^2 / 24
// max|f''|, h = (1 - c) / 400: up to about 5e-6), and off the axis the kink of max(0, n . w)
// stays outside the cone; measured 1e-6.
TEST(IblOcclusion, ConeFoldedIrradianceMatchesQuadrature) {
  std::mt19937_64 rng(601);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  for (int order : {2, 4})
    for (int trial = 0; trial < 12; ++trial) {
      const std::vector<glm::dvec3> radiance = random_radiance_sh(rng, order);
      const std::vector<glm::dvec3> irradiance = irradiance_of(radiance);
      const glm::dvec3 bent = random_unit(rng);
      const double cone_cos = 0.95 * unit(rng);
      // The normal tilted from the axis by up to 90 degrees less the cone's half-angle.
      glm::dvec3 n = bent;
      if (order == 2) {
        const glm::dvec3 across = glm::normalize(glm::cross(bent, random_unit(rng)));
        const double tilt = unit(rng) * (kPi / 2 - std::acos(cone_cos));
        n = std::cos(tilt) * bent + std::sin(tilt) * across;
      }
      const glm::dvec3 formula = cone_lobe_irradiance(irradiance, n, bent, cone_cos, 1 - cone_cos * cone_cos);
      const glm::dvec3 quadrature = cone_irradiance_quadrature(
          [&](const glm::dvec3& w) { return evaluate_sh(radiance, w); }, n, bent, cone_cos, 400);
      const double scale = max_component(evaluate_sh(irradiance, n));
      worst = std::max(worst, max_component(formula - quadrature) / scale);
    }
  std::cout << "cone-folded SH irradiance against quadrature: max error " << worst << " of the unoccluded\n";
  EXPECT_LE(worst, 5e-6);
}

// A cone of half-angle 90 degrees is the hemisphere: plain SH irradiance. A cone of 0: nothing.
TEST(IblOcclusion, ConeFoldedIrradianceLimits) {
  std::mt19937_64 rng(602);
  for (int order : {1, 2, 3, 4}) {
    const std::vector<glm::dvec3> irradiance = irradiance_of(random_radiance_sh(rng, order));
    const glm::dvec3 bent = random_unit(rng);
    const glm::dvec3 plain = evaluate_sh(irradiance, bent);
    EXPECT_LE(max_component(cone_lobe_irradiance(irradiance, bent, bent, 0.0, 1.0) - plain),
              1e-12 * max_component(plain))
        << "order " << order;
    EXPECT_EQ(cone_lobe_irradiance(irradiance, bent, bent, 1.0, 0.0), glm::dvec3(0.0)) << "order " << order;
  }
}

// A constant environment L through a cone about the normal gives pi L (1 - c^2), the cone's
// cosine-weighted visibility (as occlusion.gtao and the ray tracer define the cone): AO
// exactly; a cone tilted by t from the normal gets cos t of it.
TEST(IblOcclusion, ConstantEnvironmentThroughAConeIsAmbientOcclusion) {
  const glm::dvec3 n(0, 0, 1), tilted(std::sin(0.3), 0, std::cos(0.3));
  for (double cone_cos : {0.3, 0.7, 0.99}) {
    std::vector<glm::dvec3> irradiance(9, glm::dvec3(0.0));
    irradiance[0] = glm::dvec3(2.0 * std::sqrt(kPi) * kPi);  // L = 1
    const double visibility = 1 - cone_cos * cone_cos;
    EXPECT_NEAR(cone_lobe_irradiance(irradiance, n, n, cone_cos, visibility).x, kPi * visibility, 1e-12);
    EXPECT_NEAR(cone_lobe_irradiance(irradiance, n, tilted, cone_cos, visibility).x, kPi * visibility * std::cos(0.3),
                1e-12);
  }
}

// Cases of the cap intersection with known answers, then the closed form against quadrature on
// random axes and apertures up to the hemisphere. Tolerance 5e-6 sr: where the quadrature's
// rings graze the other cap's edge the arc grows with a square-root slope, which the midpoint
// rule integrates only to order h^1.5 (h = 1e-5); measured 1.7e-6.
TEST(IblOcclusion, CapIntersectionMatchesQuadrature) {
  EXPECT_NEAR(cap_intersection(0.0, 0.0, 1.0), 2 * kPi, 1e-12);               // the same hemisphere
  EXPECT_NEAR(cap_intersection(0.0, 0.0, 0.0), kPi, 1e-12);                   // hemispheres at right angles
  EXPECT_NEAR(cap_intersection(0.5, 0.9, 0.95), 2 * kPi * (1 - 0.9), 1e-12);  // the small cap inside
  EXPECT_EQ(cap_intersection(0.9, 0.9, 0.0), 0.0);                            // apart
  std::mt19937_64 rng(603);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 a = random_unit(rng), b = random_unit(rng);
    const double cos1 = unit(rng), cos2 = unit(rng);
    const double closed = cap_intersection(cos1, cos2, glm::dot(a, b));
    const double quadrature = cone_intersection_quadrature(a, cos1, b, cos2, 100000);
    worst = std::max(worst, std::abs(closed - quadrature));
  }
  std::cout << "cap intersection against quadrature: max error " << worst << " sr\n";
  EXPECT_LE(worst, 5e-6);
}

// The specular occlusion (visible lobe cone over the lobe cone above the horizon) against the
// same ratio by quadrature, roughness 0.2 to 1. Tolerance 1e-4: the quadrature's 5e-6 sr at
// worst over lobes of at least 2 pi a^2 / (2 - a^2) = 5e-3 sr (roughness 0.2) is 1e-3, but
// rings within a narrow lobe are short and far finer: measured 6e-8.
TEST(IblOcclusion, SpecularOcclusionMatchesQuadrature) {
  std::mt19937_64 rng(604);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 n = random_unit(rng);
    glm::dvec3 r = random_unit(rng);
    if (glm::dot(r, n) < 0) r = -r;
    const glm::dvec3 bent = glm::normalize(n + 0.8 * random_unit(rng));
    const double cone_cos = 0.9 * unit(rng), roughness = 0.2 + 0.8 * unit(rng);
    const double lobe_cos = specular_cone_cosine(roughness);
    const double above = cone_intersection_quadrature(n, 0.0, r, lobe_cos, 100000);
    const double visible = cone_intersection_quadrature(bent, cone_cos, r, lobe_cos, 100000);
    const double reference = std::clamp(visible / std::max(above, 0.05 * 2 * kPi * (1 - lobe_cos)), 0.0, 1.0);
    worst = std::max(worst, std::abs(specular_occlusion_from_cone(n, r, bent, cone_cos, roughness) - reference));
  }
  std::cout << "specular occlusion against quadrature: max error " << worst << "\n";
  EXPECT_LE(worst, 1e-4);
}

// An open plane (the cone is the normal's hemisphere) leaves specular alone at every angle and
// roughness; a lobe wholly outside the cone is occluded; a mirror sees only its direction.
TEST(IblOcclusion, SpecularOcclusionLimits) {
  const glm::dvec3 n(0, 0, 1);
  for (double roughness : {0.0, 0.1, 0.5, 1.0}) {
    for (double elevation : {0.05, 0.5, 1.5}) {
      const glm::dvec3 r(std::cos(elevation), 0, std::sin(elevation));
      EXPECT_DOUBLE_EQ(specular_occlusion_from_cone(n, r, n, 0.0, roughness), 1.0) << roughness << " " << elevation;
    }
  }
  const glm::dvec3 r = glm::normalize(glm::dvec3(1, 0, 0.2));
  EXPECT_EQ(specular_occlusion_from_cone(n, r, n, 0.95, 0.3), 0.0);  // an 18-degree cone about n
  EXPECT_EQ(specular_occlusion_from_cone(n, r, n, 0.95, 0.0), 0.0);
  EXPECT_EQ(specular_occlusion_from_cone(n, n, n, 0.95, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(specular_cone_cosine(1.0), 0.0);  // roughness 1: the hemisphere
  EXPECT_DOUBLE_EQ(specular_cone_cosine(0.0), 1.0);
  for (double roughness = 0.05; roughness < 1; roughness += 0.05)
    EXPECT_LT(specular_cone_cosine(roughness + 0.05), specular_cone_cosine(roughness));
}

// Jimenez et al.'s fit stays within [k_A, 1] for every albedo and visibility, grows with the
// albedo, and at albedo 0 (no light to bounce) is k_A: exactly once clamped, and within 0.05 for
// the bare cubic (the fit's own error there: its largest gap is 0.045 near k_A = 0.3).
TEST(IblOcclusion, MultiBounceFitStaysInRange) {
  double cubic_gap = 0;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) {
      const double visibility = i / 100.0, albedo = j / 100.0;
      const double g = multi_bounce_occlusion(visibility, albedo);
      ASSERT_GE(g, visibility) << visibility << " " << albedo;
      ASSERT_LE(g, 1.0) << visibility << " " << albedo;
      if (j > 0) {
        ASSERT_GE(g, multi_bounce_occlusion(visibility, (j - 1) / 100.0)) << visibility << " " << albedo;
      }
      if (j == 0) {
        EXPECT_EQ(g, visibility);
        cubic_gap = std::max(cubic_gap, std::abs(multi_bounce_cubic(visibility, 0.0) - visibility));
      }
    }
  std::cout << "multi-bounce cubic at albedo 0: largest gap to k_A " << cubic_gap << "\n";
  EXPECT_LE(cubic_gap, 0.05);
  EXPECT_GT(multi_bounce_occlusion(0.5, 0.8), 0.6);  // a bright albedo brings light back
}

}  // namespace
}  // namespace lg::test
