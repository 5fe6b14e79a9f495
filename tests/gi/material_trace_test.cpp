// The ray tracers read the glTF material's alpha, normal map and sidedness as the G-buffer does,
// on the generated assets of examples/gltf (scripts/make-test-gltf): the cut-out quad's shadow
// has its hole and every kind of ray passes through it, the normal-mapped plane is lit along its
// mapped normal, and camera rays cull back faces of single-sided materials only.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <utility>

#include "nodes/gi/path_tracer/microfacet_brdf.h"
#include "nodes/gi/path_tracer/path_tracer.h"
#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/raytrace/camera_pixels.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg::test {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kPi = std::numbers::pi;

// The asset with its sun turned to travel along `direction` and made a point on the sky (radius
// 0: a delta, so the reference's direct light is exact and noiseless).
World asset(const char* name, glm::vec3 direction = {0.0f, 0.0f, -1.0f}) {
  World world = load_world(std::string(LUMAGRAPH_SOURCE_DIR "/examples/gltf/") + name);
  world.each<DirectionalLight>([&](Entity e, DirectionalLight& sun) {
    sun.angular_radius = 0.0f;
    world.get<Transform>(e).rotation = look_rotation(direction);
  });
  return world;
}

// One path per pixel of the asset's camera (size x size, aspect 1), direct light only.
struct DirectImage {
  SceneView view;
  ReferenceImage image;

  glm::dvec3 at(uint32_t x, uint32_t y) const { return image.mean_of(ReferenceAov::direct)[y * image.width + x]; }
};

DirectImage direct_light(const World& world, uint32_t size) {
  DirectImage out{make_scene_view(world, 1.0f), {}};
  const PathScene scene(out.view, PathEnvironment::none());
  PathTracerOptions o;
  o.width = o.height = size, o.samples_per_pixel = 1, o.max_bounces = 1;
  out.image = trace_reference(scene, o);
  return out;
}

// What pixel (x, y) shows of the plane z = `depth` with `normal` and the material (base colour,
// roughness, dielectric) under a sun of 3 W/m^2 from `to_sun` with nothing in between, by the
// BRDF the tracer and the raster share (microfacet_brdf.h, checked on its own by the furnace).
glm::dvec3 sunlit(const DirectImage& d, uint32_t x, uint32_t y, double depth, glm::dvec3 normal, glm::dvec3 base,
                  double roughness, glm::dvec3 to_sun) {
  const CameraPixels pixels(d.view.camera, d.image.width, d.image.height);
  const glm::dvec3 direction = pixels.ray_direction(x, y);
  const glm::dvec3 point = pixels.eye() + direction * ((depth - pixels.eye().z) / direction.z);
  const BrdfSurface surface = make_brdf_surface(normal, SurfaceMaterial{base, roughness, 0.0, glm::dvec3(0.0)});
  return evaluate_brdf(surface, glm::normalize(pixels.eye() - point), to_sun).sum() * 3.0;
}

// cut-out-quad.gltf: a 2 m quad at z = 0, its middle (|x|, |y| < 0.5) transparent, before a red
// wall at z = -1 (base colour 0.9, 0.1, 0.1), under a head-on sun of 3 W/m^2, seen from z = 3
// (fov 0.8 rad). The hole's shadow on the wall is |x| < 0.5 and the camera sees the wall through
// the hole out to |x| < 0.667: pixel columns 23-41 of 64 see the lit wall, 42-44 the quad's shadow
// around the hole, 45 and beyond the quad itself (green, 0.2, 0.9, 0.2 x white texels). Exact
// values (a delta light): 1e-5 relative allows float storage.
TEST(MaterialTrace, CutOutQuadsShadowHasTheHole) {
  const DirectImage d = direct_light(asset("cut-out-quad.gltf"), 64);
  const glm::dvec3 z(0.0, 0.0, 1.0);
  auto expect_near = [](glm::dvec3 traced, glm::dvec3 expected, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(traced[c], expected[c], 1e-5 * expected[c]) << what << ", channel " << c;
  };
  for (uint32_t x : {26u, 32u, 40u})
    expect_near(d.at(x, 32), sunlit(d, x, 32, -1.0, z, {0.9, 0.1, 0.1}, 1.0, z), "the wall lit through the hole");
  EXPECT_EQ(d.at(43, 32), glm::dvec3(0.0)) << "the wall in the quad's shadow, seen through the hole";
  expect_near(d.at(50, 32), sunlit(d, 50, 32, 0.0, z, {0.2, 0.9, 0.2}, 0.8, z), "the quad's opaque border");
}

// The same hole for the rays bakes trace: a probe's ray (probe bakes) and RayScene's occlusion
// queries, single and in packets (occlusion bakes), pass through the hole and stop at the border.
TEST(MaterialTrace, BakeRaysPassThroughTheCutOut) {
  const PathScene scene(make_scene_view(asset("cut-out-quad.gltf"), 1.0f), PathEnvironment::none());
  const PathTransport transport(scene, 1);
  const PathRandom random(1, 0, transport.dimensions_per_bounce());
  const ProbeRay through = transport.probe_ray({0.2, 0.1, -0.5}, {0.0, 0.0, 1.0}, random);
  EXPECT_TRUE(std::isinf(through.distance)) << through.distance;
  const ProbeRay border = transport.probe_ray({0.75, 0.1, -0.5}, {0.0, 0.0, 1.0}, random);
  EXPECT_NEAR(border.distance, 0.5, 1e-6);
  EXPECT_TRUE(border.back_face);  // the quad faces +Z

  const RayScene& rays = scene.rays();
  EXPECT_FALSE(rays.occluded({0.2f, 0.1f, -0.5f}, {0, 0, 1}, kInf));
  EXPECT_TRUE(rays.occluded({0.75f, 0.1f, -0.5f}, {0, 0, 1}, kInf));
  // From (0, 0, -0.5) these reach z = 0 at x = 0, at x = 0.75 (the border) and at (0.15, 0.15).
  const glm::vec3 directions[] = {
      {0.0f, 0.0f, 1.0f}, glm::normalize(glm::vec3(1.5f, 0.0f, 1.0f)), glm::normalize(glm::vec3(0.3f, 0.3f, 1.0f))};
  bool blocked[3];
  rays.occluded_packet({0.0f, 0.0f, -0.5f}, directions, kInf, blocked);
  EXPECT_FALSE(blocked[0]);
  EXPECT_TRUE(blocked[1]);
  EXPECT_FALSE(blocked[2]);
  const auto hit = rays.intersect({0.0f, 0.0f, 3.0f}, {0, 0, -1}, kInf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 4.0f, 1e-5f);  // the wall behind the hole
}

