// env.sh_project's pass on lavapipe (its shader, recorded by the kernel's own function) against
// the double-precision brute-force projection of the same half-precision texels. Tolerance:
// 1e-4 of the reference's coefficient norm per channel (the target), or 1e-6 relative
// where the issue asks (constant environment); float sums with Kahan compensation measure
// about 5e-8 here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include "nodes/env/common/sh_basis.h"
#include "nodes/env/sh_project/sh_project_kernel.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/transfer.h"
#include "tests/env/env_test_support.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr double pi = std::numbers::pi;

struct GpuSh {
  std::vector<glm::dvec3> coefficients;
  double non_finite = 0;
};

class ShProjectGpuTest : public GpuTest {
 protected:
  GpuSh project(const CubeImage& env, const ShProjectSettings& settings) {
    Image cube = make_cube(context(), "env", env.size, 1);
    upload_cube(submitter(), cube, {env}, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    const int count = sh_count(settings.order);
    Buffer out = Buffer::dedicated(context(), {.name = "sh", .size = uint64_t(count) * 16});
    Buffer partials = Buffer::dedicated(context(), {.name = "partials", .size = sh_partials_bytes(cube)});
    Sampler sampler(context(), {.filter = Filter::nearest});
    submitter().run([&](VkCommandBuffer cmd) {
      record_sh_project(context(), pipelines(), cmd, "sh/project", settings, cube, sampler.handle(), partials, out);
      memory_barrier(cmd);
    });
    const std::vector<std::byte> bytes = read_buffer(submitter(), out);
    std::vector<float> values(count * 4);
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
    GpuSh sh;
    for (int k = 0; k < count; ++k) sh.coefficients.emplace_back(values[4 * k], values[4 * k + 1], values[4 * k + 2]);
    sh.non_finite = values[3];
    return sh;
  }

  // Max over channels of |gpu - reference| / (the reference's coefficient norm in that channel).
  static double error_of_norm(const std::vector<glm::dvec3>& gpu, const std::vector<glm::dvec3>& reference) {
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
      double norm = 0, err = 0;
      for (size_t k = 0; k < reference.size(); ++k) {
        norm += reference[k][c] * reference[k][c];
        err = std::max(err, std::abs(gpu[k][c] - reference[k][c]));
      }
      worst = std::max(worst, err / std::sqrt(norm));
    }
    return worst;
  }

  double check_against_reference(const CubeImage& env, int order, ShWindow window, bool convolve, const char* what) {
    const ShProjectSettings settings = sh_project_settings(order, window, 0.05, convolve);
    const CubeImage seen = round_to_half(env);
    const ShReference reference = project_sh_reference(seen, order, settings.band_factors);
    const GpuSh gpu = project(seen, settings);
    const double err = error_of_norm(gpu.coefficients, reference.coefficients);
    std::cout << what << ", order " << order << ": max error / coefficient norm " << err << "\n";
    EXPECT_LE(err, 1e-4) << what << " order " << order;
    EXPECT_EQ(gpu.non_finite, reference.non_finite);
    return err;
  }
};

TEST_F(ShProjectGpuTest, MatchesBruteForceOnRandomEnvironments) {
  for (int order = 1; order <= 4; ++order)
    check_against_reference(random_environment(order == 4 ? 128 : 40, 100 + order), order, ShWindow::none, false,
                            "random");
}

TEST_F(ShProjectGpuTest, MatchesBruteForceWithWindowsAndCosineConvolution) {
  const CubeImage env = random_environment(32, 200);
  check_against_reference(env, 2, ShWindow::none, true, "irradiance");
  check_against_reference(env, 3, ShWindow::hanning, false, "hanning");
  check_against_reference(env, 4, ShWindow::lanczos, true, "lanczos, irradiance");
  check_against_reference(env, 4, ShWindow::min_ringing, true, "min ringing, irradiance");
}

TEST_F(ShProjectGpuTest, MatchesBruteForceOnTheProbes) {
  for (const char* name : {"grace.hdr", "pisa.hdr"}) {
    const std::optional<CubeImage> env = load_probe(name, 128);
    if (!env) GTEST_SKIP() << "../shared/data/env/" << name << " is missing";
    check_against_reference(*env, 4, ShWindow::none, false, name);
  }
}

