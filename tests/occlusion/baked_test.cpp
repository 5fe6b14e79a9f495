// occlusion.baked on lavapipe: bakes made at test time with the bake library (few rays, into the
// build folder), attached to the Stanford bunny by a scene file's "occlusion" key, drawn at
// 160x90 and compared pixel by pixel with the same bake interpolated on the CPU in double
// (baked_reference.h); the vertex bake against the camera-view ray-traced reference (printed and
// bounded); bakes that belong to other geometry refused at load with file, line and column;
// occlusion.baked feeding lighting.ibl with no validation message; a scene without bakes open
// everywhere with the drawing pass dropped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <sstream>

#include "api/renderer.h"
#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/occlusion/baked/baked_reference.h"
#include "nodes/occlusion/baked/occlusion_bake_reader.h"
#include "nodes/raytrace/ray_scene.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/occlusion/reference/scene_reference.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/scene_error.h"
#include "runtime/scene/scene_file.h"
#include "tests/occlusion/ao_render.h"
#include "tests/occlusion/occlusion_worlds.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kWidth = 160, kHeight = 90;
const std::string kBakedNode = R"({ "id": "ao", "type": "occlusion.baked" })";

fs::path shared_data() {
  return fs::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data";
}
fs::path bunny_obj() {
  return shared_data() / "mesh" / "bunny.obj";
}
fs::path test_dir() {
  const fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "baked-test";
  fs::create_directories(dir);
  return dir;
}

#define SKIP_WITHOUT_BUNNY() \
  if (!fs::exists(bunny_obj())) GTEST_SKIP() << bunny_obj() << " is missing"

struct BakeRequest {
  BakeMode mode = BakeMode::vertex;
  int rays = 64;
  float max_distance = std::numeric_limits<float>::infinity();
  uint32_t resolution = 0;   // texel: the lightmap's side; volume: points on the longest axis
  uint32_t chunk_count = 1;  // > 1: chunk 0 of this many
};

// What `lumagraph bake INPUT --out OUT` writes (the .lgbake alone), through the library.
void bake(const fs::path& input, const fs::path& out, const BakeRequest& request) {
  WorldLoadOptions options;
  options.asset_roots.roots = {test_dir().string(), shared_data().string()};
  const WorldMesh mesh = make_world_mesh(make_scene_view(load_world(input.string(), options), 1.0f));
  const BakeDomain domain = request.mode == BakeMode::vertex  ? BakeDomain::vertices(mesh)
                            : request.mode == BakeMode::texel ? BakeDomain::lightmap(mesh, request.resolution)
                                                              : BakeDomain::volume(mesh, {request.resolution, 0, 0});
  const OcclusionSettings settings{.rays = request.rays, .max_distance = request.max_distance};
  BakeFile file;
  file.header = make_bake_header(domain, mesh, input.string(), settings, 1, 0, request.chunk_count);
  if (request.mode == BakeMode::texel) file.lightmap_uvs = domain.lightmap_uvs();
  file.data = run_bake(RayScene(mesh.positions, mesh.indices), domain, settings, 1, file.header.range);
  write_bake_file(out.string(), file);
}

enum class BakeKey { entity, scene, none };

