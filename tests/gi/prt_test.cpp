// Precomputed radiance transfer on the CPU: SH rotation against rotating an environment map and
// projecting it again; the baked transfer of a lone sphere against the exact cosine lobe; a
// degenerate mesh; chunks merging bit-identically; the .lgprt reader refusing damaged files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <random>

#include "nodes/env/common/cube_map.h"
#include "nodes/env/common/sh_basis.h"
#include "nodes/env/common/sh_rotation.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "nodes/gi/prt/prt_file.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ray_test_scenes.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using test::scene_of;

glm::dmat3 random_rotation_matrix(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi), axis(-1.0, 1.0);
  glm::dvec3 a(axis(rng), axis(rng), axis(rng));
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), angle(rng), glm::normalize(a + glm::dvec3(0.0, 0.0, 1e-3))));
}

// The band-4 basis at R^T w, from the turned coefficients: for any coefficients c and direction
// w, sum_k (M c)_k Y_k(w) = sum_k c_k Y_k(R^T w). Exact up to rounding (1e-10 of the
// coefficients' size).
TEST(ShRotation, TurnsEveryBandExactly) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 4; ++trial) {
    const glm::dmat3 r = random_rotation_matrix(rng);
    const ShRotation turn = sh_rotation(4, r);
    std::vector<glm::dvec3> c(25), turned(25);
    for (auto& v : c) v = {normal(rng), normal(rng), normal(rng)};
    turn.apply(c, turned);
    for (int d = 0; d < 20; ++d) {
      const glm::dvec3 w = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
      const glm::dvec3 expected = evaluate_sh(c, glm::transpose(r) * w), got = evaluate_sh(turned, w);
      for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], expected[ch], 1e-10) << trial << " " << d;
    }
  }
}

// A smooth environment (three random exponential lobes) on a 64^2 cube, and the same
// environment turned by R (each texel holds f(R^T w) at its centre), both projected by
// env.sh_project's reference to order 4: turning the first projection's coefficients must give
// the second's. The two maps sample f at different points, so their projections differ by the
// texel discretisation: measured 2e-5 of the coefficient vector's norm at 64^2 (the check is
// run at 16^2 too: 3e-4, shrinking with the texel area as a discretisation error does);
// required 1e-3. A wrong rotation (an inverse, a band off) is off by the coefficients' own size.
TEST(ShRotation, MatchesRotatingTheEnvironmentMapAndProjectingAgain) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  struct Lobe {
    glm::dvec3 axis, color;
    double sharpness;
  };
  std::vector<Lobe> lobes;
  for (int i = 0; i < 3; ++i)
    lobes.push_back({glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng))),
                     {0.5 + std::abs(normal(rng)), 0.5 + std::abs(normal(rng)), 0.5 + std::abs(normal(rng))},
                     1.0 + 3.0 * std::abs(normal(rng))});
  const auto radiance = [&](glm::dvec3 w) {
    glm::dvec3 sum(0.1);
    for (const Lobe& l : lobes) sum += l.color * std::exp(l.sharpness * (glm::dot(w, l.axis) - 1.0));
    return sum;
  };
  const glm::dmat3 r = random_rotation_matrix(rng);
  constexpr uint32_t kFace = 64;
  CubeImage original(kFace), turned(kFace);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < kFace; ++j)
      for (uint32_t i = 0; i < kFace; ++i) {
        const glm::dvec3 w = glm::normalize(original.direction(f, i, j));
        original.at(f, i, j) = glm::dvec4(radiance(w), 1.0);
        turned.at(f, i, j) = glm::dvec4(radiance(glm::transpose(r) * w), 1.0);
      }
  const std::vector<double> none(5, 1.0);
  const std::vector<glm::dvec3> c = project_sh_reference(original, 4, none).coefficients;
  const std::vector<glm::dvec3> expected = project_sh_reference(turned, 4, none).coefficients;
  std::vector<glm::dvec3> got(c.size());
  sh_rotation(4, r).apply(c, got);
  double norm = 0, error = 0;
  for (size_t k = 0; k < c.size(); ++k) {
    norm += glm::dot(expected[k], expected[k]);
    error += glm::dot(got[k] - expected[k], got[k] - expected[k]);
  }
  std::printf("rotated coefficients against the turned map's: %.3g of the norm\n", std::sqrt(error / norm));
  EXPECT_LT(std::sqrt(error / norm), 1e-3);
}

