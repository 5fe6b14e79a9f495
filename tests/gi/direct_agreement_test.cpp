// The reference's direct AOV against lighting.deferred on lavapipe: a grey floor under a
// rectangle, a sphere, a tube, a point, a spot and a directional light, nothing casting shadows
// on it. Diffuse is exact in both (the deferred node's area formulas are closed forms), so what
// differs is the reference's noise, the deferred node's LTC specular for area lights, and the
// G-buffer's 8-bit albedo and 16-bit float output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/gi/path_tracer/path_tracer.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/render/deferred_graph.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{64, 48};

void place(World& world, Entity e, glm::vec3 position, glm::quat rotation = {1.0f, 0.0f, 0.0f, 0.0f}) {
  Transform& t = world.add(e, Transform{});
  t.position = position, t.rotation = rotation;
}

World lit_floor(float roughness) {
  World world;
  Entity floor = world.create("floor");
  PbrMaterial grey;
  grey.base_color = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f), grey.roughness = roughness;
  const int material = world.add_material(grey);
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(12.0f, 12.0f)), material});
  world.add(floor, Transform{});
  Entity camera = world.create("camera");
  world.add(camera, Camera{.vertical_fov = 1.0f});
  place(world, camera, {0.0f, 3.0f, 2.5f}, look_rotation({0.0f, -0.8f, -0.6f}));
  Entity rect = world.create("rect");
  world.add(rect, RectLight{.intensity = 4.0f, .width = 0.8f, .height = 0.5f});
  place(world, rect, {-0.8f, 1.0f, -0.5f}, look_rotation({0.2f, -1.0f, 0.1f}));
  Entity sphere = world.create("sphere");
  world.add(sphere, SphereLight{.color = {1.0f, 0.8f, 0.6f}, .intensity = 20.0f, .radius = 0.15f});
  place(world, sphere, {0.9f, 0.6f, 0.0f});
  Entity tube = world.create("tube");
  world.add(tube, TubeLight{.color = {0.6f, 0.8f, 1.0f}, .intensity = 15.0f, .length = 1.0f, .radius = 0.05f});
  place(world, tube, {0.0f, 0.5f, 0.8f});
  Entity point = world.create("point");
  world.add(point, PointLight{.intensity = 0.5f});
  place(world, point, {0.5f, 1.2f, -1.5f});
  Entity spot = world.create("spot");
  world.add(spot,
            SpotLight{.intensity = 1.5f, .inner_cone_angle = 0.3f, .outer_cone_angle = 0.5f, .casts_shadows = false});
  place(world, spot, {-0.3f, 1.5f, 0.8f}, look_rotation({0.2f, -1.0f, -0.3f}));
  Entity sun = world.create("sun");
  world.add(sun, DirectionalLight{.intensity = 0.5f});
  place(world, sun, {0.0f, 0.0f, 0.0f}, look_rotation({0.3f, -1.0f, -0.4f}));
  return world;
}

struct Comparison {
  double relative_mean_error = 0.0;  // |mean(traced) - mean(raster)| / mean(raster)
  double relative_rms_error = 0.0;   // RMS over pixels of (traced - raster), over mean(raster)
  double relative_noise = 0.0;       // RMS of the traced standard errors, over mean(raster)
  // The RMS over pixels whose 3x3 neighbourhood is all drawn (not black) in the raster image: away
  // from silhouettes against the dark, where the raster path covers a pixel by its centre and the
  // reference by the share of its area.
  double relative_interior_rms_error = 0.0;
  // The RMS difference without the reference's own noise (independent errors add in squares).
  double systematic() const {
    return std::sqrt(std::max(0.0, relative_rms_error * relative_rms_error - relative_noise * relative_noise));
  }
};

