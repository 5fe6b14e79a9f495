// The inspector shows a vertex bake of the bunny (baked at test time through the bake library,
// 8 rays a vertex) on its mesh: the colour range is the file's, and a bake opened with another
// mesh, or a volume bake given a mesh, is refused naming the file.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <algorithm>

#include "editor/inspector_widget.h"
#include "nodes/occlusion/bake/bake_file.h"
#include "qt_app.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg {
namespace {

const char* bunny = LUMAGRAPH_SOURCE_DIR "/../shared/data/mesh/bunny.obj";

TEST(VertexBakeView, ShowsTheBakeOnItsMeshAndRefusesAnotherMesh) {
  if (!QFile::exists(bunny)) GTEST_SKIP() << "test data missing: " << bunny;
  test::qt_app();
  QTemporaryDir dir;
  const WorldMesh mesh = make_world_mesh(make_scene_view(load_world(bunny), 1.0f));
  const BakeDomain domain = BakeDomain::vertices(mesh);
  const RayScene scene(mesh.positions, mesh.indices);
  BakeFile file;
  file.header = make_bake_header(domain, mesh, bunny, {.rays = 8}, 1, 0, 1);
  file.data = run_bake(scene, domain, {.rays = 8}, 1, file.header.range);
  const QString path = dir.filePath("bunny.lgbake");
  write_bake_file(path.toStdString(), file);

  InspectorWidget inspector;
  ASSERT_TRUE(inspector.open_vertex_bake(path, bunny)) << inspector.summary().toStdString();
  float low = 1, high = 0;
  for (size_t i = 0; i < file.data.size(); ++i)
    if (file.data.valid[i] > 0)
      low = std::min(low, file.data.visibility[i]), high = std::max(high, file.data.visibility[i]);
  ASSERT_TRUE(inspector.vertex_bake_range());
  EXPECT_DOUBLE_EQ((*inspector.vertex_bake_range())[0], low);
  EXPECT_DOUBLE_EQ((*inspector.vertex_bake_range())[1], high);
  EXPECT_LT(low, high) << "the bunny occludes itself: its visibility cannot be constant";
  EXPECT_TRUE(inspector.summary().contains("2503 vertices")) << inspector.summary().toStdString();

  // One triangle is not the bunny.
  const QString triangle = dir.filePath("triangle.obj");
  QFile obj(triangle);
  ASSERT_TRUE(obj.open(QIODevice::WriteOnly));
  obj.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  obj.close();
  EXPECT_FALSE(inspector.open_vertex_bake(path, triangle));
  EXPECT_FALSE(inspector.vertex_bake_range());
  EXPECT_TRUE(inspector.summary().startsWith(triangle)) << inspector.summary().toStdString();
  EXPECT_TRUE(inspector.summary().contains("not the geometry")) << inspector.summary().toStdString();

  EXPECT_FALSE(inspector.open_vertex_bake(path, dir.filePath("absent.obj")));
  EXPECT_TRUE(inspector.summary().contains("absent.obj")) << inspector.summary().toStdString();

  // A volume bake (4 points on the long axis, 1 ray: only its kind matters) given a mesh.
  const BakeDomain grid = BakeDomain::volume(mesh, {4, 0, 0});
  file.header = make_bake_header(grid, mesh, bunny, {.rays = 1}, 1, 0, 1);
  file.data = run_bake(scene, grid, {.rays = 1}, 1, file.header.range);
  const QString volume = dir.filePath("volume.lgbake");
  write_bake_file(volume.toStdString(), file);
  EXPECT_FALSE(inspector.open_vertex_bake(volume, bunny));
  EXPECT_TRUE(inspector.summary().startsWith(volume)) << inspector.summary().toStdString();
  EXPECT_TRUE(inspector.summary().contains("a volume bake, expected a vertex bake"))
      << inspector.summary().toStdString();
}

}  // namespace
}  // namespace lg
