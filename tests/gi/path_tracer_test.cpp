// The path tracer's bookkeeping on the Cornell box under env.sky's default sky: the AOVs add up
// to the radiance, a pixel's value does not depend on how the rows were split, and a broken
// light is counted, not spread.
#include "nodes/gi/path_tracer/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg::test {
namespace {

SceneView cornell_box() {
  return make_scene_view(load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json"), 4.0f / 3.0f);
}

PathTracerOptions small_image(uint32_t spp) {
  PathTracerOptions o;
  o.width = 32, o.height = 24, o.samples_per_pixel = spp;
  return o;
}

// Every path adds emission + direct + indirect diffuse + specular into the radiance, so the
// means do too, up to float rounding of the stored means (1e-5 relative, 1e-6 absolute). The
// box is open toward the camera, so some pixels see only the sky (emission).
TEST(PathTracer, AovsAddUpToTheRadiance) {
  const PathScene scene(cornell_box(), PathEnvironment::sky(SkyParams{}));
  const ReferenceImage image = trace_reference(scene, small_image(8));
  EXPECT_EQ(image.non_finite_samples, 0u);
  double direct = 0.0, indirect = 0.0;
  for (size_t i = 0; i < image.pixel_count(); ++i) {
    const glm::vec3 sum = image.mean_of(ReferenceAov::emission)[i] + image.mean_of(ReferenceAov::direct)[i] +
                          image.mean_of(ReferenceAov::indirect_diffuse)[i] + image.mean_of(ReferenceAov::specular)[i];
    const glm::vec3 radiance = image.mean_of(ReferenceAov::radiance)[i];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], radiance[c], 1e-6 + 1e-5 * radiance[c]) << "pixel " << i;
    direct += image.mean_of(ReferenceAov::direct)[i].r;
    indirect += image.mean_of(ReferenceAov::indirect_diffuse)[i].r;
  }
  EXPECT_GT(direct, 0.0);  // the lamp and the sun reach the box
  EXPECT_GT(indirect, 0.0);
}

TEST(PathTracer, ChunksOfRowsGiveTheSamePixelsBitForBit) {
  const PathScene scene(cornell_box(), PathEnvironment::sky(SkyParams{}));
  const PathTracerOptions whole = small_image(4);
  const ReferenceImage reference = trace_reference(scene, whole);
  uint32_t row = 0;
  for (uint32_t rows : {5u, 1u, 11u, 7u}) {
    PathTracerOptions band = whole;
    band.row_begin = row, band.row_end = row + rows;
    const ReferenceImage part = trace_reference(scene, band);
    ASSERT_EQ(part.pixel_count(), size_t(rows) * whole.width);
    for (size_t a = 0; a < kReferenceAovCount; ++a)
      for (size_t i = 0; i < part.pixel_count(); ++i) {
        const size_t j = size_t(row) * whole.width + i;
        ASSERT_EQ(part.mean[a][i], reference.mean[a][j]) << "aov " << a << " pixel " << j;
        ASSERT_EQ(part.standard_error[a][i], reference.standard_error[a][j]) << "aov " << a << " pixel " << j;
      }
    row += rows;
  }
  EXPECT_EQ(row, whole.height);
}

TEST(PathTracer, ANonFiniteLightIsCountedAndLeavesTheImageFinite) {
  SceneView view = cornell_box();
  view.point_lights.push_back(
      {.position = {0.0f, 1.5f, 0.0f}, .intensity = {std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f}});
  const PathScene scene(std::move(view), PathEnvironment::none());
  const ReferenceImage image = trace_reference(scene, small_image(2));
  EXPECT_GT(image.non_finite_samples, 0u);
  for (size_t a = 0; a < kReferenceAovCount; ++a)
    for (size_t i = 0; i < image.pixel_count(); ++i) {
      ASSERT_TRUE(std::isfinite(image.mean[a][i].r) && std::isfinite(image.mean[a][i].g) &&
                  std::isfinite(image.mean[a][i].b));
      ASSERT_TRUE(std::isfinite(image.standard_error[a][i].r));
    }
}

}  // namespace
}  // namespace lg::test
