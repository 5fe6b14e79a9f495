// Directional occlusion against ray tracing (issue 6: directional GTAO must beat AO x
// irradiance): surface points of the bunny and of the floor around it
// (examples/worlds/stanford-bunny.json), lit by ../shared/data/env/grace.hdr. The reference
// integrates L(w) V(w) max(0, n . w) over every texel of the environment's cube (48^2 a face)
// with one Embree visibility ray per texel. Against it:
//   AO x SH(n)             k_A times the SH irradiance at the normal (lighting.ibl with ao alone),
//   AO x SH(bent)          k_A times the SH irradiance at the bent normal,
//   cone SH (lighting.ibl) the SH radiance integrated over the visibility cone with the cosine
//                          about the normal (lighting.ibl with bent normals),
//   cone, exact radiance   the same integral over the cube's own radiance (the cone model
//                          without SH truncation),
// with k_A, the bent normal and the cone ray traced (estimate_occlusion, 4,096 rays), and the
// SH the double-precision projection of the same cube (order 2, as the examples use). The
// relative error of a point is |E - E_ref| / E_ref in luminance; it is also given over the
// unoccluded irradiance. Points whose reference is under 2% of their unoccluded irradiance
// (the floor inside the bunny's open base, its underside a few millimetres above the floor,
// where a relative error means nothing) are left out and counted. The table goes to the log and to
// build/ibl_occlusion_vs_raytrace.csv.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <random>
#include <vector>

#include "nodes/env/common/sh_basis.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "nodes/lighting/ibl/ibl_occlusion.h"
#include "nodes/occlusion/estimate/occlusion_estimate.h"
#include "nodes/raytrace/parallel_for.h"
#include "nodes/raytrace/ray_scene.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/env/env_test_support.h"
#include "tests/lighting/occluded_irradiance.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kFace = 48;        // grace has 64 texels a quarter turn (256 x 128), resampled 4x4
constexpr int kOcclusionRays = 4096;  // k_A's standard error at most 0.5 / 64 = 0.008
constexpr int kBunnyPoints = 768, kFloorPoints = 384;
constexpr int kShOrder = 2;

struct Triangles {
  size_t first = 0, count = 0;  // a draw's range of the RayScene's triangles
};

// Each draw's triangles in the RayScene (draws in order, each mesh's triangles in order).
std::vector<Triangles> draw_ranges(const SceneView& view) {
  std::vector<Triangles> ranges;
  size_t first = 0;
  for (const DrawItem& draw : view.draws) {
    const size_t count = view.mesh_of(draw).indices.size() / 3;
    ranges.push_back({first, count});
    first += count;
  }
  return ranges;
}