// examples/worlds/stanford-bunny.json with the bunny's model `model` and `bake` (in the test
// folder) as the bunny's "occlusion" (BakeKey::entity) or the file's own (BakeKey::scene);
// returns the scene file's path.
fs::path bunny_world(const std::string& name, const std::string& bake, const fs::path& model = bunny_obj(),
                     BakeKey key = BakeKey::entity) {
  const fs::path path = test_dir() / (name + ".json");
  const std::string entity_bake = key == BakeKey::entity ? R"(, "occlusion": ")" + bake + R"(")" : "";
  const std::string scene_bake = key == BakeKey::scene ? R"("occlusion": ")" + bake + R"(",)" : "";
  std::ofstream(path) << R"({
  "format": "lumagraph-world/1", )"
                      << scene_bake << R"(
  "materials": { "floor": {"base_color": [0.5, 0.5, 0.5], "roughness": 0.8},
                 "porcelain": {"base_color": [0.9, 0.88, 0.85], "roughness": 0.2} },
  "environment": {"intensity": 1},
  "entities": [
    {"name": "floor", "shape": {"type": "quad", "size": [4, 4]}, "material": "floor"},
    {"name": "bunny", "transform": {"position": [0.2, -0.33, 0], "scale": 10},
     "model": ")" << fs::relative(model, test_dir()).string()
                      << R"(", "material": "porcelain")" << entity_bake << R"(},
    {"name": "sun", "transform": {"position": [1, 3, 2], "look_at": [0, 0, 0]}, "directional_light": {"irradiance": 3}},
    {"name": "camera", "transform": {"position": [0, 1, 3], "look_at": [0, 0.6, 0]}, "camera": {"vertical_fov": 35}}
  ]
})";
  return path;
}

World load_with_bakes(const fs::path& scene) {
  WorldLoadOptions options;
  options.asset_roots.roots = {test_dir().string(), shared_data().string()};
  options.read_occlusion = read_occlusion_bake;
  return load_world(scene.string(), options);
}

std::string load_error(const fs::path& scene) {
  try {
    load_with_bakes(scene);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(loaded)";
}

// Which draw each of RayScene(view)'s primitives belongs to, by the draws' first triangles.
struct DrawOfPrimitive {
  std::vector<uint32_t> first_triangle;
  explicit DrawOfPrimitive(const SceneView& view) {
    uint32_t triangles = 0;
    for (const DrawItem& d : view.draws) {
      first_triangle.push_back(triangles);
      triangles += uint32_t(view.mesh_of(d).indices.size() / 3);
    }
  }
  size_t operator()(uint32_t primitive) const {
    return size_t(std::upper_bound(first_triangle.begin(), first_triangle.end(), primitive) - first_triangle.begin() -
                  1);
  }
};

// The mean absolute error against `reference` over the pixels whose primary ray hits the mesh
// named "bunny".
double bunny_pixels_mae(const AoRender& r, const AoImage& reference, size_t* pixels) {
  const RayScene scene(r.view);
  const CameraPixels camera(r.view.camera, kWidth, kHeight);
  const DrawOfPrimitive draw_of(r.view);
  double sum = 0;
  size_t n = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      const size_t i = size_t(y) * kWidth + x;
      const auto hit = scene.intersect(glm::vec3(camera.eye()), glm::vec3(camera.ray_direction(x, y)),
                                       std::numeric_limits<float>::infinity());
      if (!hit || std::isnan(reference.visibility[i])) continue;
      if (r.view.mesh_of(r.view.draws[draw_of(hit->primitive)]).name != "bunny") continue;
      sum += std::abs(r.last_ao[4 * i] - reference.visibility[i]);
      ++n;
    }
  *pixels = n;
  return n ? sum / n : 0.0;
}

struct RayTracedError {
  AoError all;
  double bunny_mae = 0;
};

// The rendered ao against 128-ray ray-traced AO of the whole scene (rays end at 0.5 m), over
// every pixel and over the bunny's alone, printed as `what`'s.
RayTracedError against_ray_tracing(const AoRender& r, const std::string& what) {
  const AoImage reference = trace_scene_reference(r.view, RayScene(r.view), {kWidth, kHeight},
                                                  AoSettings{.rays = 128, .max_distance = 0.5, .falloff_from = 1.0});
  RayTracedError out{error_against(reference, r.last_ao)};
  size_t bunny_pixels = 0;
  out.bunny_mae = bunny_pixels_mae(r, reference, &bunny_pixels);
  std::printf(
      "%s against ray tracing: MAE %.4f  p95 %.4f  max %.3f  bias %+.4f  (%zu pixels); on the bunny's pixels MAE "
      "%.4f (%zu pixels)\n",
      what.c_str(), out.all.mean_absolute, out.all.p95, out.all.max, out.all.mean_signed, out.all.pixels, out.bunny_mae,
      bunny_pixels);
  return out;
}

