// A spot light aimed straight down at a floor, seen by a camera straight above it on the same
// axis: every pixel of the deferred output against the spot formula of
// nodes/lighting/deferred/README.md in double precision, the lit disk's radius against
// h tan(outer angle), and the centre against the plain point-light formula.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/trigonometric.hpp>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/render/deferred_graph.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{128, 128};
constexpr double kPi = 3.14159265358979323846;
constexpr double kCameraHeight = 4.0, kLightHeight = 2.0, kIntensity = 10.0;
constexpr double kInnerDegrees = 20.0, kOuterDegrees = 30.0;
const double kVerticalFov = Camera{}.vertical_fov;
constexpr double kRelative = 1.2e-3;  // justified in EveryPixelFollowsTheConeFalloff

// A white floor of roughness 1 (its specular barely depends on the view) at y = 0; the camera
// and the spot light above its origin, both looking straight down.
World floor_under_spot() {
  World world;
  PbrMaterial rough;
  rough.roughness = 1.0f;
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(20.0f, 20.0f)), world.add_material(rough)});
  world.add(floor, Transform{});
  const glm::quat down = look_rotation({0.0f, -1.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  world.add(camera, Transform{.position = {0.0f, float(kCameraHeight), 0.0f}, .rotation = down});
  Entity spot = world.create("spot");
  world.add(spot, SpotLight{.intensity = float(kIntensity),
                            .inner_cone_angle = float(glm::radians(kInnerDegrees)),
                            .outer_cone_angle = float(glm::radians(kOuterDegrees))});
  world.add(spot, Transform{.position = {0.0f, float(kLightHeight), 0.0f}, .rotation = down});
  return world;
}

// Distance from the axis of the floor point seen at the centre of pixel (x, y): the camera
// looks straight down, so its ray through normalised device coordinates (u, v) meets the floor
// at tan(fov / 2) (u aspect, v) times its height.
double radius_at(uint32_t x, uint32_t y) {
  const double u = (x + 0.5) / kFrame.width * 2.0 - 1.0, v = (y + 0.5) / kFrame.height * 2.0 - 1.0;
  const double aspect = double(kFrame.width) / kFrame.height;
  return kCameraHeight * std::tan(kVerticalFov / 2.0) * std::hypot(u * aspect, v);
}

// nodes/common/shaders/brdf.glsl in double for the floor (albedo 1, roughness 1, metalness 0,
// normal +Y) at distance r from the axis: Lambert plus GGX, height-correlated Smith and Schlick,
// times n.l, each direction reduced to its height over its length; the specular with its
// multiple-scattering scale and the diffuse weighted by what it leaves (brdf_albedo.h).
double brdf_cosine(double r) {
  const double alpha = 1.0, f0 = 0.04;
  const double lx = -r, ly = kLightHeight, ll = std::hypot(lx, ly);
  const double vx = -r, vy = kCameraHeight, vl = std::hypot(vx, vy);
  const double n_dot_l = ly / ll, n_dot_v = vy / vl;
  const double hx = lx / ll + vx / vl, hy = n_dot_l + n_dot_v, hl = std::hypot(hx, hy);
  const double n_dot_h = hy / hl, v_dot_h = (vx / vl * hx + n_dot_v * hy) / hl;
  const double a2 = alpha * alpha, dd = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  const double distribution = a2 / (kPi * dd * dd);
  const double visibility = 0.5 / (n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2) +
                                   n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2));
  const double fresnel = f0 + (1.0 - f0) * std::pow(1.0 - v_dot_h, 5.0);
  const glm::dvec2 scale_bias = brdf_albedo_lookup(n_dot_v, 1.0);
  const double diffuse = 1.0 - specular_albedo(glm::dvec3(f0), scale_bias).x;
  const double scale = specular_energy_scale(glm::dvec3(f0), scale_bias).x;
  return (diffuse / kPi + distribution * visibility * fresnel * scale) * n_dot_l;
}

// The point light's radiance at r: intensity over distance squared (no range).
double point_light(double r) {
  return brdf_cosine(r) * kIntensity / (r * r + kLightHeight * kLightHeight);
}