// `count` points uniform by area on the triangles of `range` that `accept` keeps, with their
// geometric normals (the side counter-clockwise triangles face).
template <class Accept>
std::vector<SurfacePoint> sample_surface(const RayScene& scene, Triangles range, int count, std::mt19937_64& rng,
                                         Accept accept) {
  std::vector<double> area_sum;
  for (size_t t = 0; t < range.count; ++t) {
    const auto c = scene.triangle(uint32_t(range.first + t));
    const double area = 0.5 * glm::length(glm::cross(glm::dvec3(c[1] - c[0]), glm::dvec3(c[2] - c[0])));
    area_sum.push_back((area_sum.empty() ? 0.0 : area_sum.back()) + area);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SurfacePoint> points;
  while (int(points.size()) < count) {
    const size_t t = std::lower_bound(area_sum.begin(), area_sum.end(), unit(rng) * area_sum.back()) - area_sum.begin();
    const auto c = scene.triangle(uint32_t(range.first + std::min(t, range.count - 1)));
    const glm::vec3 cross = glm::cross(c[1] - c[0], c[2] - c[0]);
    if (glm::length(cross) <= 0) continue;
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const glm::vec3 p = c[0] + float(u) * (c[1] - c[0]) + float(v) * (c[2] - c[0]);
    if (accept(p)) points.push_back({p, glm::normalize(cross)});
  }
  return points;
}

struct PointIrradiance {
  double reference = 0, open = 0;  // luminance: occluded (the reference) and unoccluded
  double exact_cone = 0;           // the cube's radiance through the cone, cosine about n unclipped as the formula
  double ao_normal = 0, ao_bent = 0, cone = 0, sh_open = 0;
};

PointIrradiance irradiance_at(const RayScene& scene, const CubeImage& env, std::span<const glm::dvec3> sh,
                              const SurfacePoint& point, uint64_t seed) {
  const OcclusionResult occ = estimate_occlusion(scene, point.position, point.normal, {.rays = kOcclusionRays}, seed);
  const glm::dvec3 n(point.normal), bent(occ.bent_normal);
  const OccludedIrradiance traced = occluded_irradiance(scene, env, point.position, point.normal, n);
  glm::dvec3 exact_cone(0.0);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < env.size; ++j)
      for (uint32_t i = 0; i < env.size; ++i) {
        const glm::dvec3 d = glm::normalize(env.direction(f, i, j));
        if (glm::dot(bent, d) >= occ.cone_cos)
          exact_cone += glm::dvec3(env.at(f, i, j)) * texel_solid_angle(env.size, i, j) * glm::dot(n, d);
      }
  const double k_a = occ.visibility;
  PointIrradiance out;
  out.reference = luminance(traced.reference);
  out.open = luminance(traced.open);
  out.exact_cone = luminance(exact_cone);
  out.sh_open = luminance(glm::max(evaluate_sh(sh, n), glm::dvec3(0.0)));
  out.ao_normal = k_a * out.sh_open;
  out.ao_bent = k_a * luminance(glm::max(evaluate_sh(sh, bent), glm::dvec3(0.0)));
  out.cone = luminance(cone_lobe_irradiance(sh, n, bent, occ.cone_cos, k_a));
  return out;
}