struct Comparison {
  size_t compared = 0, sky = 0;
  double ao_max = 0, bent_max = 0, cone_max = 0;
};

// Every other pixel whose primary ray (through the pixel centre, as the rasterizer samples)
// lands on a baked mesh where the G-buffer saw the same point: the rendered ao, bent normal and
// cone cosine against baked_occlusion_at() at the ray's hit. `edge_margin` skips hits whose
// smallest barycentric is below it (texel bakes change chart across a triangle edge, so a
// pixel on an edge may sample either).
Comparison compare_with_cpu(const AoRender& r, double edge_margin) {
  const SceneView& view = r.view;
  const RayScene scene(view);
  const CameraPixels camera(view.camera, kWidth, kHeight);
  const DrawOfPrimitive draw_of(view);
  Comparison c;
  for (uint32_t y = 0; y < kHeight; y += 2)
    for (uint32_t x = 0; x < kWidth; x += 2) {
      const size_t i = size_t(y) * kWidth + x;
      const double depth = r.gbuffer.depth[i];
      if (!(depth > 0.0)) {
        EXPECT_EQ(r.last_ao[4 * i], 1.0f);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(r.bent_normals[4 * i + k], 0.0f);
        ++c.sky;
        continue;
      }
      const glm::dvec3 dir = camera.ray_direction(x, y);
      const auto hit = scene.intersect(glm::vec3(camera.eye()), glm::vec3(dir), std::numeric_limits<float>::infinity());
      if (!hit) continue;
      const glm::dvec3 point = camera.eye() + dir * double(hit->distance);
      const glm::dvec3 seen =
          glm::dvec3(camera.world_from_view() * glm::dvec4(camera.view_position(x + 0.5, y + 0.5, depth), 1.0));
      if (glm::length(seen - point) > 1e-3 * hit->distance) continue;  // a silhouette: another surface
      const size_t draw = draw_of(hit->primitive);
      const MeshData& mesh = view.mesh_of(view.draws[draw]);
      if (!mesh.occlusion) continue;
      const auto corners = scene.triangle(hit->primitive);
      const glm::dvec3 bary =
          barycentric_of(point, {glm::dvec3(corners[0]), glm::dvec3(corners[1]), glm::dvec3(corners[2])});
      if (std::min({bary.x, bary.y, bary.z}) < edge_margin) continue;
      const BakedSample want = baked_occlusion_at(mesh, glm::dmat4(view.draws[draw].world),
                                                  hit->primitive - draw_of.first_triangle[draw], bary);
      c.ao_max = std::max(c.ao_max, std::abs(r.last_ao[4 * i] - want.ao));
      for (int k = 0; k < 3; ++k)
        c.bent_max = std::max(c.bent_max, std::abs(r.bent_normals[4 * i + k] - want.bent_normal[k]));
      c.cone_max = std::max(c.cone_max, std::abs(r.bent_normals[4 * i + 3] - want.cone_cos));
      ++c.compared;
    }
  return c;
}

// Tolerances of the GPU against the double interpolation of the same bake. ao passes through
// rgba16f (the drawing pass's target: rounding 2^-11 relative) and is stored in r8 (1/510 from
// rounding): 1/255 covers both with margin; float interpolation adds about 1e-6. The bent normal
// is stored in rgba8_snorm (1/254 from rounding), so 1/127. The cone cosine sqrt(1 - k_A) is
// steep near k_A = 1: a k_A error e moves it by up to sqrt(e), so with rgba16f's 2^-11 near 1 it
// may move by 0.022; 0.03 leaves margin for the snorm rounding.
constexpr double kAoTolerance = 1.0 / 255.0, kBentTolerance = 1.0 / 127.0, kConeTolerance = 0.03;

