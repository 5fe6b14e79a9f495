// The white furnace: a camera at the centre of a closed sphere whose inside emits Le and
// reflects with the raster path's BRDF. By symmetry the radiance leaving the wall depends only
// on the angle to its normal, and a chord leaves and arrives at the same angle, so
// L(mu_o) = Le + integral over mu_i of K(mu_o, mu_i) L(mu_i), K the BRDF times n.l integrated
// over azimuth. Solved here by the Nystrom method (Gauss-Legendre in mu, midpoint in azimuth),
// independently of the path tracer's sampling; the camera sees L(1). For a Lambertian wall of
// albedo rho the solution is Le / (1 - rho), which checks the solver itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "nodes/gi/path_tracer/microfacet_brdf.h"
#include "nodes/gi/path_tracer/path_tracer.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/world.h"

namespace lg::test {
namespace {

constexpr double kPi = std::numbers::pi;

// Gauss-Legendre nodes and weights on [0, 1] (Newton on the Legendre recurrence).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n), w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      derivative = n * (z * p0 - p1) / (z * z - 1.0);
      const double step = p0 / derivative;
      z -= step;
      if (std::abs(step) < 1e-15) break;
    }
    x[i] = 0.5 * (1.0 - z);
    w[i] = 1.0 / ((1.0 - z * z) * derivative * derivative);  // 2 / (...) on [-1, 1], halved
  }
}

// L(1) inside the sphere for a wall whose BRDF times n.l is `f_cos(view, light)` (local frame,
// normal +Z) and emission le.
double furnace_solution(const std::function<double(glm::dvec3, glm::dvec3)>& f_cos, double le, int mu_nodes = 96,
                        int phi_steps = 1024) {
  std::vector<double> mu, w;
  gauss_legendre(mu_nodes, mu, w);
  auto direction = [](double m, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - m * m));
    return glm::dvec3(s * std::cos(phi), s * std::sin(phi), m);
  };
  auto kernel = [&](double mu_o, double mu_i) {  // integral over azimuth of f cos
    double sum = 0.0;
    for (int k = 0; k < phi_steps; ++k)
      sum += f_cos(direction(mu_o, 0.0), direction(mu_i, 2.0 * kPi * (k + 0.5) / phi_steps));
    return sum * 2.0 * kPi / phi_steps;
  };
  // (I - K W) L = le, by Gaussian elimination.
  const int n = mu_nodes;
  std::vector<double> a(size_t(n) * (n + 1));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) a[size_t(i) * (n + 1) + j] = (i == j ? 1.0 : 0.0) - kernel(mu[i], mu[j]) * w[j];
    a[size_t(i) * (n + 1) + n] = le;
  }
  for (int c = 0; c < n; ++c)
    for (int r = c + 1; r < n; ++r) {
      const double factor = a[size_t(r) * (n + 1) + c] / a[size_t(c) * (n + 1) + c];
      for (int k = c; k <= n; ++k) a[size_t(r) * (n + 1) + k] -= factor * a[size_t(c) * (n + 1) + k];
    }
  std::vector<double> l(n);
  for (int r = n - 1; r >= 0; --r) {
    double s = a[size_t(r) * (n + 1) + n];
    for (int k = r + 1; k < n; ++k) s -= a[size_t(r) * (n + 1) + k] * l[k];
    l[r] = s / a[size_t(r) * (n + 1) + r];
  }
  double seen = le;  // the Nystrom interpolant at mu = 1
  for (int j = 0; j < n; ++j) seen += kernel(1.0, mu[j]) * w[j] * l[j];
  return seen;
}

SceneView furnace_scene(const PbrMaterial& material) {
  World world;
  Entity sphere = world.create("furnace");
  world.add(sphere, MeshRenderer{world.add_mesh(make_sphere(1.0f, 192, 96)), world.add_material(material)});
  world.add(sphere, Transform{});
  Entity camera = world.create("camera");
  world.add(camera, Camera{.vertical_fov = 1.2f, .near_plane = 0.01f});
  world.add(camera, Transform{});
  return make_scene_view(world, 1.0f);
}