// normal-mapped-plane.gltf: a plane facing +Z whose constant normal texel (191, 128, 238) tilts
// the normal 30 degrees toward +u (+X here: u grows with x), base colour 0.8, roughness 1. Under
// a sun from 30 degrees off the axis toward +X the mapped normal faces it (n.l = 1 up to the
// texel's 8-bit rounding) where the unmapped one gives cos 30, and from the -X side cos 60
// against cos 30: the traced pixels must be what the BRDF gives with the decoded texel's normal.
// Exact values (a delta light, constant texel): 1e-5 relative.
TEST(MaterialTrace, NormalMappedPlaneIsLitAlongItsMappedNormal) {
  const glm::dvec3 m = glm::dvec3(191.0, 128.0, 238.0) / 255.0 * 2.0 - 1.0;
  const glm::dvec3 mapped = glm::normalize(m);  // tangent +X, bitangent +Y: the plane's own axes
  const double s = std::sin(kPi / 6.0), c = std::cos(kPi / 6.0);
  for (const glm::dvec3 to_sun : {glm::dvec3(s, 0.0, c), glm::dvec3(-s, 0.0, c)}) {
    const DirectImage d = direct_light(asset("normal-mapped-plane.gltf", -glm::vec3(to_sun)), 64);
    for (const auto& [x, y] : {std::pair{32u, 32u}, {10u, 50u}, {55u, 12u}}) {
      const glm::dvec3 expected = sunlit(d, x, y, 0.0, mapped, glm::dvec3(0.8), 1.0, to_sun);
      EXPECT_NEAR(d.at(x, y).g, expected.g, 1e-5 * expected.g) << "pixel " << x << ", " << y << ", sun x " << to_sun.x;
    }
  }
}

// A normal map scaled up (10x: the bent normal lies 80 degrees off the plane's, toward +X) under
// a sun low on the -X side, which the plane faces (geometric n.l = 0.5) but the bent normal does
// not: no light, exactly 0, never negative; with bounces under env.sky every pixel stays finite
// and non-negative.
TEST(MaterialTrace, BentNormalsTurnedFromTheLightGiveNoLight) {
  World world = asset("normal-mapped-plane.gltf", -glm::vec3(-std::sin(kPi / 3.0), 0.0, std::cos(kPi / 3.0)));
  for (size_t m = 0; m < world.materials().size(); ++m) world.edit_material(int(m)).normal_scale = 10.0f;
  const DirectImage d = direct_light(world, 32);
  EXPECT_EQ(d.at(16, 16), glm::dvec3(0.0));
  const PathScene scene(d.view, PathEnvironment::sky(SkyParams{}));
  PathTracerOptions o;
  o.width = o.height = 32, o.samples_per_pixel = 4, o.max_bounces = 4;
  const ReferenceImage image = trace_reference(scene, o);
  EXPECT_EQ(image.non_finite_samples, 0u);
  for (size_t a = 0; a < kReferenceAovCount; ++a)
    for (const glm::vec3& v : image.mean[a])
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(v[c]) && v[c] >= 0.0f) << "aov " << a;
}

// Camera rays cull as the G-buffer does with cull_backfaces: the back of the single-sided red
// wall is skipped, the back of the double-sided cut-out quad is seen (shaded on the camera's
// side), and its hole shows what lies behind it (nothing). Without culling the wall's back is seen.
TEST(MaterialTrace, CameraRaysCullBackFacesOfSingleSidedMaterialsOnly) {
  const PathScene scene(make_scene_view(asset("cut-out-quad.gltf"), 1.0f), PathEnvironment::none());
  const PathTransport transport(scene, 1);
  const glm::dvec3 forward(0.0, 0.0, 1.0);
  const auto quad = transport.visible_surface({0.75, 0.1, -3.0}, forward, true);
  ASSERT_TRUE(quad) << "the double-sided quad's back";
  EXPECT_NEAR(quad->position.z, 0.0, 1e-6);
  EXPECT_NEAR(quad->normal.z, -1.0, 1e-9);
  EXPECT_FALSE(transport.visible_surface({0.2, 0.1, -3.0}, forward, true)) << "through the wall's back and the hole";
  const auto wall = transport.visible_surface({0.2, 0.1, -3.0}, forward, false);
  ASSERT_TRUE(wall);
  EXPECT_NEAR(wall->position.z, -1.0, 1e-6);
  // Other rays meet both sides of every surface: the wall's back still casts its shadow.
  EXPECT_TRUE(scene.rays().occluded({0.2f, 0.1f, -2.0f}, {0, 0, 1}, kInf));
}

}  // namespace
}  // namespace lg::test
