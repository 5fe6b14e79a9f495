// The area-light diffuse formulas as the GPU runs them (the deferred node's GLSL, on
// lavapipe) against the double-precision reference quadrature, on fresh random configurations
// from fixed seeds. Issue 3's criterion: max relative error <= 1% for sphere, tube and
// rectangle lights fully above the horizon, 1.5 to 50 bounding radii away. Across the horizon
// the errors are printed (the issue asks for them in the log) and bounded relative to the scale.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <iostream>
#include <vector>

#include "nodes/lighting/deferred/area_light_formulas.h"
#include "nodes/lighting/deferred/area_light_reference.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/transfer.h"
#include "tests/lighting/area_light_cases.h"
#include "tests/runtime/gpu_test.h"

namespace lg {
std::span<const EmbeddedShader> lighting_test_shaders();  // generated
}

namespace lg::test {
namespace {

using glm::dvec3;

constexpr double kReferenceTol = 1e-8;
constexpr int kCases = 400;

struct GpuCase {
  float a[4], b[4], c[4], p[4], n[4];
};

struct Case {
  GpuCase gpu;
  double reference;
  double scale;  // the bounding sphere's head-on irradiance
};

void put(float* out, dvec3 v, double w) {
  out[0] = float(v.x), out[1] = float(v.y), out[2] = float(v.z), out[3] = float(w);
}

// Positions are rounded to float before the reference sees them (area_light_accuracy_test.cpp
// explains why); the radiance is 1, so E is the projected solid angle.
Shading round_shading(Shading s) {
  s.p = dvec3(to_float(s.p));
  s.n = dvec3(to_float(s.n));
  return s;
}

std::vector<Case> make_cases(int kind, Horizon horizon, uint64_t seed) {
  CaseGenerator g(seed);
  std::vector<Case> cases;
  for (int i = 0; i < kCases; ++i) {
    Case c{};
    if (kind == 0) {
      SphereLightD l = rounded(g.sphere());
      l.radiance = 1;
      Shading s = round_shading(g.shading(l.center, l.radius, 1, horizon));
      put(c.gpu.a, l.center, l.radius), put(c.gpu.p, s.p, 0), put(c.gpu.n, s.n, 0);
      c.reference = reference_sphere_irradiance(l, s.p, s.n, kReferenceTol).value;
      c.scale = s.bound_irradiance;
    } else if (kind == 1) {
      TubeLightD l = rounded(g.tube());
      l.radiance = 1;
      Shading s = round_shading(g.shading(light_center(l), bounding_radius(l), 1, horizon));
      put(c.gpu.a, l.end0, l.radius), put(c.gpu.b, l.end1, 0), put(c.gpu.p, s.p, 0), put(c.gpu.n, s.n, 1);
      c.reference = reference_tube_irradiance(l, s.p, s.n, kReferenceTol).value;
      c.scale = s.bound_irradiance;
    } else {
      RectLightD l = rounded(g.rect());
      l.radiance = 1;
      dvec3 front = l.two_sided ? dvec3(0.0) : glm::cross(l.half_x, l.half_y);
      Shading s = round_shading(g.shading(l.center, bounding_radius(l), 1, horizon, front));
      put(c.gpu.a, l.center, l.two_sided ? 1 : 0), put(c.gpu.b, l.half_x, 0), put(c.gpu.c, l.half_y, 0);
      put(c.gpu.p, s.p, 0), put(c.gpu.n, s.n, 2);
      c.reference = reference_rect_irradiance(l, s.p, s.n, kReferenceTol).value;
      c.scale = s.bound_irradiance;
    }
    cases.push_back(c);
  }
  return cases;
}

class AreaLightGpuTest : public GpuTest {
 protected:
  std::vector<float> run(const std::vector<Case>& cases) {
    std::vector<GpuCase> input;
    for (const Case& c : cases) input.push_back(c.gpu);
    Buffer in = Buffer::dedicated(context(), {.name = "cases", .size = input.size() * sizeof(GpuCase)});
    Buffer out = Buffer::dedicated(context(), {.name = "irradiance", .size = input.size() * sizeof(float)});
    upload_buffer(submitter(), in, std::as_bytes(std::span(input)));
    const Pipeline& p =
        pipelines().compute({"area_irradiance",
                             find_shader(lighting_test_shaders(), "tests/lighting/shaders/area_irradiance.comp"),
                             {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}});
    submitter().run([&](VkCommandBuffer cmd) {
      const DescriptorWrite writes[] = {storage_buffer(0, in.handle()), storage_buffer(1, out.handle())};
      bind_pipeline(context(), cmd, p, writes);
      vkCmdDispatch(cmd, uint32_t((input.size() + 63) / 64), 1, 1);
      memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    });
    std::vector<std::byte> bytes = read_buffer(submitter(), out);
    std::vector<float> result(cases.size());
    std::memcpy(result.data(), bytes.data(), result.size() * sizeof(float));
    return result;
  }