void expect_matches_cpu(const Comparison& c, const char* what) {
  std::printf("%s: %zu surface pixels compared, %zu sky; max |ao - cpu| %.5f, bent %.5f, cone %.5f\n", what, c.compared,
              c.sky, c.ao_max, c.bent_max, c.cone_max);
  EXPECT_GT(c.compared, 800u);
  EXPECT_GT(c.sky, 100u);
  EXPECT_LE(c.ao_max, kAoTolerance);
  EXPECT_LE(c.bent_max, kBentTolerance);
  EXPECT_LE(c.cone_max, kConeTolerance);
}

// (1) A vertex bake (64 rays, rays ending at 0.05 mesh units = 0.5 m at the world's scale of 10,
// as GTAO's radius in its accuracy test) matches its CPU interpolation, and against the
// ray-traced reference (128 rays, the same 0.5 m, a hit within it occluding fully) its error is
// printed for every pixel and for the bunny's alone. The bake does not see the floor (it is of
// the bunny alone), so the contact between them is where it errs: measured MAE 0.082 over all
// pixels and 0.077 over the bunny's; 0.10 bounds both with margin (GTAO "high" measures 0.036
// here at 1280x720).
TEST(BakedOcclusion, VertexBakeMatchesItsInterpolationAndRayTracing) {
  SKIP_WITHOUT_BUNNY();
  bake(bunny_obj(), test_dir() / "bunny-vertex.lgbake", {.mode = BakeMode::vertex, .rays = 64, .max_distance = 0.05f});
  const World world = load_with_bakes(bunny_world("bunny-vertex", "bunny-vertex.lgbake"));
  const AoRender r = render_occlusion(world, kWidth, kHeight, kBakedNode);
  EXPECT_EQ(r.validation_messages, 0u);
  expect_matches_cpu(compare_with_cpu(r, 0.0), "vertex bake");

  const RayTracedError e = against_ray_tracing(r, "vertex bake (64 rays)");
  EXPECT_LE(e.all.mean_absolute, 0.10);
  EXPECT_LE(e.bunny_mae, 0.10);

  // The same against a reference that traces only what the bake traced, the bunny: the primary
  // rays still hit what the frame shows (pixels whose ray misses the bunny stay out), only the
  // occlusion rays ignore the floor. This is the method's own error: interpolation across
  // triangles and 64-ray Monte Carlo noise.
  SceneView bunny_only = r.view;
  bunny_only.draws.erase(std::remove_if(bunny_only.draws.begin(), bunny_only.draws.end(),
                                        [&](const DrawItem& d) { return !r.view.mesh_of(d).occlusion; }),
                         bunny_only.draws.end());
  const AoImage own = trace_scene_reference(bunny_only, RayScene(bunny_only), {kWidth, kHeight},
                                            AoSettings{.rays = 128, .max_distance = 0.5, .falloff_from = 1.0});
  const AoError o = error_against(own, r.last_ao);
  std::printf("vertex bake against ray tracing of the bunny alone: MAE %.4f  p95 %.4f  bias %+.4f  (%zu pixels)\n",
              o.mean_absolute, o.p95, o.mean_signed, o.pixels);
}

// (2) A texel bake (a 512 lightmap: cells of 7 texels for the bunny's 4,968 triangles, 32 rays)
// matches its CPU bilinear lookup away from triangle edges.
TEST(BakedOcclusion, TexelBakeMatchesItsLightmapLookup) {
  SKIP_WITHOUT_BUNNY();
  bake(bunny_obj(), test_dir() / "bunny-texel.lgbake", {.mode = BakeMode::texel, .rays = 32, .resolution = 512});
  const World world = load_with_bakes(bunny_world("bunny-texel", "bunny-texel.lgbake"));
  const AoRender r = render_occlusion(world, kWidth, kHeight, kBakedNode);
  EXPECT_EQ(r.validation_messages, 0u);
  expect_matches_cpu(compare_with_cpu(r, 0.02), "texel bake");
}