// 256^2 faces: 1536 tiles to add up.
TEST_F(ShProjectGpuTest, ConstantEnvironmentHasOnlyTheConstantTerm) {
  CubeImage env(256);
  const glm::dvec3 radiance(1.5, 0.25, 3.0);  // exact in half precision
  for (glm::dvec4& t : env.texels) t = glm::dvec4(radiance, 1.0);
  const GpuSh gpu = project(env, sh_project_settings(4, ShWindow::none, 0, false));
  const glm::dvec3 l00 = 2 * std::sqrt(pi) * radiance;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu.coefficients[0][c], l00[c], 1e-6 * l00[c]);
  for (size_t k = 1; k < gpu.coefficients.size(); ++k)
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(gpu.coefficients[k][c]), 1e-6 * l00[c]) << k;
  // Irradiance coefficients give E = pi L in every direction.
  const GpuSh irradiance = project(env, sh_project_settings(2, ShWindow::none, 0, true));
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 100; ++k) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const glm::dvec3 e = evaluate_sh(irradiance.coefficients, n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], pi * radiance[c], 1e-6 * pi * radiance[c]);
  }
}

// Against the reference's integral of Y_lm over the texel: 1e-6 of the peak. That integral
// differs from Y_lm(centre) times the solid angle by the basis' curvature over the texel:
// bound 2e-3 of the peak on 64^2 faces (measured 1.0e-3).
TEST_F(ShProjectGpuTest, SingleBrightTexelGivesTheBasisAtItsDirection) {
  CubeImage env(64);
  const int face = 4;
  const uint32_t i = 45, j = 12;
  env.at(face, i, j) = glm::dvec4(1000.0, 500.0, 250.0, 1.0);
  const GpuSh gpu = project(env, sh_project_settings(4, ShWindow::none, 0, false));
  std::vector<double> y(25);
  sh_evaluate(4, env.direction(face, i, j), y);
  const double omega = texel_solid_angle(64, i, j);
  const double peak = 1000.0 * omega * y[0];
  const std::vector<double> ones(5, 1.0);
  const ShReference reference = project_sh_reference(env, 4, ones);
  for (int k = 0; k < 25; ++k)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(gpu.coefficients[k][c], reference.coefficients[k][c], 1e-6 * peak) << k;
      EXPECT_NEAR(gpu.coefficients[k][c], y[k] * env.at(face, i, j)[c] * omega, 2e-3 * peak) << k;
    }
}

// A quarter turn about +Y maps texel centres onto texel centres, so the rotated environment is
// exact; its SH must reconstruct the original's, rotated: f'(R d) = f(d).
TEST_F(ShProjectGpuTest, RotatingTheEnvironmentRotatesTheCoefficients) {
  const CubeImage env = round_to_half(random_environment(32, 300));
  const glm::dmat3 rotation(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));  // columns
  const auto settings = sh_project_settings(4, ShWindow::none, 0, false);
  const GpuSh original = project(env, settings);
  const GpuSh rotated = project(rotate_quarter_turn(env, rotation), settings);
  double scale = 0;
  for (const glm::dvec3& c : original.coefficients) scale = std::max(scale, glm::length(c));
  std::mt19937_64 rng(8);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 200; ++k) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const glm::dvec3 diff = evaluate_sh(rotated.coefficients, rotation * d) - evaluate_sh(original.coefficients, d);
    EXPECT_LT(glm::length(diff), 1e-5 * scale);
  }
  // Band energies are rotation invariant.
  for (int l = 0; l <= 4; ++l) {
    double a = 0, b = 0;
    for (int k = l * l; k < (l + 1) * (l + 1); ++k)
      a += glm::dot(original.coefficients[k], original.coefficients[k]),
          b += glm::dot(rotated.coefficients[k], rotated.coefficients[k]);
    EXPECT_NEAR(std::sqrt(b), std::sqrt(a), 1e-5 * scale) << l;
  }
}

// Stress: a sun 1e5 times the sky in one texel, and NaN and Inf texels (policy: counted as 0,
// the count in coefficient 0's w).
TEST_F(ShProjectGpuTest, SunAndNonFiniteTexels) {
  CubeImage env(32);
  for (glm::dvec4& t : env.texels) t = glm::dvec4(0.25, 0.3, 0.4, 1.0);
  env.at(2, 20, 9) = glm::dvec4(25000.0, 25000.0, 24000.0, 1.0);
  check_against_reference(env, 4, ShWindow::none, true, "sun 1e5 x sky");
  env.at(0, 1, 2) = glm::dvec4(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0, 1.0);
  env.at(3, 5, 5) = glm::dvec4(1.0, std::numeric_limits<double>::infinity(), 1.0, 1.0);
  env.at(5, 31, 31) = glm::dvec4(-std::numeric_limits<double>::infinity(), 1.0, 1.0, 1.0);
  check_against_reference(env, 4, ShWindow::none, true, "NaN and Inf texels");
  const GpuSh gpu = project(env, sh_project_settings(2, ShWindow::none, 0, false));
  EXPECT_EQ(gpu.non_finite, 3.0);
  for (const glm::dvec3& c : gpu.coefficients)
    EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
}

}  // namespace
}  // namespace lg::test