  // Max relative error over lit cases (reference above 1e-3 of the scale) and max error
  // relative to the scale over all; every result must be finite.
  void check(int kind, Horizon horizon, uint64_t seed, double max_relative, double max_scaled) {
    const char* names[] = {"sphere", "tube", "rectangle"};
    std::vector<Case> cases = make_cases(kind, horizon, seed);
    std::vector<float> gpu = run(cases);
    double worst_relative = 0, worst_scaled = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
      ASSERT_TRUE(std::isfinite(gpu[i])) << names[kind] << " case " << i;
      const double err = std::abs(double(gpu[i]) - cases[i].reference);
      worst_scaled = std::max(worst_scaled, err / cases[i].scale);
      if (cases[i].reference > 1e-3 * cases[i].scale)
        worst_relative = std::max(worst_relative, err / cases[i].reference);
    }
    std::cout << names[kind] << (horizon == Horizon::kAbove ? " above" : " across")
              << " the horizon, GPU formulas: max relative error " << worst_relative << ", max error / scale "
              << worst_scaled << " over " << cases.size() << " cases\n";
    RecordProperty("max_relative_error", std::to_string(worst_relative));
    EXPECT_LE(worst_relative, max_relative) << names[kind];
    EXPECT_LE(worst_scaled, max_scaled) << names[kind];
  }
};

// Above the horizon: 1% relative, the bound (measured on lavapipe: sphere 4.6e-7,
// tube 2.5e-5, rectangle 1.1e-3), and 1e-4 of the scale.
TEST_F(AreaLightGpuTest, SphereAboveHorizonWithinOnePercent) {
  check(0, Horizon::kAbove, 301, 0.01, 1e-4);
}
TEST_F(AreaLightGpuTest, TubeAboveHorizonWithinOnePercent) {
  check(1, Horizon::kAbove, 302, 0.01, 1e-4);
}
TEST_F(AreaLightGpuTest, RectangleAboveHorizonWithinOnePercent) {
  check(2, Horizon::kAbove, 303, 0.01, 1e-4);
}

// Across the horizon the GPU's acos and atan (lavapipe evaluates them by polynomials, less
// exactly than the CPU's libm) lose about 1e-4 of the scale where the formulas' terms cancel;
// on cases lit under 2% of the scale that is a relative error of a few percent (measured
// worst: sphere 28% at 0.1% lit, tube 3.8%, rectangle 4.1%; the CPU formulas stay under 0.14%).
// Bound: 1e-3 of the scale (measured 3.1e-4, 7.8e-5, 8.0e-5); relative error only logged.
TEST_F(AreaLightGpuTest, SphereAcrossHorizonWithinAThousandthOfTheScale) {
  check(0, Horizon::kCrossing, 304, 1.0, 1e-3);
}
TEST_F(AreaLightGpuTest, TubeAcrossHorizonWithinAThousandthOfTheScale) {
  check(1, Horizon::kCrossing, 305, 1.0, 1e-3);
}
TEST_F(AreaLightGpuTest, RectangleAcrossHorizonWithinAThousandthOfTheScale) {
  check(2, Horizon::kCrossing, 306, 1.0, 1e-3);
}

}  // namespace
}  // namespace lg::test
