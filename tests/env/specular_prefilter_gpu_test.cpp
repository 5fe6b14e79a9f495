// env.specular_prefilter's pass on lavapipe against the double-precision brute force over
// every texel of the same (half-precision) environment, at output texels drawn at random from
// fixed seeds. The exact method (the node's default) is held to issue 21's bound, 0.5% RMS at
// every mip, on the random environment, the probes and a synthetic sun. Filtered importance
// sampling (method 'sampled') is held to the earlier target, under 1% at roughness 0.25, 0.5 and
// 1 on the random environment at the default 256 samples (measured 0.31%, 0.47%, 0.27%; before
// prefilter.comp's corrections 0.44%, 0.67%, 0.97%); on the probes, whose small sources are
// thousands of times their sky, it is only bounded: grace 3.0%, 5.1%, 7.3% at 256 samples (2.7%,
// 3.1%, 3.8% at 1024); pisa 0.59%, 0.39%, 0.58% (0.18%, 0.13%, 0.20%). Invariants for both: a
// constant environment comes back at every roughness; non-finite texels give finite output. For
// sampling: roughness 0 is the environment itself; its own mip chain starts at the input and
// keeps its integral. Stress: a sun 1e5 times the sky, NaN and Inf texels.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>
#include <limits>
#include <random>

#include "nodes/env/specular_prefilter/exact_prefilter.h"
#include "nodes/env/specular_prefilter/prefilter_reference.h"
#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/sampler.h"
#include "tests/env/env_test_support.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr uint32_t kDefaultSamples = 256;  // the schema's default