// A lone sphere is convex: nothing shadows it, so its shadowed transfer is the unshadowed one,
// cosine_lobe_band(l) Y_k(n), up to the Monte Carlo error of 1,024 stratified rays. A constant
// environment L = 1 (L_00 = 2 sqrt(pi)) then gives E = pi from the unshadowed transfer. Per
// coefficient the shadowed transfer is within 0.02 of the exact one (whose band-0 value is
// sqrt(pi)/2 = 0.886): the worst of 25 coefficients over the vertices measured 0.0122 at 1,024
// rays and 0.0034 at 4,096, falling as stratified Monte Carlo error does (no bias beneath it).
TEST(PrtBake, ShadowedTransferOfAConvexMeshIsTheCosineLobe) {
  const PathScene scene(scene_of({{make_sphere(1.0f, 16, 8), glm::mat4(1.0f)}}), PathEnvironment::none());
  const uint64_t vertices = scene.surfaces().mesh().positions.size();
  PrtSettings s{.kind = TransferKind::unshadowed, .order = 4, .rays = 1024, .bounces = 0, .seed = 3};
  const PrtData exact = bake_transfer(scene, s, {0, vertices});
  s.kind = TransferKind::shadowed;
  const PrtData traced = bake_transfer(scene, s, {0, vertices});
  const int floats = prt_vertex_floats(4);
  double worst = 0;
  for (uint64_t v = 0; v < vertices; ++v) {
    ASSERT_EQ(exact.valid[v], 1.0f);
    ASSERT_EQ(traced.valid[v], 1.0f);
    EXPECT_NEAR(exact.transfer[v * floats] * 2.0 * std::sqrt(std::numbers::pi), std::numbers::pi, 1e-5);
    for (int f = 0; f < floats; ++f)
      worst = std::max(worst, double(std::abs(exact.transfer[v * floats + f] - traced.transfer[v * floats + f])));
  }
  std::printf("shadowed against unshadowed transfer on a sphere: at most %.4f a coefficient\n", worst);
  EXPECT_LT(worst, 0.02);
}

// A sphere inside a closed box sees nothing of the environment: shadowed transfer 0; with
// bounces the light still cannot get in (0 too). A zero-area triangle and a vertex without a
// normal bake without NaN: the latter invalid with transfer 0.
TEST(PrtBake, ClosedAndDegenerateGeometryStaysFinite) {
  MeshData sliver = make_quad(1.0f, 1.0f);
  sliver.positions[1] = sliver.positions[0];  // a zero-area triangle
  sliver.normals[2] = glm::vec3(0.0f);        // no normal
  const PathScene scene(scene_of({{make_sphere(0.3f, 12, 6), glm::mat4(1.0f)},
                                  {make_box(glm::vec3(2.0f)), glm::mat4(1.0f)},
                                  {std::move(sliver), glm::mat4(1.0f)}}),
                        PathEnvironment::none());
  const WorldMesh& mesh = scene.surfaces().mesh();
  for (TransferKind kind : {TransferKind::shadowed, TransferKind::interreflected}) {
    const PrtSettings s{.kind = kind, .order = 3, .rays = 64, .bounces = kind == TransferKind::shadowed ? 0u : 3u};
    const PrtData d = bake_transfer(scene, s, {0, mesh.positions.size()});
    const int floats = prt_vertex_floats(3);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      for (int f = 0; f < floats; ++f) ASSERT_TRUE(std::isfinite(d.transfer[v * floats + f])) << v;
      if (v >= mesh.parts[0].vertex_count) continue;
      for (int f = 0; f < floats; ++f) EXPECT_EQ(d.transfer[v * floats + f], 0.0f) << "inside the box, vertex " << v;
    }
    const size_t no_normal = mesh.parts[2].first_vertex + 2;
    EXPECT_EQ(d.valid[no_normal], 0.0f);
    for (int f = 0; f < floats; ++f) EXPECT_EQ(d.transfer[no_normal * floats + f], 0.0f);
  }
}