// (3) Bakes that do not belong to the model: of another mesh (a triangle), of the same counts but
// other positions (the bunny with one vertex moved), of a volume, one chunk of a bake; and a
// world with a bake loaded by a program without a bake reader.
TEST(BakedOcclusion, BakeOfOtherGeometryIsRefusedAtLoad) {
  SKIP_WITHOUT_BUNNY();
  const fs::path triangle = test_dir() / "triangle.obj";
  std::ofstream(triangle) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  bake(triangle, test_dir() / "triangle.lgbake", {.mode = BakeMode::vertex, .rays = 4});
  std::string error = load_error(bunny_world("wrong-mesh", "triangle.lgbake"));
  const std::string scene = (test_dir() / "wrong-mesh.json").string();
  EXPECT_NE(error.find(scene + ":9:92: error: "), std::string::npos) << error;  // the "occlusion" value
  EXPECT_NE(error.find("'triangle.lgbake' for model '"), std::string::npos) << error;
  EXPECT_NE(error.find("bunny.obj'"), std::string::npos) << error;
  EXPECT_NE(error.find("1 mesh ('triangle' 3 vertices), but this draws 1 mesh ('bunny' 2503 vertices)"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("(/entities/1/occlusion)"), std::string::npos) << error;

  std::ifstream in(bunny_obj());
  std::stringstream moved;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (first && line.rfind("v ", 0) == 0) line = "v 0.5 0.5 0.5", first = false;
    moved << line << "\n";
  }
  const fs::path other = test_dir() / "bunny-moved.obj";
  std::ofstream(other) << moved.str();
  bake(other, test_dir() / "bunny-moved.lgbake", {.mode = BakeMode::vertex, .rays = 4});
  error = load_error(bunny_world("wrong-geometry", "bunny-moved.lgbake"));
  EXPECT_NE(error.find("bunny-moved.obj', whose geometry hash"), std::string::npos) << error;

  bake(bunny_obj(), test_dir() / "bunny-volume.lgbake", {.mode = BakeMode::volume, .rays = 4, .resolution = 4});
  error = load_error(bunny_world("volume", "bunny-volume.lgbake"));
  EXPECT_NE(error.find("is a volume bake"), std::string::npos) << error;
  EXPECT_NE(error.find("occlusion.bake node"), std::string::npos) << error;

  bake(bunny_obj(), test_dir() / "bunny-chunk.lgbake", {.mode = BakeMode::vertex, .rays = 4, .chunk_count = 2});
  error = load_error(bunny_world("chunk", "bunny-chunk.lgbake"));
  EXPECT_NE(error.find("is chunk 0 of 2; merge the chunks first"), std::string::npos) << error;

  WorldLoadOptions no_reader;
  no_reader.asset_roots.roots = {test_dir().string(), shared_data().string()};
  try {
    load_world((test_dir() / "volume.json").string(), no_reader);
    ADD_FAILURE() << "loaded without a bake reader";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("without an occlusion bake reader"), std::string::npos) << e.what();
  }
}