// lighting.deferred's image against the reference's `aov` (its direct light unless said).
Comparison compare(const World& world, uint32_t spp, ReferenceAov aov = ReferenceAov::direct) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // light.color is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(deferred_lighting_graph());
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  const std::vector<float> raster = renderer.executor().read_image("light.color");

  const PathScene scene(make_scene_view(world, float(kFrame.width) / kFrame.height), PathEnvironment::none());
  PathTracerOptions o;
  o.width = kFrame.width, o.height = kFrame.height, o.samples_per_pixel = spp, o.max_bounces = 1;
  const ReferenceImage traced = trace_reference(scene, o);
  const auto& mean = traced.mean_of(aov);
  const auto& error = traced.error_of(aov);
  double raster_sum = 0.0, traced_sum = 0.0, squared = 0.0, noise = 0.0;
  const size_t n = traced.pixel_count();
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      raster_sum += raster[4 * i + c], traced_sum += mean[i][c];
      squared += (mean[i][c] - raster[4 * i + c]) * (mean[i][c] - raster[4 * i + c]);
      noise += double(error[i][c]) * error[i][c];
    }
  const double raster_mean = raster_sum / (3.0 * n);
  const auto drawn = [&](int x, int y) {
    const size_t i = size_t(y) * kFrame.width + size_t(x);
    return raster[4 * i] + raster[4 * i + 1] + raster[4 * i + 2] > 0.0f;
  };
  double interior_squared = 0.0;
  size_t interior = 0;
  for (int y = 1; y + 1 < int(kFrame.height); ++y)
    for (int x = 1; x + 1 < int(kFrame.width); ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) all = all && drawn(x + dx, y + dy);
      if (!all) continue;
      const size_t i = size_t(y) * kFrame.width + size_t(x);
      for (int c = 0; c < 3; ++c) interior_squared += std::pow(mean[i][c] - raster[4 * i + c], 2.0);
      ++interior;
    }
  return {std::abs(traced_sum - raster_sum) / raster_sum, std::sqrt(squared / (3.0 * n)) / raster_mean,
          std::sqrt(noise / (3.0 * n)) / raster_mean,
          interior > 0 ? std::sqrt(interior_squared / (3.0 * double(interior))) / raster_mean : 0.0};
}

// The reference's own noise is taken out of the per-pixel RMS difference: what is left, at most 4% of the mean, is the
// deferred node's approximation (LTC specular, 8-bit albedo, half-float output); the means agree
// to 1.5%.
TEST(DirectAgreement, ReferenceDirectLightMatchesTheDeferredNode) {
  for (float roughness : {1.0f, 0.5f}) {
    const Comparison c = compare(lit_floor(roughness), 128);
    std::printf("roughness %.1f: mean %.4f, rms %.4f, reference noise %.4f, rest %.4f (relative)\n", roughness,
                c.relative_mean_error, c.relative_rms_error, c.relative_noise, c.systematic());
    EXPECT_LT(c.relative_mean_error, 0.015) << "roughness " << roughness;
    EXPECT_LT(c.systematic(), 0.04) << "roughness " << roughness;
  }
}

// A glTF asset of examples/gltf with its head-on sun replaced by a point light (a delta: the
// reference's direct light is then exact, with no noise).
World asset_under_point_light(const char* name) {
  World world = load_world(std::string(LUMAGRAPH_SOURCE_DIR "/examples/gltf/") + name);
  std::vector<Entity> suns;
  world.each<DirectionalLight>([&](Entity e, DirectionalLight&) { suns.push_back(e); });
  for (Entity e : suns) world.destroy(e);
  Entity point = world.create("point");
  world.add(point, PointLight{.intensity = 2.0f, .casts_shadows = false});
  place(world, point, {0.8f, 0.6f, 1.5f});
  return world;
}

