// The LTC area-light specular as the GPU runs it (area_light_ltc.glsl and ltc_table.glsl on
// lavapipe, the table from ltc_table_texels()) against its C++ twin on random configurations:
// lights above and across the horizon, views down to n.v 0.02, roughness 0 to 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <vector>

#include "nodes/lighting/deferred/area_light_ltc.h"
#include "nodes/lighting/deferred/ltc_table.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/transfer.h"
#include "tests/lighting/area_specular_cases.h"
#include "tests/runtime/gpu_test.h"

namespace lg {
std::span<const EmbeddedShader> lighting_test_shaders();  // generated
}

namespace lg::test {
namespace {

using glm::dvec3;

struct GpuCase {
  float a[4], b[4], c[4], p[4], n[4], v[4];
};

void put(float* out, dvec3 v, double w) {
  out[0] = float(v.x), out[1] = float(v.y), out[2] = float(v.z), out[3] = float(w);
}

class AreaLightLtcGpuTest : public GpuTest {
 protected:
  std::vector<float> run(const std::vector<GpuCase>& input) {
    const auto table = ltc_table_texels();
    Buffer in = Buffer::dedicated(context(), {.name = "cases", .size = input.size() * sizeof(GpuCase)});
    Buffer out = Buffer::dedicated(context(), {.name = "integral", .size = input.size() * sizeof(float)});
    Buffer ltc = Buffer::dedicated(context(), {.name = "ltc", .size = sizeof(table)});
    upload_buffer(submitter(), in, std::as_bytes(std::span(input)));
    upload_buffer(submitter(), ltc, std::as_bytes(std::span(table)));
    const Pipeline& p =
        pipelines().compute({"area_ltc",
                             find_shader(lighting_test_shaders(), "tests/lighting/shaders/area_ltc.comp"),
                             {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                              {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                              {2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}}});
    submitter().run([&](VkCommandBuffer cmd) {
      const DescriptorWrite writes[] = {storage_buffer(0, in.handle()), storage_buffer(1, out.handle()),
                                        uniform_buffer(2, ltc.handle())};
      bind_pipeline(context(), cmd, p, writes);
      vkCmdDispatch(cmd, uint32_t((input.size() + 63) / 64), 1, 1);
      memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    });
    std::vector<std::byte> bytes = read_buffer(submitter(), out);
    std::vector<float> result(input.size());
    std::memcpy(result.data(), bytes.data(), result.size() * sizeof(float));
    return result;
  }
};

// I is a fraction of the lobe in [0, 1]. The two differ by float rounding and lavapipe's atan
// and sqrt (polynomials); 1e-4 absolute plus 1e-3 relative leaves that room and catches any
// difference of method (a wrong matrix layout, a lost edge or clip moves I by percents).
TEST_F(AreaLightLtcGpuTest, ShaderMatchesTheCppTwin) {
  CaseGenerator g(401);
  std::vector<GpuCase> input;
  std::vector<float> expected;
  for (int k = 0; k < 300; ++k) {
    const LightShape shape = LightShape(k % 3);
    SpecularRange range{k % 2 == 0 ? Horizon::kAbove : Horizon::kCrossing};
    range.min_roughness = 0.0;
    const SpecularCase c = make_specular_case(g, shape, range);
    GpuCase gpu{};
    const glm::vec3 p = to_float(c.p), n = to_float(c.n), v = to_float(c.v);
    const LtcLobe lobe = ltc_lobe(std::max(glm::dot(n, v), 1e-4f), float(c.roughness));
    put(gpu.p, c.p, c.roughness), put(gpu.n, c.n, double(k % 3)), put(gpu.v, c.v, lobe.albedo);
    float cpu = 0.0f;
    if (shape == LightShape::kSphere) {
      put(gpu.a, c.sphere.center, c.sphere.radius);
      cpu = ltc_sphere_specular({to_float(c.sphere.center), float(c.sphere.radius), 1.0f}, p, n, v, lobe);
    } else if (shape == LightShape::kTube) {
      put(gpu.a, c.tube.end0, c.tube.radius), put(gpu.b, c.tube.end1, 0.0);
      cpu =
          ltc_tube_specular({to_float(c.tube.end0), to_float(c.tube.end1), float(c.tube.radius), 1.0f}, p, n, v, lobe);
    } else {
      put(gpu.a, c.rect.center, c.rect.two_sided ? 1.0 : 0.0), put(gpu.b, c.rect.half_x, 0.0);
      put(gpu.c, c.rect.half_y, 0.0);
      cpu = ltc_rect_specular(to_float(RectLightD{c.rect.center, c.rect.half_x, c.rect.half_y, 1.0, c.rect.two_sided}),
                              p, n, v, lobe);
    }
    gpu.c[3] = lobe.alpha;  // the twins' lobe exactly
    input.push_back(gpu);
    expected.push_back(cpu);
  }
  const std::vector<float> gpu = run(input);
  double worst = 0.0;
  for (size_t k = 0; k < gpu.size(); ++k) {
    ASSERT_TRUE(std::isfinite(gpu[k])) << "case " << k;
    const double err = std::fabs(double(gpu[k]) - expected[k]);
    worst = std::max(worst, err / (1e-4 + 1e-3 * expected[k]));
    EXPECT_LE(err, 1e-4 + 1e-3 * expected[k]) << "case " << k << " (" << shape_name(LightShape(k % 3)) << ")";
  }
  std::cout << "LTC on the GPU against the C++ twin: worst error " << worst << " of the bound over " << gpu.size()
            << " cases\n";
}

}  // namespace
}  // namespace lg::test