// glTF's cone falloff: the square of the ramp from cos(outer) to cos(inner).
double cone(double r) {
  const double cos_angle = kLightHeight / std::hypot(r, kLightHeight);
  const double cos_inner = std::cos(glm::radians(kInnerDegrees)), cos_outer = std::cos(glm::radians(kOuterDegrees));
  const double t = std::clamp((cos_angle - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0);
  return t * t;
}

class SpotLightRender : public testing::Test {
 protected:
  void SetUp() override {
    RendererOptions options;
    options.device.validation = true;
    options.alias = false;  // the lighting is read back after the frame
    renderer_ = std::make_unique<Renderer>(options);
    renderer_->set_graph(deferred_lighting_graph());
    renderer_->render(floor_under_spot(), kFrame);
    auto messages = renderer_->context().take_validation_messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
    color_ = renderer_->executor().read_image("light.color");
    ASSERT_EQ(color_.size(), size_t{kFrame.width} * kFrame.height * 4);
  }
  float red(uint32_t x, uint32_t y) const { return color_[(size_t{y} * kFrame.width + x) * 4]; }

  std::unique_ptr<Renderer> renderer_;
  std::vector<float> color_;
};

TEST_F(SpotLightRender, EveryPixelFollowsTheConeFalloff) {
  // Half-float output bounds the error. The output is RGBA16F, and lavapipe converts to it by
  // truncation (the centre reads 0.803223 = 1645 * 2^-11 where the formula gives 0.803605):
  // a value can lose one spacing of the 10-bit mantissa, up to 2^-10 (9.8e-4) of itself. The
  // floor's normal (0, 1, 0) is stored exactly (nodes/common/shaders/gbuffer.glsl puts 0 on a
  // step of its 10-bit channel); kRelative = 1.2e-3. The absolute term, 1e-6 of the peak, covers
  // half-float subnormals and float cancellation in the ramp at the cone's edge.
  const double peak = point_light(0.0), absolute = 1e-6 * peak;
  double worst = 0.0;  // the largest error as a fraction of its tolerance
  for (uint32_t y = 0; y < kFrame.height; ++y)
    for (uint32_t x = 0; x < kFrame.width; ++x) {
      const double r = radius_at(x, y), want = point_light(r) * cone(r);
      const double error = std::abs(red(x, y) - want);
      worst = std::max(worst, error / (kRelative * want + absolute));
      ASSERT_LE(error, kRelative * want + absolute) << "pixel " << x << ", " << y << " at r = " << r << " m";
    }
  std::printf("largest error: %.3f of its tolerance\n", worst);
}

TEST_F(SpotLightRender, TheLitDiskEndsAtTheOuterAngle) {
  // Pixel centres lie one footprint apart on the floor, so the farthest lit one is within a
  // footprint inside the edge; nothing beyond the edge may be lit at all.
  const double footprint = 2.0 * kCameraHeight * std::tan(kVerticalFov / 2.0) / kFrame.height;
  const double edge = kLightHeight * std::tan(glm::radians(kOuterDegrees));
  double lit_radius = 0.0;
  for (uint32_t y = 0; y < kFrame.height; ++y)
    for (uint32_t x = 0; x < kFrame.width; ++x)
      if (red(x, y) > 0.0f) lit_radius = std::max(lit_radius, radius_at(x, y));
  std::printf("lit radius %.4f m, h tan(outer) %.4f m, pixel footprint %.4f m\n", lit_radius, edge, footprint);
  EXPECT_LE(lit_radius, edge);
  EXPECT_GE(lit_radius, edge - footprint);
}

TEST_F(SpotLightRender, TheCentreIsThePointLight) {
  // The four pixels around the axis are 0.7 pixel footprints (0.02 m) from it, well inside the
  // inner cone (0.73 m): there the spot must be the point light, within the tolerance of the
  // test above.
  for (uint32_t y : {kFrame.height / 2 - 1, kFrame.height / 2})
    for (uint32_t x : {kFrame.width / 2 - 1, kFrame.width / 2}) {
      const double want = point_light(radius_at(x, y));
      EXPECT_NEAR(red(x, y), want, kRelative * want) << "pixel " << x << ", " << y;
    }
  std::printf("centre %.6f, point-light formula %.6f (on the axis: (1 + 0.01) / pi * I / h^2 = %.6f)\n",
              red(kFrame.width / 2, kFrame.height / 2), point_light(radius_at(kFrame.width / 2, kFrame.height / 2)),
              1.01 / kPi * kIntensity / (kLightHeight * kLightHeight));
}

}  // namespace
}  // namespace lg::test