PathScene two_spheres() {
  return PathScene(scene_of({{make_sphere(0.5f, 12, 6), glm::translate(glm::mat4(1.0f), {-0.52f, 0.0f, 0.0f})},
                             {make_sphere(0.5f, 12, 6), glm::translate(glm::mat4(1.0f), {0.52f, 0.0f, 0.0f})}}),
                   PathEnvironment::none());
}

PrtFile bake_file(const PathScene& scene, const PrtSettings& s, uint32_t index, uint32_t count) {
  PrtFile file;
  file.header = make_prt_header(scene.surfaces().mesh(), "two-spheres", s, index, count);
  file.data = bake_transfer(scene, s, file.header.range);
  return file;
}

// Three chunks, merged in another order, are byte for byte the whole bake's file; the merge
// refuses a missing chunk and a part of another bake, naming the file.
TEST(PrtFile, ChunksMergeBitIdentically) {
  const PathScene scene = two_spheres();
  const PrtSettings s{.kind = TransferKind::interreflected, .order = 2, .rays = 32, .bounces = 2, .seed = 9};
  const std::string whole = encode_prt_file(bake_file(scene, s, 0, 1));
  const fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "prt-test";
  fs::create_directories(dir);
  std::vector<std::string> paths;
  for (uint32_t i : {2u, 0u, 1u}) {
    paths.push_back((dir / ("part" + std::to_string(i) + ".lgprt")).string());
    write_prt_file(paths.back(), bake_file(scene, s, i, 3));
  }
  std::vector<PrtFile> parts;
  for (const std::string& p : paths) parts.push_back(read_prt_file(p));
  EXPECT_TRUE(encode_prt_file(merge_prt_parts(parts, paths)) == whole);
  EXPECT_THROW(merge_prt_parts({parts[0], parts[1]}, {paths[0], paths[1]}), BakeFileError);
  PrtSettings other = s;
  other.seed = 10;
  parts[1] = bake_file(scene, other, 0, 3);
  try {
    merge_prt_parts(parts, paths);
    FAIL() << "a part of another bake was merged";
  } catch (const BakeFileError& e) {
    EXPECT_NE(std::string(e.what()).find(paths[1]), std::string::npos) << e.what();
  }
}

// Damaged files are refused with a BakeFileError that names the file and what is wrong.
TEST(PrtFile, ReaderRefusesDamagedFiles) {
  const PathScene scene = two_spheres();
  const PrtSettings s{.kind = TransferKind::shadowed, .order = 2, .rays = 8, .bounces = 0, .seed = 1};
  const PrtFile file = bake_file(scene, s, 0, 1);
  const std::string good = encode_prt_file(file);
  const fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "prt-test";
  fs::create_directories(dir);
  const std::string path = (dir / "damaged.lgprt").string();
  const auto refused = [&](const std::string& bytes, const std::string& expected) {
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      read_prt_file(path);
      ADD_FAILURE() << "accepted a file that should fail with: " << expected;
    } catch (const BakeFileError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
  };
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string bytes = good;
    const size_t at = bytes.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return bytes.replace(at, from.size(), to);
  };
  refused(good.substr(0, good.size() - 4), "truncated");
  refused("LGBAKE01" + good.substr(8), "not a PRT bake");
  // (Edits keep the header's length, which the file states.)
  refused(replaced("\"order\": 2", "\"order\": 5"), "\"order\"");
  refused(replaced("\"order\": 2", "\"order\": 1"), "order 1 is not 2 to 4");
  refused(replaced("\"shadowed\"", "\"shadowex\""), "is not unshadowed, shadowed or interreflected");
  refused(replaced("\"bounces\": 0", "\"bounces\": 3"), "has no bounces");
  const std::string count = std::to_string(file.header.vertices);
  refused(replaced("\"vertices\": " + count, "\"vertices\": " + std::string(count.size(), '9')), "the parts hold");
  std::string nan = good;
  const float not_a_number = NAN;
  std::memcpy(nan.data() + nan.size() - (file.data.valid.size() + 3) * sizeof(float), &not_a_number, sizeof(float));
  refused(nan, "non-finite");
  std::string invalid = good;
  const float two = 2.0f;
  std::memcpy(invalid.data() + invalid.size() - sizeof(float), &two, sizeof(float));
  refused(invalid, "valid must be 0 or 1");
}

}  // namespace
}  // namespace lg