ReferenceImage trace_furnace(const PbrMaterial& material, uint32_t spp) {
  const PathScene scene(furnace_scene(material), PathEnvironment::none());
  PathTracerOptions o;
  o.width = o.height = 16;
  o.samples_per_pixel = spp;
  o.max_bounces = 1024;      // Russian roulette ends the paths
  o.cull_backfaces = false;  // the camera sees the sphere's inside, its back faces
  ReferenceImage image = trace_reference(scene, o);
  EXPECT_EQ(image.non_finite_samples, 0u);
  return image;
}

// The image's mean radiance (green) and that mean's standard error (pixels are independent).
std::pair<double, double> image_mean(const ReferenceImage& image) {
  const auto& mean = image.mean_of(ReferenceAov::radiance);
  const auto& error = image.error_of(ReferenceAov::radiance);
  double sum = 0.0, variance = 0.0;
  for (size_t i = 0; i < mean.size(); ++i) sum += mean[i].g, variance += double(error[i].g) * error[i].g;
  return {sum / double(mean.size()), std::sqrt(variance) / double(mean.size())};
}

// Root mean square over the pixels of the actual error against `expected` and of the stated one.
std::pair<double, double> pixel_errors(const ReferenceImage& image, double expected) {
  const auto& mean = image.mean_of(ReferenceAov::radiance);
  const auto& error = image.error_of(ReferenceAov::radiance);
  double actual = 0.0, stated = 0.0;
  for (size_t i = 0; i < mean.size(); ++i)
    actual += (mean[i].g - expected) * (mean[i].g - expected), stated += double(error[i].g) * error[i].g;
  return {std::sqrt(actual / double(mean.size())), std::sqrt(stated / double(mean.size()))};
}

PbrMaterial emitting_wall(float albedo, float roughness, float metalness) {
  PbrMaterial m;
  m.base_color = glm::vec4(albedo, albedo, albedo, 1.0f);
  m.roughness = roughness, m.metalness = metalness, m.emissive = glm::vec3(1.0f);
  return m;
}
const PbrMaterial kRoughDielectric = emitting_wall(0.5f, 1.0f, 0.0f);
const PbrMaterial kGlossyMetal = emitting_wall(0.8f, 0.5f, 1.0f);

double solved_radiance(const PbrMaterial& m) {
  const BrdfSurface surface = make_brdf_surface(
      {0.0, 0.0, 1.0}, SurfaceMaterial{glm::dvec3(m.base_color), m.roughness, m.metalness, glm::dvec3(0.0)});
  return furnace_solution([&](glm::dvec3 v, glm::dvec3 l) { return evaluate_brdf(surface, v, l).sum().g; },
                          m.emissive.g);
}

// A white surface (albedo 1) under a constant environment of 1 reflects 1 toward every view:
// the integral of the BRDF times n.l over the hemisphere, each lobe through the path tracer's
// own sampler and density on a 128 x 128 midpoint grid. Dielectric and metal, roughness 0 to 1 in
// steps of 0.1, views from n.v = 1e-4 (grazing) to 1. Tolerance 1%, the raster path's criterion;
// what remains is the albedo table's interpolation (nodes/env/brdf_lut/brdf_albedo.h).
TEST(Furnace, WhiteSurfacesReflectAConstantEnvironmentWhole) {
  constexpr int grid = 128;
  double worst = 0.0;
  for (const double metalness : {0.0, 1.0})
    for (int r = 0; r <= 10; ++r)
      for (int k = 0; k <= 16; ++k) {
        const double t = k / 16.0, n_dot_v = 1e-4 + (1 - 1e-4) * t * t;
        const BrdfSurface s = make_brdf_surface({0.0, 0.0, 1.0}, SurfaceMaterial{glm::dvec3(1.0), r / 10.0, metalness});
        const glm::dvec3 v(std::sqrt(1 - n_dot_v * n_dot_v), 0.0, n_dot_v);
        double reflected = 0.0;
        for (int a = 0; a < grid; ++a)
          for (int b = 0; b < grid; ++b) {
            const glm::dvec2 u((a + 0.5) / grid, (b + 0.5) / grid);
            const glm::dvec3 ls = sample_specular(s, v, u), ld = sample_diffuse(s, u);
            const double ps = specular_pdf(s, v, ls), pd = diffuse_pdf(s, ld);
            if (ps > 0.0) reflected += evaluate_brdf(s, v, ls).specular.g / ps;
            if (pd > 0.0) reflected += evaluate_brdf(s, v, ld).diffuse.g / pd;
          }
        reflected /= grid * grid;
        EXPECT_TRUE(std::isfinite(reflected));
        worst = std::max(worst, std::abs(reflected - 1.0));
        EXPECT_NEAR(reflected, 1.0, 0.01)
            << "metalness " << metalness << ", roughness " << r / 10.0 << ", n.v " << n_dot_v;
      }
  std::printf("path tracer's BRDF, white furnace: max |reflected - 1| = %.5f\n", worst);
}