// The same comparison on a glTF asset (examples/gltf/metal-rough-plane.gltf): its metalness and
// roughness come from a texture read through texcoord set 1 with a transform (left half rough
// dielectric, right half metal of roughness 0.2), its base colour is multiplied by vertex
// colours, under the point light and under the asset's own head-on sun (a disk of the default
// angular radius, so the reference is noisy there: its noise is taken out). A reference that read
// the material's factors alone (roughness 1, metal 1) is 85% off in the mean. The metal's
// narrow lobe (alpha 0.04) resolves the G-buffer's normal: before the normal was stored with
// 0 on a step of its 10-bit channel (nodes/common/shaders/gbuffer.glsl) the plane's normal read
// back tilted by 1.4 mrad, and the per-pixel RMS difference was 38% of the mean under the point
// light, and the sun's image 2.2% off in the mean; now 2.1% and 0.2%. Allowed: 1% in the mean
// (the G-buffer's 8-bit sRGB albedo is 0.1%) and 5% RMS per pixel beyond the reference's noise
// (half-float output and the 8-bit roughness texel on the highlight's steep flank).
TEST(DirectAgreement, TexturedAssetMatchesTheDeferredNode) {
  const World own_sun = load_world(LUMAGRAPH_SOURCE_DIR "/examples/gltf/metal-rough-plane.gltf");
  for (const auto& [name, world] :
       {std::pair<const char*, World>{"point light", asset_under_point_light("metal-rough-plane.gltf")},
        {"its own sun", own_sun}}) {
    const Comparison c = compare(world, 4);
    std::printf("metal-rough plane under %s: mean %.4f, rms %.4f, reference noise %.4f, rest %.4f (relative)\n", name,
                c.relative_mean_error, c.relative_rms_error, c.relative_noise, c.systematic());
    EXPECT_LT(c.relative_mean_error, 0.01) << name;
    EXPECT_LT(c.systematic(), 0.05) << name;
  }
}

// examples/gltf/normal-mapped-plane.gltf (a constant normal texel tilting the normal 30 degrees
// toward +u, tangents generated by the importer, rough white-grey dielectric) under the same
// point light: the reference bends its normal as the G-buffer does. The means agree to 0.29% and
// the per-pixel RMS difference is 0.45% of the mean (a reference without the normal map: 6.3% and
// 23%). Allowed: 1% for each, the G-buffer's 8-bit sRGB albedo (0.1%), its rgb10a2 normal (about
// 1 mrad) and half-float output, not a wrong frame, which moves the light by tens of percent.
TEST(DirectAgreement, NormalMappedAssetMatchesTheDeferredNode) {
  const Comparison c = compare(asset_under_point_light("normal-mapped-plane.gltf"), 4);
  std::printf("normal-mapped plane: mean %.4f, rms %.4f, reference noise %.4f (relative)\n", c.relative_mean_error,
              c.relative_rms_error, c.relative_noise);
  EXPECT_EQ(c.relative_noise, 0.0);  // delta lights only
  EXPECT_LT(c.relative_mean_error, 0.01);
  EXPECT_LT(c.relative_rms_error, 0.01);
}

// examples/gltf/emissive-surface.gltf (an emissive texture of orange and blue texels times a
// factor times KHR_materials_emissive_strength 4) with its sun removed: what lighting.deferred
// writes is then the emission alone, which must be the reference's emission AOV. The means
// agree to 0.7% (without the emission pass the image is black: 100%). Allowed: 2%, for the
// texture's 8-bit sRGB texels and half-float output (0.1%) and the reference averaging the
// texture over each pixel where the raster path samples its centre. Per pixel they do not agree
// yet, and this is not asserted: away from the outline the RMS difference is 40% of the mean,
// because lavapipe's anisotropic filtering blurs this 2x2 texture magnified 20 times toward its
// 1x1 mip (18% with anisotropy off, still lower in contrast than the bilinear reference, and
// with a visible seam along the triangles' shared edge): a finding about texture sampling, left open.
TEST(DirectAgreement, EmissionMatchesTheReference) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/gltf/emissive-surface.gltf");
  std::vector<Entity> suns;
  world.each<DirectionalLight>([&](Entity e, DirectionalLight&) { suns.push_back(e); });
  for (Entity e : suns) world.destroy(e);
  const Comparison c = compare(world, 4, ReferenceAov::emission);
  std::printf("emissive surface: mean %.4f, rms %.4f (away from the outline %.4f), reference noise %.4f (relative)\n",
              c.relative_mean_error, c.relative_rms_error, c.relative_interior_rms_error, c.relative_noise);
  EXPECT_LT(c.relative_mean_error, 0.02);
}

}  // namespace
}  // namespace lg::test