TEST(IblOcclusionRaytrace, ConeFoldedIrradianceBeatsAmbientOcclusionOnTheBunny) {
  const fs::path world_file = fs::path(LUMAGRAPH_SOURCE_DIR) / "examples" / "worlds" / "stanford-bunny.json";
  const fs::path shared = fs::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data";
  std::optional<CubeImage> env = load_probe("grace.hdr", kFace);
  if (!env || !fs::exists(shared / "mesh" / "bunny.obj")) GTEST_SKIP() << "no " << shared << " (grace.hdr, bunny.obj)";
  WorldLoadOptions options;
  options.asset_roots.roots = {world_file.parent_path().string(), shared.string()};
  const SceneView view = make_scene_view(load_world(world_file.string(), options), 1.0f);
  const RayScene scene(view);

  // The bunny is the draw with the most triangles, the floor the other one; floor points within
  // 0.3 m of the bunny's footprint, where it occludes.
  const std::vector<Triangles> ranges = draw_ranges(view);
  ASSERT_EQ(ranges.size(), 2u);
  const size_t bunny = ranges[0].count > ranges[1].count ? 0 : 1;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (size_t t = 0; t < ranges[bunny].count; ++t)
    for (const glm::vec3& c : scene.triangle(uint32_t(ranges[bunny].first + t)))
      lo = glm::min(lo, c), hi = glm::max(hi, c);
  std::mt19937_64 rng(606);
  std::vector<SurfacePoint> points =
      sample_surface(scene, ranges[bunny], kBunnyPoints, rng, [](const glm::vec3&) { return true; });
  const std::vector<SurfacePoint> floor =
      sample_surface(scene, ranges[1 - bunny], kFloorPoints, rng, [&](const glm::vec3& p) {
        return p.x > lo.x - 0.3f && p.x < hi.x + 0.3f && p.z > lo.z - 0.3f && p.z < hi.z + 0.3f;
      });
  points.insert(points.end(), floor.begin(), floor.end());

  std::vector<double> bands(kShOrder + 1);
  for (int l = 0; l <= kShOrder; ++l) bands[l] = cosine_lobe_band(l);
  const std::vector<glm::dvec3> sh = project_sh_reference(*env, kShOrder, bands).coefficients;

  std::vector<PointIrradiance> results(points.size());
  parallel_for(points.size(), [&](size_t i) { results[i] = irradiance_at(scene, *env, sh, points[i], 6060 + i); });

  // Per method, the relative error and the error relative to the unoccluded irradiance (which
  // weighs a point by the light it could get rather than by the light it gets).
  struct Method {
    const char* name;
    double PointIrradiance::*value;
    std::vector<double> relative, of_open;
  };
  Method methods[] = {{"AO x SH(n)", &PointIrradiance::ao_normal, {}, {}},
                      {"AO x SH(bent)", &PointIrradiance::ao_bent, {}, {}},
                      {"cone SH (lighting.ibl)", &PointIrradiance::cone, {}, {}},
                      {"cone, exact radiance", &PointIrradiance::exact_cone, {}, {}}};
  std::vector<double> sh_truncation, gain;
  int sealed = 0;
  for (const PointIrradiance& r : results) {
    if (r.reference < 0.02 * r.open) {
      ++sealed;
      continue;
    }
    sh_truncation.push_back(std::abs(r.sh_open - r.open) / r.open);
    for (Method& m : methods) {
      m.relative.push_back(std::abs(r.*m.value - r.reference) / r.reference);
      m.of_open.push_back(std::abs(r.*m.value - r.reference) / r.open);
    }
    gain.push_back(methods[0].relative.back() - methods[2].relative.back());
  }
  ASSERT_GE(gain.size(), points.size() * 3 / 4) << sealed << " of " << points.size() << " points sealed";

  std::cout << "grace.hdr on the bunny world, " << gain.size() << " points (" << sealed
            << " sealed left out), SH order " << kShOrder << "; unoccluded SH irradiance against the cube's: mean "
            << error_stats(sh_truncation).mean << ", p95 " << error_stats(sh_truncation).p95 << "\n";
  std::cout << std::left << std::setw(26) << "method" << std::right << std::setw(16) << "relative mean" << std::setw(8)
            << "p95" << std::setw(16) << "of open mean" << std::setw(8) << "p95"
            << "\n";
  std::ofstream csv(fs::path(LUMAGRAPH_BINARY_DIR) / "ibl_occlusion_vs_raytrace.csv");
  csv << "method,points,relative_mean,relative_p95,of_open_mean,of_open_p95\n";
  for (const Method& m : methods) {
    const ErrorStats rel = error_stats(m.relative), open = error_stats(m.of_open);
    std::cout << std::left << std::setw(26) << m.name << std::right << std::fixed << std::setprecision(4)
              << std::setw(16) << rel.mean << std::setw(8) << rel.p95 << std::setw(16) << open.mean << std::setw(8)
              << open.p95 << "\n";
    csv << '"' << m.name << "\"," << m.relative.size() << ',' << rel.mean << ',' << rel.p95 << ',' << open.mean << ','
        << open.p95 << "\n";
  }

  // The cone must beat AO x SH(n) by more than chance: the mean of the per-point gain at least
  // 4 standard errors above 0 (the points are independent draws; k_A's ray noise is in both).
  const MeanAndError mean_gain = mean_and_error(gain);
  std::cout << "mean gain of the cone over AO x SH(n): " << mean_gain.mean << " +- " << mean_gain.standard_error
            << "\n";
  EXPECT_GT(mean_gain.mean, 4 * mean_gain.standard_error);
  EXPECT_LT(error_stats(methods[2].relative).p95, error_stats(methods[0].relative).p95);
}

}  // namespace
}  // namespace lg::test
