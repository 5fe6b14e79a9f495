// Directional GTAO end to end (issue 6): occlusion.gtao renders the bunny world on lavapipe, and
// its own ambient occlusion, bent normals and cones light each pixel under
// ../shared/data/env/grace.hdr the two ways lighting.ibl can, both against the ray-traced
// irradiance with visibility inside the integral (tests/lighting/occluded_irradiance.h):
//   AO x SH(n)   GTAO's k_A times the SH irradiance at the normal (lighting.ibl with ao alone),
//   cone SH      the SH radiance over GTAO's visibility cone, cosine about the normal, scaled by
//                GTAO's k_A (lighting.ibl with ao and bent normals).
// ibl_occlusion_raytrace_test.cpp measures the same formulas with ray-traced cones; this one
// measures what screen space actually hands them. Each sampled pixel's surface comes from a
// primary ray through its centre (the G-buffer's projection); the cosine is about the
// G-buffer's shading normal. GTAO sees 0.5 m around a pixel and the reference the whole scene,
// and both methods share that loss. Pixels whose reference is under 2% of their unoccluded
// irradiance are left out, as in the ray-traced-cone test.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "nodes/common/gbuffer_normal.h"
#include "nodes/env/common/sh_basis.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "nodes/lighting/ibl/ibl_occlusion.h"
#include "nodes/occlusion/reference/height_field_reference.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/parallel_for.h"
#include "tests/env/env_test_support.h"
#include "tests/lighting/occluded_irradiance.h"
#include "tests/occlusion/ao_render.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kWidth = 160, kHeight = 90, kStride = 3;  // 1,590 pixels sampled
constexpr uint32_t kFace = 48;                               // as ibl_occlusion_raytrace_test.cpp
constexpr int kShOrder = 2;

struct PixelIrradiance {
  bool covered = false;
  double reference = 0, open = 0, ao_normal = 0, cone = 0;
};

TEST(DirectionalGtao, GtaoConesBeatAmbientOcclusionTimesIrradianceOnTheBunny) {
  const fs::path shared = fs::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data";
  std::optional<CubeImage> env = load_probe("grace.hdr", kFace);
  if (!env || !fs::exists(shared / "mesh" / "bunny.obj")) GTEST_SKIP() << "no " << shared << " (grace.hdr, bunny.obj)";
  const AoRender render = render_occlusion(
      load_example_world("stanford-bunny"), kWidth, kHeight,
      R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "radius": 0.5 } })", {.frames = 8});
  ASSERT_EQ(render.validation_messages, 0u);
  const RayScene scene(render.view);
  const CameraPixels pixels(render.view.camera, kWidth, kHeight);

  std::vector<double> bands(kShOrder + 1);
  for (int l = 0; l <= kShOrder; ++l) bands[l] = cosine_lobe_band(l);
  const std::vector<glm::dvec3> sh = project_sh_reference(*env, kShOrder, bands).coefficients;

  const uint32_t columns = kWidth / kStride, rows = kHeight / kStride;
  std::vector<PixelIrradiance> results(columns * rows);
  parallel_for(results.size(), [&](size_t s) {
    const uint32_t x = uint32_t(s % columns) * kStride + 1, y = uint32_t(s / columns) * kStride + 1;
    const size_t pixel = size_t(y) * kWidth + x;
    const glm::dvec3 eye = pixels.eye(), direction = pixels.ray_direction(x, y);
    const std::optional<RayHit> hit = scene.intersect(glm::vec3(eye), glm::vec3(direction), 1e30f);
    if (!hit || render.gbuffer.depth[pixel] <= 0.0f) return;
    const glm::dvec3 n = decode_gbuffer_normal(&render.gbuffer.normal[4 * pixel]);
    const glm::vec4 bent_cone(render.bent_normals[4 * pixel], render.bent_normals[4 * pixel + 1],
                              render.bent_normals[4 * pixel + 2], render.bent_normals[4 * pixel + 3]);
    if (glm::length(glm::vec3(bent_cone)) < 0.5f) return;  // GTAO wrote no bent normal here
    const glm::vec3 position = glm::vec3(eye + direction * double(hit->distance));
    const OccludedIrradiance traced = occluded_irradiance(scene, *env, position, hit->normal, n);
    const double k_a = render.last_ao[4 * pixel];
    PixelIrradiance& r = results[s];
    r.covered = true;
    r.reference = luminance(traced.reference);
    r.open = luminance(traced.open);
    r.ao_normal = k_a * luminance(glm::max(evaluate_sh(sh, n), glm::dvec3(0.0)));
    r.cone = luminance(cone_lobe_irradiance(sh, n, glm::normalize(glm::dvec3(bent_cone)), bent_cone.w, k_a));
  });

  std::vector<double> ao_error, cone_error, gain, ao_of_open, cone_of_open;
  size_t sealed = 0, covered = 0;
  for (const PixelIrradiance& r : results) {
    if (!r.covered) continue;
    ++covered;
    if (r.reference < 0.02 * r.open) {
      ++sealed;
      continue;
    }
    ao_error.push_back(std::abs(r.ao_normal - r.reference) / r.reference);
    cone_error.push_back(std::abs(r.cone - r.reference) / r.reference);
    gain.push_back(ao_error.back() - cone_error.back());
    ao_of_open.push_back(std::abs(r.ao_normal - r.reference) / r.open);
    cone_of_open.push_back(std::abs(r.cone - r.reference) / r.open);
  }
  ASSERT_GE(gain.size(), 500u) << covered << " pixels covered, " << sealed << " sealed";
  const ErrorStats ao = error_stats(ao_error), cone = error_stats(cone_error);
  const MeanAndError mean_gain = mean_and_error(gain);
  std::printf("grace.hdr on the bunny world, GTAO high at %ux%u, %zu pixels (%zu sealed left out)\n", kWidth, kHeight,
              gain.size(), sealed);
  const ErrorStats ao_open = error_stats(ao_of_open), cone_open = error_stats(cone_of_open);
  std::printf("  AO x SH(n): relative error mean %.4f, p95 %.4f; over the unoccluded mean %.4f, p95 %.4f\n", ao.mean,
              ao.p95, ao_open.mean, ao_open.p95);
  std::printf("  cone SH:    relative error mean %.4f, p95 %.4f; over the unoccluded mean %.4f, p95 %.4f\n", cone.mean,
              cone.p95, cone_open.mean, cone_open.p95);
  std::printf("  mean gain %.4f +- %.4f\n", mean_gain.mean, mean_gain.standard_error);
  // Better than chance: the per-pixel gain's mean at least 4 standard errors above 0.
  EXPECT_GT(mean_gain.mean, 4 * mean_gain.standard_error);
}

}  // namespace
}  // namespace lg::test
