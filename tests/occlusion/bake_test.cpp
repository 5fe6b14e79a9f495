// The bake library: lightmap charts and volume grids, chunks that merge byte-identically to a
// single run in every mode, merge and read errors, volume points inside geometry, and the
// bunny's 256-ray vertex bake against a 4,096-ray reference within Monte Carlo noise, and rays
// through alpha-tested cut-outs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nodes/occlusion/bake/bake_domain.h"
#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/occlusion/bake/bake_outputs.h"
#include "nodes/occlusion/bake/bake_run.h"
#include "nodes/raytrace/world_mesh.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ray_test_scenes.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

// A floor with a box and a sphere on it: open, creased and closed parts.
WorldMesh small_scene() {
  return make_world_mesh(
      test::scene_of({test::floor_quad(4.0f),
                      {make_box(glm::vec3(1.0f)), glm::translate(glm::mat4(1.0f), {0.6f, 0.5f, 0.0f})},
                      {make_sphere(0.4f, 12, 6), glm::translate(glm::mat4(1.0f), {-0.7f, 0.4f, 0.3f})}}));
}

BakeDomain domain_for(BakeMode mode, const WorldMesh& mesh) {
  if (mode == BakeMode::vertex) return BakeDomain::vertices(mesh);
  if (mode == BakeMode::texel) return BakeDomain::lightmap(mesh, 128);
  return BakeDomain::volume(mesh, {9, 0, 0});
}

BakeFile bake(const WorldMesh& mesh, const BakeDomain& domain, const OcclusionSettings& settings, uint32_t index,
              uint32_t count) {
  const RayScene scene(mesh.positions, mesh.indices);
  BakeFile file;
  file.header = make_bake_header(domain, mesh, "small", settings, 7, index, count);
  if (domain.mode() == BakeMode::texel) file.lightmap_uvs = domain.lightmap_uvs();
  file.data = run_bake(scene, domain, settings, 7, file.header.range);
  return file;
}

struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("lumagraph-bake-test-" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

TEST(Bake, ChunksMergeByteIdenticallyInEveryMode) {
  const WorldMesh mesh = small_scene();
  const OcclusionSettings settings{.rays = 16};
  for (BakeMode mode : {BakeMode::vertex, BakeMode::texel, BakeMode::volume}) {
    const BakeDomain domain = domain_for(mode, mesh);
    const BakeFile whole = bake(mesh, domain, settings, 0, 1);
    // Through the file format, in shuffled order, with an uneven count of chunks.
    TempFolder folder;
    std::vector<BakeFile> parts;
    std::vector<std::string> paths;
    for (uint32_t i : {3u, 0u, 4u, 1u, 2u}) {
      paths.push_back(folder.file("part" + std::to_string(i)));
      write_bake_file(paths.back(), bake(mesh, domain, settings, i, 5));
      parts.push_back(read_bake_file(paths.back()));
    }
    const BakeFile merged = merge_bake_parts(parts, paths);
    ASSERT_EQ(encode_bake_file(merged), encode_bake_file(whole)) << bake_mode_name(mode);
    if (mode == BakeMode::volume) {
      EXPECT_EQ(encode_vti(merged), encode_vti(whole));
    }
    // The bake saw real occlusion (the comparison is not of constant data).
    size_t partial = 0;
    for (size_t i = 0; i < whole.data.size(); ++i)
      partial += whole.data.visibility[i] > 0.0f && whole.data.visibility[i] < 1.0f;
    EXPECT_GT(partial, 0u) << bake_mode_name(mode);
  }
}

TEST(Bake, FilesRoundTripAndBadOnesAreNamed) {
  const WorldMesh mesh = small_scene();
  const BakeDomain domain = BakeDomain::lightmap(mesh, 64);
  const BakeFile file =
      bake(mesh, domain, {.rays = 8, .max_distance = 0.5f, .falloff = OcclusionFalloff::obscurance}, 1, 2);
  TempFolder folder;
  const std::string path = folder.file("part.lgbake");
  write_bake_file(path, file);
  EXPECT_EQ(encode_bake_file(read_bake_file(path)), encode_bake_file(file));

  const std::string bytes = encode_bake_file(file);
  auto expect_error = [&](const std::string& name, const std::string& content, const std::string& message) {
    std::ofstream(folder.file(name), std::ios::binary) << content;
    try {
      read_bake_file(folder.file(name));
      ADD_FAILURE() << name << " was read";
    } catch (const BakeFileError& e) {
      EXPECT_NE(std::string(e.what()).find(folder.file(name) + ": " + message), std::string::npos) << e.what();
    }
  };
  expect_error("truncated", bytes.substr(0, bytes.size() - 4), "the file has");
  expect_error("short-header", bytes.substr(0, 40), "the header length");
  expect_error("not-a-bake", "P6\n1 1\n255\nabc", "not a bake file");
  std::string bad_json = bytes;
  bad_json[16] = '[';
  expect_error("bad-json", bad_json, "the header is not");
  EXPECT_THROW(read_bake_file(folder.file("missing")), BakeFileError);
  // A header whose points disagree with its layout (a lightmap of size^2 texels).
  BakeFile inconsistent = bake(mesh, domain, {.rays = 2}, 0, 1);
  inconsistent.header.points += 1, inconsistent.header.range.end += 1;
  inconsistent.data.resize(inconsistent.data.size() + 1);
  expect_error("inconsistent", encode_bake_file(inconsistent), "the texel layout describes 4096 points");
}

TEST(Bake, MergeRejectsPartsThatDoNotBelongTogether) {
  const WorldMesh mesh = small_scene();
  const BakeDomain domain = BakeDomain::vertices(mesh);
  const OcclusionSettings settings{.rays = 8};
  const BakeFile a = bake(mesh, domain, settings, 0, 3), b = bake(mesh, domain, settings, 1, 3),
                 c = bake(mesh, domain, settings, 2, 3), other = bake(mesh, domain, {.rays = 9}, 1, 3),
                 halves = bake(mesh, domain, settings, 1, 2);
  auto message = [](const std::vector<BakeFile>& parts, const std::vector<std::string>& names) {
    try {
      merge_bake_parts(parts, names);
    } catch (const BakeFileError& e) {
      return std::string(e.what());
    }
    return std::string("merged");
  };
  EXPECT_EQ(message({a, b}, {"a", "b"}), "merge: chunks missing of 3: 2");
  EXPECT_EQ(message({a, b, b, c}, {"a", "b", "b2", "c"}), "b2: chunk 1 is also in b");
  EXPECT_NE(message({a, other, c}, {"a", "other", "c"}).find("other: belongs to another bake than a"),
            std::string::npos);
  EXPECT_NE(message({a, halves, c}, {"a", "halves", "c"}).find("halves: is a chunk of 2"), std::string::npos);
  EXPECT_EQ(message({c, a, b}, {"c", "a", "b"}), "merged");
}

TEST(Bake, LightmapChartsAreInsideTheirCellsAndTexelsOnTheirTriangles) {
  const WorldMesh mesh = small_scene();
  const uint32_t size = 256;
  const BakeDomain domain = BakeDomain::lightmap(mesh, size);
  const std::vector<float> uvs = domain.lightmap_uvs();
  const size_t triangles = mesh.triangle_count();
  ASSERT_EQ(uvs.size(), 6 * triangles);
  // Overlap-free: the charts' UV boxes, grown by one texel, are pairwise disjoint.
  std::vector<std::array<float, 4>> boxes;
  for (size_t t = 0; t < triangles; ++t) {
    std::array<float, 4> box{1e9f, 1e9f, -1e9f, -1e9f};
    for (int k = 0; k < 3; ++k) {
      const float u = uvs[6 * t + 2 * k], v = uvs[6 * t + 2 * k + 1];
      ASSERT_GE(u, 0.0f);
      ASSERT_LE(u, 1.0f);
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
      box = {std::min(box[0], u), std::min(box[1], v), std::max(box[2], u), std::max(box[3], v)};
    }
    boxes.push_back(box);
  }
  const float texel = 1.0f / size;
  for (size_t i = 0; i < triangles; ++i)
    for (size_t j = i + 1; j < triangles; ++j) {
      const bool apart = boxes[i][2] + texel <= boxes[j][0] || boxes[j][2] + texel <= boxes[i][0] ||
                         boxes[i][3] + texel <= boxes[j][1] || boxes[j][3] + texel <= boxes[i][1];
      ASSERT_TRUE(apart) << "charts " << i << " and " << j;
    }
  // Texels inside a chart sample a point of its triangle with the triangle's orientation, and
  // every chart gets some.
  std::vector<int> inside_texels(triangles, 0);
  for (uint64_t index = 0; index < domain.size(); ++index) {
    const BakeSample s = domain.sample(index);
    if (s.coverage != 1.0f) continue;
    const float u = (float(index % size) + 0.5f) / size, v = (float(index / size) + 0.5f) / size;
    size_t t = 0;
    while (t < triangles && !(u >= boxes[t][0] && u <= boxes[t][2] && v >= boxes[t][1] && v <= boxes[t][3])) ++t;
    ASSERT_LT(t, triangles) << "texel " << index << " is in no chart";
    ++inside_texels[t];
    const glm::vec3 p0 = mesh.positions[mesh.indices[3 * t]], p1 = mesh.positions[mesh.indices[3 * t + 1]],
                    p2 = mesh.positions[mesh.indices[3 * t + 2]];
    const glm::vec3 area = glm::cross(p1 - p0, p2 - p0);
    if (glm::length(area) < 1e-6f) continue;  // UV-sphere pole triangles: corners at the pole, (nearly) no area
    const glm::vec3 n = glm::normalize(area);
    EXPECT_NEAR(glm::dot(s.point.position - p0, n), 0.0f, 1e-5f) << "texel " << index;
    EXPECT_GT(glm::dot(s.point.normal, n), 0.0f) << "texel " << index;
  }
  for (size_t t = 0; t < triangles; ++t) EXPECT_GT(inside_texels[t], 0) << "triangle " << t;
  try {
    BakeDomain::lightmap(mesh, 16);
    FAIL() << "a lightmap too small for its triangles was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the size must be at least"), std::string::npos) << e.what();
  }
}