class SpecularPrefilterGpuTest : public GpuTest {
 protected:
  // Every mip of the prefiltered map of `env` (its mips made on the CPU, area-correct), and
  // in `own_chain_levels` (when given) every level of the chain the pass builds for itself.
  // samples 0: the exact method (exact_prefilter.h); else filtered importance sampling.
  std::vector<CubeImage> prefilter(const CubeImage& env, uint32_t out_size, uint32_t mips, uint32_t samples,
                                   std::vector<CubeImage>* own_chain_levels = nullptr) {
    const std::vector<CubeImage> chain = mip_chain(env);
    Image source = make_cube(context(), "env", env.size, uint32_t(chain.size()));
    upload_cube(submitter(), source, chain, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    Image out = make_cube(context(), "specular", out_size, mips);
    Image own_chain = make_cube(context(), "chain", env.size, uint32_t(chain.size()));
    Sampler trilinear(context(), {.filter = Filter::linear});
    Buffer peaks = Buffer::dedicated(context(), {.name = "peaks", .size = prefilter_peaks_bytes()});
    submitter().run([&](VkCommandBuffer cmd) {
      image_barrier(cmd, out, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      image_barrier(cmd, own_chain, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      if (samples == 0)
        record_specular_prefilter_exact(context(), pipelines(), cmd, "specular/prefilter", source, own_chain,
                                        trilinear.handle(), peaks, out);
      else
        record_specular_prefilter(context(), pipelines(), cmd, "specular/prefilter", samples, source, &own_chain,
                                  trilinear.handle(), out, PrefilterSampling::filtered);
      memory_barrier(cmd);
    });
    if (own_chain_levels)
      for (uint32_t m = 0; m < chain.size(); ++m)
        own_chain_levels->push_back(read_cube(submitter(), own_chain, m, VK_IMAGE_LAYOUT_GENERAL));
    std::vector<CubeImage> result;
    for (uint32_t m = 0; m < mips; ++m) result.push_back(read_cube(submitter(), out, m, VK_IMAGE_LAYOUT_GENERAL));
    return result;
  }

  // RMS over `count` random texels of `mip` (and RGB) of (gpu - reference) / reference.
  static double relative_rms(const CubeImage& env, const CubeImage& mip, double roughness, int count, uint64_t seed) {
    std::mt19937_64 rng(seed);
    double sum = 0;
    for (int k = 0; k < count; ++k) {
      const int f = int(rng() % 6);
      const uint32_t i = uint32_t(rng() % mip.size), j = uint32_t(rng() % mip.size);
      const glm::dvec3 ref = prefiltered_reference(env, mip.direction(f, i, j), roughness);
      for (int c = 0; c < 3; ++c) {
        const double e = (mip.at(f, i, j)[c] - ref[c]) / ref[c];
        sum += e * e;
      }
    }
    return std::sqrt(sum / (3.0 * count));
  }

  // Roughness 0.25, 0.5 and 1 (mips 1, 2 and 4 of 5) against bounds[0..2].
  void check_roughness_levels(const CubeImage& env, const char* what, uint32_t samples, const double (&bounds)[3]) {
    const CubeImage seen = round_to_half(env);
    const uint32_t mips = 5;
    const std::vector<CubeImage> out = prefilter(seen, env.size, mips, samples);
    const uint32_t levels[3] = {1, 2, 4};
    for (int k = 0; k < 3; ++k) {
      const double roughness = prefilter_roughness(levels[k], mips);
      const double rms = relative_rms(seen, out[levels[k]], roughness, 150, 40 + k);
      std::cout << what << ", roughness " << roughness << ", " << samples << " samples: RMS relative error " << rms
                << "\n";
      EXPECT_LT(rms, bounds[k]) << what << " roughness " << roughness << ", " << samples << " samples";
    }
  }

  // The exact method: every mip of `mips` but roughness 0 (the environment itself) under `bound`.
  void check_exact_every_mip(const CubeImage& env, const char* what, uint32_t mips, double bound, int texels = 150) {
    const CubeImage seen = round_to_half(env);
    const std::vector<CubeImage> out = prefilter(seen, env.size, mips, 0);
    for (uint32_t m = 1; m < mips; ++m) {
      const double roughness = prefilter_roughness(m, mips);
      const double rms = relative_rms(seen, out[m], roughness, texels, 40 + m);
      std::cout << what << ", exact, roughness " << roughness << ": RMS relative error " << rms << "\n";
      EXPECT_LT(rms, bound) << what << " roughness " << roughness;
    }
  }
};

// The bound, 0.5% RMS at every mip of the node's default 6 (roughness 0.2 to 1), on a
// 64^2 random environment with a sun about 1e4 times its sky on one texel, off the centre of the
// coarse texel it is in (without the peak list a coarse sum would weight it at that centre).
// Measured 0.04% to 0.10% (the output's half precision alone is up to 0.05%); without the peak
// list 0.21% to 1.0%. 50 texels a mip keep it under 2 s (the brute force dominates).
TEST_F(SpecularPrefilterGpuTest, ExactWithinHalfPercentAtEveryMipWithASun) {
  CubeImage env = random_environment(64, 504);
  env.at(4, 21, 38) = glm::dvec4(3000.0, 2900.0, 2600.0, 1.0);
  check_exact_every_mip(env, "random 64^2 with a sun", 6, 0.005, 50);
}

TEST_F(SpecularPrefilterGpuTest, RandomEnvironmentWithinOnePercentAtTheDefaultSamples) {
  check_roughness_levels(random_environment(128, 500), "random", kDefaultSamples, {0.01, 0.01, 0.01});
}

// The bound for the exact method, 0.5% RMS at every mip of a 128^2 cube (5 mips: the
// benchmark's), on the random environment and the probes; measured 0.04% to 0.13%. Filtered
// importance sampling at 256 samples is only bounded (grace 3.0% to 7.3%).
TEST_F(SpecularPrefilterGpuTest, Probes) {
  check_exact_every_mip(random_environment(128, 500), "random", 5, 0.005);
  for (const char* name : {"grace.hdr", "pisa.hdr"}) {
    const std::optional<CubeImage> env = load_probe(name, 128);
    if (!env) GTEST_SKIP() << "../shared/data/env/" << name << " is missing";
    check_exact_every_mip(*env, name, 5, 0.005);
    check_roughness_levels(*env, name, kDefaultSamples, {0.5, 0.5, 0.5});
  }
}

// Half precision holds 1.5 and 0.25 exactly and trilinear reads of a constant are exact; the
// float sums then land a hair off and the rgba16f store (which lavapipe rounds toward zero)
// can drop one half-precision step: 1e-3 relative.
TEST_F(SpecularPrefilterGpuTest, ConstantEnvironmentAtEveryRoughness) {
  CubeImage env(32);
  for (glm::dvec4& t : env.texels) t = glm::dvec4(1.5, 0.25, 3.0, 1.0);
  for (uint32_t samples : {kDefaultSamples, 0u})  // 0: the exact method
    for (const CubeImage& mip : prefilter(env, 32, 6, samples))
      for (const glm::dvec4& t : mip.texels) {
        ASSERT_NEAR(t.x, 1.5, 1.5e-3) << samples << " samples";
        ASSERT_NEAR(t.y, 0.25, 0.25e-3) << samples << " samples";
        ASSERT_NEAR(t.z, 3.0, 3e-3) << samples << " samples";
      }
}

TEST_F(SpecularPrefilterGpuTest, RoughnessZeroIsTheEnvironment) {
  const CubeImage env = round_to_half(random_environment(32, 501));
  const std::vector<CubeImage> out = prefilter(env, 32, 3, kDefaultSamples);
  for (size_t t = 0; t < env.texels.size(); ++t)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(out[0].texels[t][c], env.texels[t][c], 1e-3 * env.texels[t][c]);
}

// The pass's own chain: level 0 is the input's mip 0 (its non-finite texels as 0, and only
// those), and each further level, a tent read bilinearly across the faces' edges and weighted by
// the solid angle where it reads, keeps the radiance's integral: measured within 7e-4 down to
// faces of 4x4, 4e-3 at 2x2 and 1x1 (the input's box chain is exact).
TEST_F(SpecularPrefilterGpuTest, OwnChainStartsAtTheInputAndKeepsItsIntegral) {
  CubeImage env = round_to_half(random_environment(64, 503));
  env.at(3, 10, 20) = glm::dvec4(std::numeric_limits<double>::quiet_NaN(), 1, 1, 1);
  std::vector<CubeImage> levels;
  prefilter(env, 16, 2, 16, &levels);
  ASSERT_EQ(levels.size(), 7u);
  env.at(3, 10, 20) = glm::dvec4(0, 0, 0, 1);
  for (size_t t = 0; t < env.texels.size(); ++t)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(levels[0].texels[t][c], env.texels[t][c]) << "texel " << t;
  const glm::dvec3 total = integrate(env);
  for (size_t m = 1; m < levels.size(); ++m) {
    const glm::dvec3 level = integrate(levels[m]);
    for (int c = 0; c < 3; ++c) {
      std::cout << "chain level " << m << ", channel " << c << ": integral / mip 0's - 1 = " << level[c] / total[c] - 1
                << "\n";
      EXPECT_NEAR(level[c] / total[c], 1.0, levels[m].size >= 4 ? 1e-3 : 5e-3) << "level " << m << " channel " << c;
    }
  }
}

TEST_F(SpecularPrefilterGpuTest, SunAndNonFiniteTexels) {
  CubeImage env = random_environment(64, 502);
  env.at(2, 40, 20) = glm::dvec4(30000.0, 30000.0, 28000.0, 1.0);  // about 1e5 x the sky
  const CubeImage seen = round_to_half(env);
  const std::vector<CubeImage> out = prefilter(seen, 64, 5, kDefaultSamples);
  for (uint32_t m : {1u, 2u, 4u}) {
    const double rms = relative_rms(seen, out[m], prefilter_roughness(m, 5), 100, 60 + m);
    std::cout << "sun 1e5 x sky, roughness " << prefilter_roughness(m, 5) << ": RMS relative error " << rms << "\n";
    for (const glm::dvec4& t : out[m].texels)
      ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
  }
  env.at(0, 3, 3) = glm::dvec4(std::numeric_limits<double>::quiet_NaN(), 1, 1, 1);
  env.at(4, 10, 50) = glm::dvec4(1, std::numeric_limits<double>::infinity(), 1, 1);
  for (uint32_t samples : {kDefaultSamples, 0u})  // 0: the exact method
    for (const CubeImage& mip : prefilter(round_to_half(env), 64, 5, samples))
      for (const glm::dvec4& t : mip.texels)
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << samples << " samples";
}

}  // namespace
}  // namespace lg::test
