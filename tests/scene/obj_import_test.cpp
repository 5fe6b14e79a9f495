// OBJ import: the hand-written cube with its MTL, the Stanford bunny from ../shared/data
// (skipped with a message when absent), broken files, and load_world()'s defaults for a lone
// mesh. Tolerance on imported numbers: 1e-5.
#include <gtest/gtest.h>

#include <filesystem>
#include <glm/geometric.hpp>

#include "import_test_support.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_import.h"
#include "runtime/scene/mesh_tools.h"

namespace lg {
namespace {

using test::error_of;
using test::fixture;
using test::write_variant;

std::string bunny_path() {
  return std::string(LUMAGRAPH_SOURCE_DIR "/../shared/data/mesh/bunny.obj");
}

TEST(ObjImport, CubeWithMaterials) {
  World w;
  std::vector<Entity> made = import_obj(w, fixture("cube.obj"));
  ASSERT_EQ(made.size(), 2u);  // one mesh per material
  ASSERT_EQ(w.materials().size(), 2u);
  const PbrMaterial& shiny = w.materials()[0];
  const PbrMaterial& matte = w.materials()[1];
  EXPECT_EQ(shiny.name, "shiny");
  EXPECT_EQ(shiny.base_color, glm::vec4(0.8f, 0.1f, 0.1f, 1.0f));
  EXPECT_NEAR(shiny.roughness, std::pow(2.0f / 902.0f, 0.25f), 1e-5f);
  EXPECT_FLOAT_EQ(shiny.metalness, 1.0f);
  EXPECT_NEAR(matte.roughness, std::pow(0.5f, 0.25f), 1e-5f);
  EXPECT_FLOAT_EQ(matte.base_color.a, 0.5f);
  EXPECT_EQ(matte.emissive, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_FLOAT_EQ(matte.metalness, 0.0f);

  for (Entity e : made) {
    const MeshRenderer& r = w.get<MeshRenderer>(e);
    const MeshData& m = *w.meshes()[static_cast<size_t>(r.mesh)];
    EXPECT_EQ(mesh_problem(m), "");
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    if (r.material == 0) {  // the top face, normals from the file, uvs flipped to a top-left origin
      EXPECT_EQ(m.indices.size(), 6u);
      EXPECT_EQ(m.positions.size(), 4u);
      for (const auto& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
      EXPECT_EQ(m.uvs[0], glm::vec2(0, 1));  // vt 0 0
    } else {                                 // five faces, normals generated: each points away from the centre
      EXPECT_EQ(m.indices.size(), 30u);
      for (size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.0f);
      }
    }
  }
}

TEST(ObjImport, StanfordBunny) {
  if (!std::filesystem::exists(bunny_path())) GTEST_SKIP() << "no " << bunny_path() << " (../shared/data is absent)";
  World w;
  import_obj(w, bunny_path());
  ASSERT_EQ(w.meshes().size(), 1u);
  const MeshData& m = *w.meshes()[0];
  EXPECT_EQ(m.positions.size(), 2503u);
  EXPECT_EQ(m.indices.size(), 3u * 4968u);
  EXPECT_EQ(mesh_problem(m), "");
  EXPECT_TRUE(m.uvs.empty());
  for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
  Bounds b = transformed_bounds(m, glm::mat4(1.0f));
  EXPECT_NEAR(b.max.y - b.min.y, 0.15f, 0.02f);  // the bunny is about 15 cm tall
}

TEST(ObjImport, BrokenFilesGiveClearErrors) {
  World w;
  std::string path = write_variant("bad_index.obj", "o tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
  EXPECT_EQ(error_of([&] { import_obj(w, path); }),
            path + ":6:16: error: normal index 2 is beyond the file's 1 normal");
  path = write_variant("no_faces.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_EQ(error_of([&] { import_obj(w, path); }), path + ": error: the file has no triangles");
  path = write_variant("binary.obj", std::string("\x00\xff\x13garbage\n\x01", 12));
  EXPECT_EQ(error_of([&] { import_obj(w, path); }), path + ": error: the file has no triangles");
  EXPECT_EQ(error_of([&] { import_obj(w, fixture("nothing.obj")); }),
            fixture("nothing.obj") + ": error: the file does not exist");
}

TEST(ObjImport, MissingMaterialLibraryFallsBackToTheDefaultMaterial) {
  World w;
  std::string path =
      write_variant("no_mtl.obj", "mtllib nowhere.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::vector<Entity> made = import_obj(w, path);
  ASSERT_EQ(made.size(), 1u);
  EXPECT_EQ(w.get<MeshRenderer>(made[0]).material, -1);
}

TEST(LoadWorld, LoneMeshGetsCameraSunAndSky) {
  World w = load_world(fixture("cube.obj"));
  SceneView v = make_scene_view(w, 16.0f / 9.0f);
  SceneSummary s = v.summary();
  EXPECT_EQ(s.directional_lights, 1);
  EXPECT_TRUE(s.shadows);
  EXPECT_TRUE(s.environment);
  EXPECT_TRUE(v.environment.path.empty());
  // The cube's centre is in the middle of the screen and all its corners are on it.
  glm::mat4 vp = v.camera.projection * v.camera.view;
  glm::vec4 c = vp * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(c.x / c.w, 0.0f, 1e-5f);
  EXPECT_NEAR(c.y / c.w, 0.0f, 1e-5f);
  for (float x : {-0.5f, 0.5f})
    for (float y : {-0.5f, 0.5f})
      for (float z : {-0.5f, 0.5f}) {
        glm::vec4 p = vp * glm::vec4(x, y, z, 1);
        EXPECT_LT(std::abs(p.y / p.w), 1.0f);
        EXPECT_GT(p.z / p.w, 0.0f);
        EXPECT_LE(p.z / p.w, 1.0f);
      }
}

TEST(LoadWorld, GltfKeepsItsOwnCameraAndLights) {
  World w = load_world(fixture("scene.gltf"));
  SceneView v = make_scene_view(w, 1.0f);
  EXPECT_EQ(w.count<Camera>(), 1u);
  EXPECT_EQ(v.directional_lights.size(), 1u);  // the file's sun, no extra one
  EXPECT_TRUE(v.has_environment);
}

TEST(LoadWorld, UnknownExtension) {
  EXPECT_EQ(error_of([] { load_world("world.fbx"); }),
            "world.fbx: error: unknown kind of world file '.fbx'; expected .json, .gltf, .glb or .obj");
}

}  // namespace
}  // namespace lg