TEST(Bake, VolumeGridsAndPointsInsideGeometry) {
  const WorldMesh box = make_world_mesh(test::scene_of({{make_box(glm::vec3(1.0f, 2.0f, 0.5f)), glm::mat4(1.0f)}}));
  const BakeDomain cubic = BakeDomain::volume(box, {21, 0, 0});
  EXPECT_EQ(cubic.dims()[1], 21u);  // the longest axis, y: 2.4 with the margins
  EXPECT_EQ(cubic.spacing().x, cubic.spacing().y);
  EXPECT_NEAR(cubic.origin().y, -1.2, 1e-9);
  const BakeDomain explicit_dims = BakeDomain::volume(box, {5, 6, 7});
  EXPECT_EQ(explicit_dims.size(), 5u * 6u * 7u);
  EXPECT_THROW(BakeDomain::volume(box, {1025, 0, 0}), std::invalid_argument);
  EXPECT_THROW(BakeDomain::volume(box, {1024, 1024, 1024}), std::invalid_argument);  // over the point limit
  EXPECT_THROW(BakeDomain::volume(WorldMesh{}, {8, 0, 0}), std::invalid_argument);

  const RayScene scene(box.positions, box.indices);
  const BakeData data = run_bake(scene, explicit_dims, {.rays = 64}, 3, {0, explicit_dims.size()});
  size_t inside = 0;
  for (uint64_t i = 0; i < explicit_dims.size(); ++i) {
    const glm::vec3 p = explicit_dims.sample(i).point.position;
    const bool in_box = std::fabs(p.x) < 0.5f && std::fabs(p.y) < 1.0f && std::fabs(p.z) < 0.25f;
    EXPECT_EQ(data.valid[i], in_box ? 0.0f : 1.0f) << "point " << i;
    if (in_box) {
      EXPECT_EQ(data.visibility[i], 0.0f);
    }
    inside += in_box;
  }
  EXPECT_GT(inside, 0u);
}

TEST(Bake, AnEmptyMeshBakesNothingWithoutFailing) {
  const WorldMesh empty;
  const RayScene scene(empty.positions, empty.indices);
  EXPECT_EQ(run_bake(scene, BakeDomain::vertices(empty), {}, 1, {0, 0}).size(), 0u);
  const BakeDomain lightmap = BakeDomain::lightmap(empty, 8);
  const BakeData texels = run_bake(scene, lightmap, {.rays = 4}, 1, {0, lightmap.size()});
  ASSERT_EQ(texels.size(), 64u);
  for (float v : texels.valid) EXPECT_EQ(v, 0.0f);
  EXPECT_TRUE(lightmap.lightmap_uvs().empty());
}

