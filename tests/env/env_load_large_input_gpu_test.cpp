// env.load on an 8192x4096 EXR written at test time (random radiance, never zero, with bright,
// NaN and Inf texels): the bound of at most two float copies of the image in host
// memory, checked on the whole process (peak resident size, which on lavapipe includes the
// device image) and on the C++ heap; the NaN and Inf texels replaced and counted; every mip
// finite; and the coarsest mip holding the image's mean radiance over the sphere.
// Its own test binary: the heap tracker replaces operator new, and the other GPU tests' memory
// would blur the resident size.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "nodes/env/load/env_load_kernel.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/sampler.h"
#include "runtime/image/image_file.h"
#include "tests/bench/heap_tracker.h"
#include "tests/env/env_test_support.h"
#include "tests/runtime/gpu_test.h"
#include "tests/support/resident_memory.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kWidth = 8192, kHeight = 4096;
constexpr int64_t kFloatCopy = int64_t{kWidth} * kHeight * 4 * sizeof(float);  // 512 MiB
// Beyond the two copies: lavapipe's JIT of the two pipelines, the validation layer's tracking,
// OpenEXR's buffers (a block of rows) and the 256^2 output cube (4 MiB).
constexpr int64_t kSlack = int64_t{64} << 20;
constexpr uint32_t kFace = 256;
constexpr float kBright = 1e4f;  // well inside half range, which the EXR stores

uint64_t splitmix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

struct WrittenImage {
  uint64_t non_finite = 0;
  double mean[3] = {0, 0, 0};  // solid-angle-weighted mean radiance over the sphere
};

// Random radiance in [0.05, 2) per channel, 16 texels at kBright and 32 with a NaN or an
// infinity in one channel, saved as uncompressed half-float EXR at `path`.
WrittenImage write_test_image(const std::string& path, uint64_t seed) {
  std::vector<float> rgba(uint64_t(kWidth) * kHeight * 4);
  for (uint64_t t = 0; t < uint64_t(kWidth) * kHeight; ++t) {
    const uint64_t bits = splitmix(seed ^ t);
    for (int c = 0; c < 3; ++c) rgba[t * 4 + c] = 0.05f + 1.95f * float((bits >> (16 * c)) & 0xffff) / 65536.0f;
    rgba[t * 4 + 3] = 1.0f;
  }
  // Special texels at distinct random places, away from the poles' rows.
  std::set<uint64_t> taken;
  uint64_t draw = seed;
  const auto place = [&] {
    for (;;) {
      const uint64_t y = kHeight / 8 + splitmix(++draw) % (kHeight * 3 / 4), x = splitmix(++draw) % kWidth;
      if (taken.insert(y * kWidth + x).second) return y * kWidth + x;
    }
  };
  WrittenImage written;
  for (int k = 0; k < 16; ++k) {
    const uint64_t t = place();
    for (int c = 0; c < 3; ++c) rgba[t * 4 + c] = kBright;
  }
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()};
  for (int k = 0; k < 32; ++k) rgba[place() * 4 + k % 3] = specials[k % 4];
  written.non_finite = 32;

  for (uint32_t y = 0; y < kHeight; ++y) {
    // Exact solid angle of a texel of row y: rows span equal polar angles, top row at +Y.
    const double solid_angle =
        2 * std::numbers::pi / kWidth *
        (std::cos(std::numbers::pi * y / kHeight) - std::cos(std::numbers::pi * (y + 1) / kHeight));
    for (uint32_t x = 0; x < kWidth; ++x) {
      const float* texel = &rgba[(uint64_t(y) * kWidth + x) * 4];
      if (!(std::isfinite(texel[0]) && std::isfinite(texel[1]) && std::isfinite(texel[2]))) continue;  // becomes 0
      for (int c = 0; c < 3; ++c) written.mean[c] += texel[c] * solid_angle / (4 * std::numbers::pi);
    }
  }
  save_image(path, kWidth, kHeight, rgba, {.compress = false});
  return written;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class EnvLoadLargeInputTest : public GpuTest {};

TEST_F(EnvLoadLargeInputTest, HoldsAtMostTwoFloatCopiesOfAn8192x4096Input) {
  const fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "env-test-files";
  fs::create_directories(dir);
  const std::string path = (dir / "large-8192x4096.exr").string();
  const uint64_t seed = 4096;
  auto start = std::chrono::steady_clock::now();
  const WrittenImage written = write_test_image(path, seed);
  std::cout << "wrote " << path << " (seed " << seed << ") in " << seconds_since(start) << " s\n";

  Image cube = make_cube(context(), "env", kFace, 9);
  Sampler nearest(context(), {.filter = Filter::nearest});
  start = std::chrono::steady_clock::now();
  reset_peak_resident();
  const int64_t resident_before = resident_bytes();
  uint64_t non_finite = 0;
  bench::HeapUsage heap;
  {
    bench::HeapScope scope;
    ImageReader file(path);
    EquirectSource source = read_equirect(context(), file, 1.0, non_finite);
    submitter().run([&](VkCommandBuffer cmd) {
      image_barrier(cmd, cube, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      record_env_load(context(), pipelines(), cmd, "env/resample", source, nearest.handle(), cube);
      memory_barrier(cmd);
    });
    heap = scope.usage();
  }
  const int64_t resident_peak = peak_resident_bytes() - resident_before;
  std::cout << "env.load of 8192x4096 in " << seconds_since(start) << " s: peak resident growth "
            << double(resident_peak) / kFloatCopy << " float copies (" << (resident_peak >> 20)
            << " MiB), C++ heap peak " << (heap.peak_bytes >> 20) << " MiB; one copy is " << (kFloatCopy >> 20)
            << " MiB\n";
  EXPECT_LE(resident_peak, 2 * kFloatCopy + kSlack);
  // The image never passes through operator new (the staging buffer is driver memory).
  EXPECT_LE(heap.peak_bytes, kSlack);
  EXPECT_EQ(non_finite, written.non_finite);

  for (uint32_t m = 0; m < 9; ++m)
    for (const glm::dvec4& t : read_cube(submitter(), cube, m, VK_IMAGE_LAYOUT_GENERAL).texels)
      ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << "mip " << m;
  // The six 1x1 faces of the last mip each hold their face's solid-angle mean, and the faces
  // subtend equal solid angles. Bound 1%: 8x8 nearest samples per cube texel hit each bright
  // texel 0 to 2 times, and each carries 0.05% of the mean; the noise averages out to 1e-4;
  // rgba16f rounds by 5e-4 at most.
  const CubeImage last = read_cube(submitter(), cube, 8, VK_IMAGE_LAYOUT_GENERAL);
  for (int c = 0; c < 3; ++c) {
    double mean = 0;
    for (int f = 0; f < 6; ++f) mean += last.at(f, 0, 0)[c] / 6;
    EXPECT_NEAR(mean / written.mean[c], 1.0, 0.01) << "channel " << c;
  }
  fs::remove(path);
}

}  // namespace
}  // namespace lg::test
