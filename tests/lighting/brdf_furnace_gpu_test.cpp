// The white furnace under distant light: a white surface (albedo 1, dielectric or metal,
// roughness 0 to 1) lit from every direction by radiance 1 reflects radiance 1 toward every view,
// grazing ones included. The constant environment is taken as the deferred pass would shade it:
// each direction a distant light through brdf.glsl's make_surface and brdf_cosine, integrated on
// lavapipe by tests/lighting/shaders/brdf_furnace.comp. Tolerance 1%, the criterion; what
// remains is the 32 x 32 albedo table's bilinear interpolation (the diffuse takes 1 minus the
// tabulated specular albedo, the specular integrates to the true one), float arithmetic and the
// 4096-point quadrature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/transfer.h"
#include "tests/runtime/gpu_test.h"

namespace lg {
std::span<const EmbeddedShader> lighting_test_shaders();
}

namespace lg::test {
namespace {

struct FurnaceCase {
  float n_dot_v, roughness, metalness, albedo;
};

// Views from grazing (n.v = 1e-4, the BRDF's floor) to normal, denser toward grazing where a
// sphere's silhouette pixels are; roughness 0 to 1 in steps of 0.1; dielectric and metal.
std::vector<FurnaceCase> furnace_cases() {
  std::vector<FurnaceCase> cases;
  for (float metalness : {0.0f, 1.0f})
    for (int r = 0; r <= 10; ++r)
      for (int k = 0; k <= 32; ++k) {
        const double t = k / 32.0;
        cases.push_back({float(1e-4 + (1 - 1e-4) * t * t), float(r / 10.0), metalness, 1.0f});
      }
  return cases;
}

class BrdfFurnaceGpuTest : public GpuTest {
 protected:
  // Per case, the specular and diffuse radiance reflected from a constant environment of 1.
  std::vector<float> run(const std::vector<FurnaceCase>& cases) {
    Buffer in = Buffer::dedicated(context(), {.name = "cases", .size = cases.size() * sizeof(FurnaceCase)});
    Buffer out = Buffer::dedicated(context(), {.name = "reflected", .size = cases.size() * 2 * sizeof(float)});
    const auto texels = brdf_albedo_texels();
    Buffer table = Buffer::dedicated(context(), {.name = "brdf_albedo", .size = sizeof(texels)});
    upload_buffer(submitter(), in, std::as_bytes(std::span(cases)));
    upload_buffer(submitter(), table, std::as_bytes(std::span(texels)));
    const Pipeline& p =
        pipelines().compute({"brdf_furnace",
                             find_shader(lighting_test_shaders(), "tests/lighting/shaders/brdf_furnace.comp"),
                             {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                              {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                              {2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}}});
    submitter().run([&](VkCommandBuffer cmd) {
      const DescriptorWrite writes[] = {storage_buffer(0, in.handle()), storage_buffer(1, out.handle()),
                                        uniform_buffer(2, table.handle())};
      bind_pipeline(context(), cmd, p, writes);
      vkCmdDispatch(cmd, uint32_t((cases.size() + 63) / 64), 1, 1);
      memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    });
    std::vector<std::byte> bytes = read_buffer(submitter(), out);
    std::vector<float> result(cases.size() * 2);
    std::memcpy(result.data(), bytes.data(), result.size() * sizeof(float));
    return result;
  }
};

TEST_F(BrdfFurnaceGpuTest, WhiteSurfacesReflectAConstantDistantLightWhole) {
  const std::vector<FurnaceCase> cases = furnace_cases();
  const std::vector<float> reflected = run(cases);
  std::printf("deferred BRDF, constant distant light of 1: reflected radiance per roughness\n");
  std::printf("%-10s %9s %9s %9s %9s\n", "", "mean", "min", "max", "at n.v 1e-4");
  double worst = 0.0;
  for (size_t first = 0; first < cases.size(); first += 33) {
    double sum = 0.0, low = 1e9, high = -1e9;
    for (size_t i = first; i < first + 33; ++i) {
      const double total = double(reflected[2 * i]) + reflected[2 * i + 1];
      ASSERT_TRUE(std::isfinite(total)) << "case " << i;
      sum += total, low = std::min(low, total), high = std::max(high, total);
      worst = std::max(worst, std::abs(total - 1.0));
    }
    const double grazing = double(reflected[2 * first]) + reflected[2 * first + 1];
    std::printf("%s r %.1f %9.4f %9.4f %9.4f %9.4f\n", cases[first].metalness > 0 ? "metal" : "diel.",
                cases[first].roughness, sum / 33, low, high, grazing);
  }
  std::printf("max |reflected - 1| = %.5f\n", worst);
  EXPECT_LE(worst, 0.01);
}

}  // namespace
}  // namespace lg::test