TEST(Bake, BunnyAt256RaysMatchesA4096RayReferenceWithinMonteCarloNoise) {
  // Per vertex, the 256-ray estimate and an independent 4,096-ray one (another seed) differ by
  // noise of standard deviation at most sqrt(k (1 - k) (1/256 + 1/4096)) (the binomial bound;
  // stratification only lowers it). Checks: at most 1% of vertices beyond 3 of those (0.27%
  // expected for Gaussian noise at the bound), and the mean difference (a bias) within 4
  // standard errors of the mean.
  const std::string path = "../shared/data/mesh/bunny.obj";
  if (!fs::exists(path)) GTEST_SKIP() << path << " is not here";
  const WorldMesh mesh = make_world_mesh(make_scene_view(load_world(path), 1.0f));
  const RayScene scene(mesh.positions, mesh.indices);
  const BakeDomain domain = BakeDomain::vertices(mesh);
  const PointRange subset{0, 300};  // the first 300 vertices: 1.2 M reference rays
  const BakeData bake = run_bake(scene, domain, {.rays = 256}, 1, subset);
  const BakeData reference = run_bake(scene, domain, {.rays = 4096}, 2, subset);
  size_t beyond = 0, occluded = 0;
  double mean_difference = 0.0, mean_variance = 0.0, mean_z2 = 0.0;
  for (size_t i = 0; i < subset.size(); ++i) {
    const double k = reference.visibility[i], d = bake.visibility[i] - k;
    const double variance = std::max(k * (1.0 - k), 1.0 / 4096.0) * (1.0 / 256 + 1.0 / 4096);
    beyond += std::fabs(d) > 3.0 * std::sqrt(variance);
    occluded += k < 0.95;
    mean_difference += d / subset.size();
    mean_variance += variance / subset.size();
    mean_z2 += d * d / variance / subset.size();
  }
  std::printf("bunny, %zu vertices: %zu beyond 3 sigma, mean difference %.2e (sigma of the mean %.2e), RMS z %.3f\n",
              size_t(subset.size()), beyond, mean_difference, std::sqrt(mean_variance / subset.size()),
              std::sqrt(mean_z2));
  EXPECT_LE(beyond, subset.size() / 100) << beyond << " vertices beyond 3 sigma";
  EXPECT_LT(std::fabs(mean_difference), 4.0 * std::sqrt(mean_variance / subset.size()));
  EXPECT_GT(occluded, subset.size() / 10);  // the bunny occludes itself: a real comparison
}

// An occlusion bake's rays pass through alpha-tested cut-outs (RayScene built with the view's
// materials, as `lumagraph bake` and occlusion.bake build it): in cut-out-quad.gltf, a 2 m quad
// at z = 0 whose middle metre is transparent in front of a wall at z = -1, the volume points
// between the hole and the wall see the sky through the hole. With the quad made opaque they see
// out only through the 1 m gap at the sides. Deterministic (same seed); the margin 0.1 is several
// times the Monte Carlo noise of the average (256 rays at each of 27 points: about 0.006).
// Measured: 0.430 through the hole, 0.290 behind the opaque quad.
TEST(Bake, RaysPassThroughAlphaCutOuts) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/gltf/cut-out-quad.gltf");
  auto behind_the_hole = [&]() {
    const SceneView view = make_scene_view(world, 1.0f);
    const WorldMesh mesh = make_world_mesh(view);
    const BakeDomain volume = BakeDomain::volume(mesh, {21, 21, 11});
    const BakeData data = run_bake(RayScene(mesh, view), volume, {.rays = 256}, 7, {0, volume.size()});
    double sum = 0.0;
    int count = 0;
    for (uint64_t i = 0; i < volume.size(); ++i) {
      const glm::vec3 p = volume.sample(i).point.position;
      if (std::abs(p.x) < 0.4f && std::abs(p.y) < 0.4f && p.z > -0.9f && p.z < -0.1f && data.valid[i] == 1.0f)
        sum += data.visibility[i], ++count;
    }
    EXPECT_EQ(count, 27);  // 3 x 3 x 3 grid points
    return sum / std::max(count, 1);
  };
  const double cut_out = behind_the_hole();
  for (size_t m = 0; m < world.materials().size(); ++m)
    if (world.materials()[m].name == "cut-out") world.edit_material(int(m)).alpha_mode = AlphaMode::opaque;
  const double opaque = behind_the_hole();
  std::printf("visibility behind the hole: %.3f, behind an opaque quad: %.3f\n", cut_out, opaque);
  EXPECT_GT(cut_out, opaque + 0.1);
}

}  // namespace
}  // namespace lg