TEST(Furnace, NystromSolverGivesTheClosedFormForLambert) {
  const double rho = 0.6, le = 1.5;
  const double solved =
      furnace_solution([&](glm::dvec3, glm::dvec3 l) { return l.z > 0.0 ? rho / kPi * l.z : 0.0; }, le, 32, 64);
  EXPECT_NEAR(solved, le / (1.0 - rho), 1e-9 * le / (1.0 - rho));
}

// The path tracer against the solution, for a rough dielectric and a glossy metal (the latter
// exercises the visible-normal sampler). Tolerance: 4 standard errors of the traced mean (its
// own noise) plus 0.5% for the sphere's tessellation (192 x 96 facets with interpolated
// normals: the chord symmetry the solution assumes holds to about 0.1% there).
TEST(Furnace, PathTracerMatchesTheSolvedRadiance) {
  for (const PbrMaterial& m : {kRoughDielectric, kGlossyMetal}) {
    const double expected = solved_radiance(m);
    const auto [mean, standard_error] = image_mean(trace_furnace(m, 256));
    std::printf("metalness %.0f, roughness %.1f: traced %.5f +- %.5f, solved %.5f\n", m.metalness, m.roughness, mean,
                standard_error, expected);
    EXPECT_NEAR(mean, expected, 4.0 * standard_error + 0.005 * expected)
        << "metalness " << m.metalness << ": traced " << mean << " +- " << standard_error << ", solved " << expected;
    EXPECT_LT(standard_error, 0.01 * expected);  // the test resolves 1%
  }
}

// 16 times the paths divide each pixel's error by 4, and the standard error the tracer states
// is its actual error. Over 256 pixels a root mean square is known to about 1/sqrt(512) = 4.4%,
// so the bounds below are more than 4 of those standard deviations wide.
TEST(Furnace, NoiseFallsAsOneOverTheSquareRootOfThePaths) {
  const double expected = solved_radiance(kRoughDielectric);
  const auto [actual_16, stated_16] = pixel_errors(trace_furnace(kRoughDielectric, 16), expected);
  const auto [actual_256, stated_256] = pixel_errors(trace_furnace(kRoughDielectric, 256), expected);
  std::printf("pixel RMS error: %.5f at 16 paths (stated %.5f), %.5f at 256 (stated %.5f)\n", actual_16, stated_16,
              actual_256, stated_256);
  EXPECT_GT(actual_16 / actual_256, 4.0 / 1.25);
  EXPECT_LT(actual_16 / actual_256, 4.0 * 1.25);
  for (const auto& [actual, stated] : {std::pair{actual_16, stated_16}, std::pair{actual_256, stated_256}}) {
    EXPECT_GT(actual / stated, 0.8);
    EXPECT_LT(actual / stated, 1.25);
  }
}

}  // namespace
}  // namespace lg::test
