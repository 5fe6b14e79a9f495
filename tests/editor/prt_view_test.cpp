// The inspector shows a PRT bake of the two spheres (baked at test time through the PRT library)
// on their mesh: an unshadowed bake has sky visibility 1 everywhere and each vertex's transfer
// function is the band-limited cosine lobe about its normal, known in closed form; a shadowed bake
// is darker where the spheres face each other; a click picks the vertex under it; a chunk, another
// mesh and a bake without --mesh are refused naming the file.
#include <gtest/gtest.h>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <glm/geometric.hpp>
#include <vector>

#include "editor/inspector_widget.h"
#include "editor/prt_view.h"
#include "nodes/env/common/sh_basis.h"
#include "qt_app.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg {
namespace {

const char* two_spheres = LUMAGRAPH_SOURCE_DIR "/examples/worlds/two-spheres.json";

QString bake(const QTemporaryDir& dir, const char* name, const PrtSettings& settings, uint32_t chunks = 1) {
  const PathScene scene(make_scene_view(load_world(two_spheres), 1.0f), PathEnvironment::none());
  PrtFile file;
  file.header = make_prt_header(scene.surfaces().mesh(), two_spheres, settings, 0, chunks);
  file.data = bake_transfer(scene, settings, file.header.range);
  const QString path = dir.filePath(name);
  write_prt_file(path.toStdString(), file);
  return path;
}

// The irradiance a unit light in direction w gives an open vertex, band-limited to `order`, at angle 0 to its normal.
double band_limited_cosine_peak(int order) {
  std::vector<double> bands;
  for (int l = 0; l <= order; ++l) bands.push_back(cosine_lobe_band(l));
  return sh_impulse_response(bands, 1.0);
}

TEST(PrtView, UnshadowedTransferIsTheBandLimitedCosineAndAClickPicksTheVertex) {
  test::qt_app();
  QTemporaryDir dir;
  const QString path = bake(dir, "open.lgprt", {.kind = TransferKind::unshadowed, .order = 3, .rays = 1, .bounces = 0});
  InspectorWidget inspector;
  inspector.resize(1100, 820);
  inspector.show();
  test::settle();
  ASSERT_TRUE(inspector.open_prt_bake(path, two_spheres)) << inspector.summary().toStdString();
  const PrtViewState state = *inspector.prt_state();
  EXPECT_EQ(state.invalid, 0u);
  // Exact transfer, stored as floats: 1 to float precision.
  EXPECT_NEAR(state.sky_visibility[0], 1.0, 1e-5);
  EXPECT_NEAR(state.sky_visibility[1], 1.0, 1e-5);
  EXPECT_TRUE(inspector.summary().contains("unshadowed transfer of order 3")) << inspector.summary().toStdString();

  const PrtBake file = load_prt_bake(path.toStdString(), two_spheres);
  const double peak = band_limited_cosine_peak(3);  // 1.0625 at order 2, nearer 1 as the order grows
  const glm::dvec3 toward_camera = glm::normalize(glm::dvec3(0.5, 0.4, 1.6));  // frame_bounds' offset
  size_t facing = 0;
  for (size_t v = 0; v < file.mesh.positions.size(); ++v) {
    EXPECT_NEAR(transfer_luminance(file, v, glm::dvec3(file.mesh.normals[v])), peak, 1e-4) << "vertex " << v;
    if (file.mesh.positions[v].x < 0 &&
        glm::dot(glm::dvec3(file.mesh.normals[v]), toward_camera) >
            glm::dot(glm::dvec3(file.mesh.normals[facing]), toward_camera))
      facing = v;
  }

  // A click on the left sphere's vertex that faces the camera selects it, and its sphere spans
  // the lobe: the peak (sampled on a 64 x 32 sphere, so within 3% below it) and the ringing below zero.
  const std::array<double, 2> at = *inspector.prt_vertex_display_point(facing);
  ASSERT_TRUE(inspector.select_prt_vertex_at(int(std::lround(at[0])), int(std::lround(at[1]))));
  const PrtViewState picked = *inspector.prt_state();
  ASSERT_TRUE(picked.selected);
  EXPECT_EQ(*picked.selected, facing);
  EXPECT_LE(picked.transfer_range[1], peak + 1e-5);
  EXPECT_GE(picked.transfer_range[1], 0.97 * peak);
  EXPECT_LT(picked.transfer_range[0], 0.0) << "an order-3 cosine lobe rings below zero behind the surface";
  EXPECT_FALSE(inspector.select_prt_vertex_at(2, 2)) << "the corner of the view is not on the mesh";
}

TEST(PrtView, ShadowedTransferIsDarkerWhereTheSpheresFaceEachOther) {
  test::qt_app();
  QTemporaryDir dir;
  const QString path = bake(dir, "shadowed.lgprt", {.kind = TransferKind::shadowed, .order = 2, .rays = 64, .bounces = 0});
  InspectorWidget inspector;
  ASSERT_TRUE(inspector.open_prt_bake(path, two_spheres)) << inspector.summary().toStdString();
  const PrtViewState state = *inspector.prt_state();
  // The vertices nearest the other sphere see it over about half their hemisphere; 64 stratified rays.
  EXPECT_LT(state.sky_visibility[0], 0.75);
  EXPECT_LE(state.sky_visibility[1], 1.0 + 1e-5);
  EXPECT_GT(state.sky_visibility[1], 0.95);
}

TEST(PrtView, RefusesAChunkAnotherMeshAndABakeWithoutItsMesh) {
  test::qt_app();
  QTemporaryDir dir;
  const PrtSettings open{.kind = TransferKind::unshadowed, .order = 2, .rays = 1, .bounces = 0};
  InspectorWidget inspector;
  const QString chunk = bake(dir, "chunk.lgprt", open, 2);
  EXPECT_FALSE(inspector.open_prt_bake(chunk, two_spheres));
  EXPECT_TRUE(inspector.summary().startsWith(chunk)) << inspector.summary().toStdString();
  EXPECT_TRUE(inspector.summary().contains("merge the chunks first")) << inspector.summary().toStdString();
  EXPECT_FALSE(inspector.prt_state());

  const QString whole = bake(dir, "whole.lgprt", open);
  const QString other = QStringLiteral(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  EXPECT_FALSE(inspector.open_prt_bake(whole, other));
  EXPECT_TRUE(inspector.summary().startsWith(other)) << inspector.summary().toStdString();
  EXPECT_TRUE(inspector.summary().contains("not the geometry")) << inspector.summary().toStdString();

  QProcess inspect;
  const QString png = dir.filePath("shot.png");
  inspect.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph-inspect"), {"--bake", whole, "--screenshot", png});
  ASSERT_TRUE(inspect.waitForFinished(60'000));
  EXPECT_EQ(inspect.exitCode(), 2);
  const QString err = QString::fromUtf8(inspect.readAllStandardError());
  EXPECT_TRUE(err.contains(whole + ": a PRT bake opens on the mesh or scene it was baked from: add --mesh MESH"))
      << err.toStdString();

  // A vertex the bake does not have is an error, not silently nothing.
  for (const char* bad : {"999999", "seven"}) {
    QProcess past;
    past.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph-inspect"),
               {"--bake", whole, "--mesh", two_spheres, "--vertex", bad, "--screenshot", png});
    ASSERT_TRUE(past.waitForFinished(60'000));
    EXPECT_EQ(past.exitCode(), 2) << bad;
    const QString said = QString::fromUtf8(past.readAllStandardError());
    EXPECT_TRUE(said.contains(QStringLiteral("--vertex %1: expected a vertex from 0 to 2449 (%2 has 2450)").arg(bad, whole)))
        << said.toStdString();
  }
}

}  // namespace
}  // namespace lg