// The key's own errors, each at its place: no model or shape to apply to, not a bake's extension.
TEST(BakedOcclusion, TheSceneKeyIsChecked) {
  WorldLoadOptions options;
  options.read_occlusion = read_occlusion_bake;
  const std::string path = (test_dir() / "keys.json").string();
  auto error_of = [&](const std::string& entity) {
    try {
      parse_scene_file(R"({"format": "lumagraph-world/1", "entities": [)" + entity + "]}", path, {},
                       options.read_occlusion);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(loaded)");
  };
  EXPECT_EQ(error_of(R"({"occlusion": "a.lgbake"})"),
            path + ":1:60: error: 'occlusion' needs a 'model' or a 'shape' to apply to (/entities/0/occlusion)");
  EXPECT_NE(error_of(R"({"shape": {"type": "sphere"}, "occlusion": "a.vti"})").find("(/entities/0/occlusion)"),
            std::string::npos);
}

// (4) The example graph (occlusion.baked into lighting.ibl) on a baked bunny with Vulkan
// validation on: no message, a finite image, and the drawing pass ran.
TEST(BakedOcclusion, FeedsLightingIblWithoutValidationMessages) {
  SKIP_WITHOUT_BUNNY();
  bake(bunny_obj(), test_dir() / "bunny-lit.lgbake", {.mode = BakeMode::vertex, .rays = 16});
  const World world = load_with_bakes(bunny_world("bunny-lit", "bunny-lit.lgbake"));
  RendererOptions options;
  options.device.validation = true;
  Renderer renderer(options);
  renderer.load_graph(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/baked-occlusion.json");
  const FrameStats& stats = renderer.render(world, {kWidth, kHeight});
  EXPECT_TRUE(std::any_of(stats.passes.begin(), stats.passes.end(),
                          [](const PassStats& p) { return p.name == "baked/raster"; }));
  const std::vector<float> image = renderer.read_output();
  ASSERT_EQ(image.size(), size_t(kWidth) * kHeight * 4);
  EXPECT_TRUE(std::all_of(image.begin(), image.end(), [](float v) { return std::isfinite(v); }));
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
}

// (5) Without a baked mesh the plan drops the drawing pass (the scene summary's baked_occlusion)
// and every pixel is open: ao exactly 1; the bent normal is the G-buffer's, cone cosine 0.
TEST(BakedOcclusion, SceneWithoutBakesIsOpenEverywhere) {
  WorldBuilder b;
  b.add(make_quad(10.0f, 10.0f), {0.0f, 0.0f, 0.0f});
  b.add(make_box({1.0f, 1.0f, 1.0f}), {0.0f, 0.5f, -2.0f});
  b.camera({0.0f, 1.5f, 2.0f}, {0.0f, 0.3f, -2.0f});
  const AoRender r = render_occlusion(b.world(), 64, 48, kBakedNode);
  EXPECT_EQ(r.validation_messages, 0u);
  size_t surface = 0;
  for (size_t i = 0; i < size_t(64) * 48; ++i) {
    ASSERT_EQ(r.last_ao[4 * i], 1.0f) << i;
    EXPECT_EQ(r.bent_normals[4 * i + 3], 0.0f) << i;
    surface += r.gbuffer.depth[i] > 0.0f;
  }
  EXPECT_GT(surface, 1000u);
  Renderer renderer;
  renderer.set_graph(occlusion_graph(kBakedNode));
  const FrameStats& stats = renderer.render(b.world(), {64, 48});
  EXPECT_TRUE(
      std::none_of(stats.passes.begin(), stats.passes.end(), [](const PassStats& p) { return p.name == "ao/raster"; }));
  std::string why;
  for (const PlanNode& node : renderer.plan().nodes)
    for (const auto& [pass, reason] : node.dropped)
      if (node.id == "ao" && pass == "raster") why = reason;
  EXPECT_EQ(why, "no mesh in the scene carries baked occlusion");
}

// A bake of the whole scene file (the file's own "occlusion"), floor and bunny in world space:
// the lookup matches the CPU's (vertex and texel), and, since the bunny's bake now sees the
// floor and the floor's the bunny, the error against ray tracing of the whole scene falls below
// the bunny-alone bake's 0.082: measured 0.052 (vertex, 64 rays) and 0.058 (texel 512, 16 rays),
// bounded by 0.07. A 512 texel bake gives the floor's two triangles charts of 4 texels (the
// packing gives every triangle the same cell), 1 m each, so the contact on the floor stays
// blurred; the vertex bake has none on the floor (4 vertices).
TEST(BakedOcclusion, SceneBakeMatchesItsLookupAndSeesTheContact) {
  SKIP_WITHOUT_BUNNY();
  const fs::path input = bunny_world("scene-input", "", bunny_obj(), BakeKey::none);
  for (const BakeMode mode : {BakeMode::vertex, BakeMode::texel}) {
    const std::string name = std::string("scene-") + bake_mode_name(mode);
    bake(input, test_dir() / (name + ".lgbake"),
         {.mode = mode, .rays = mode == BakeMode::vertex ? 64 : 16, .max_distance = 0.5f, .resolution = 512});
    const World world = load_with_bakes(bunny_world(name, name + ".lgbake", bunny_obj(), BakeKey::scene));
    const AoRender r = render_occlusion(world, kWidth, kHeight, kBakedNode);
    EXPECT_EQ(r.validation_messages, 0u);
    expect_matches_cpu(compare_with_cpu(r, mode == BakeMode::texel ? 0.02 : 0.0), name.c_str());
    EXPECT_LE(against_ray_tracing(r, name).all.mean_absolute, 0.07);
  }

  // The bunny moved since the bake: the scene's geometry hash differs. And a world may not have
  // both a scene bake and an entity's.
  const fs::path moved = bunny_world("scene-moved", "scene-vertex.lgbake", bunny_obj(), BakeKey::scene);
  std::stringstream text;
  text << std::ifstream(moved).rdbuf();
  std::string edited = text.str();
  edited.replace(edited.find("0.2, -0.33, 0"), 13, "0.3, -0.33, 0");
  std::ofstream(moved) << edited;
  std::string error = load_error(moved);
  EXPECT_NE(error.find(moved.string() + ":2:"), std::string::npos) << error;
  EXPECT_NE(error.find("'scene-vertex.lgbake' for this scene file: "), std::string::npos) << error;
  EXPECT_NE(error.find("scene-input.json', whose geometry hash"), std::string::npos) << error;

  const fs::path both = bunny_world("scene-both", "scene-vertex.lgbake", bunny_obj(), BakeKey::scene);
  text.str("");
  text << std::ifstream(both).rdbuf();
  edited = text.str();
  edited.replace(edited.find(R"("material": "porcelain")"), 23,
                 R"("material": "porcelain", "occlusion": "bunny-own.lgbake")");
  std::ofstream(both) << edited;
  bake(bunny_obj(), test_dir() / "bunny-own.lgbake", {.mode = BakeMode::vertex, .rays = 4});
  error = load_error(both);
  EXPECT_NE(error.find("an entity has an 'occlusion' of its own"), std::string::npos) << error;
}

// The example world's committed bake (examples/worlds/bakes/bunny.lgbake, made by the command in
// docs/baking.md) still belongs to ../shared/data/mesh/bunny.obj: loading checks its hash.
TEST(BakedOcclusion, ExampleWorldLoadsWithItsBake) {
  SKIP_WITHOUT_BUNNY();
  const fs::path examples = fs::path(LUMAGRAPH_SOURCE_DIR) / "examples" / "worlds";
  WorldLoadOptions options;
  options.asset_roots.roots = {examples.string(), shared_data().string()};
  options.read_occlusion = read_occlusion_bake;
  const World world = load_world((examples / "stanford-bunny-baked.json").string(), options);
  const SceneView view = make_scene_view(world, 16.0f / 9.0f);
  EXPECT_TRUE(view.summary().baked_occlusion);
  size_t baked = 0;
  for (const auto& mesh : view.meshes)
    if (mesh->occlusion) {
      EXPECT_EQ(mesh->occlusion->kind, MeshOcclusion::Kind::vertex);
      EXPECT_EQ(mesh->occlusion->vertices.size(), mesh->positions.size());
      ++baked;
    }
  EXPECT_EQ(baked, 1u);
}

}  // namespace
}  // namespace lg::test
