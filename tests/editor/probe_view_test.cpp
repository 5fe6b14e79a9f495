// The inspector shows a probe bake made at test time (two boxes in a 4 x 3 x 4 volume under a
// uniform sky, through the probe library): the counts it reports are the file's, a click on a
// probe's sphere selects that probe and its maps beside the view are its stored texels, the
// slice moves and clamps, and broken or partial files say which file and why.
#include "editor/probe_view.h"

#include <gtest/gtest.h>

#include <QComboBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QTemporaryDir>
#include <set>

#include "editor/bake_legend.h"
#include "editor/inspector_widget.h"
#include "qt_app.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/world.h"

namespace lg {
namespace {

struct BakedProbes {
  QTemporaryDir dir;
  ProbeFile file;
  std::string path;

  BakedProbes() {
    World world;
    // A large box that swallows the probe at (0.5, 0, 0.5) whole (it stays off), and a thin one
    // whose face passes just beside the probe at (-0.5, 0, -0.5) (it moves out).
    for (const auto& [centre, size] : {std::pair{glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(1.6f)},
                                       std::pair{glm::vec3(-0.3f, 0.0f, -0.5f), glm::vec3(0.5f)}}) {
      Entity e = world.create();
      world.add(e, MeshRenderer{world.add_mesh(make_box(size)), -1});
      world.add(e, Transform{}).position = centre;
    }
    world.add(world.create(), Camera{});
    SceneView view = make_scene_view(world, 1.0f);
    IrradianceVolumeData volume;
    volume.size = {3, 2, 3};
    volume.probe_counts = {4, 3, 4};
    view.irradiance_volumes = {volume};
    const PathScene scene(std::move(view), PathEnvironment::image(Equirect{4, 2, std::vector<float>(32, 1.0f)}));
    ProbeGrid grid(scene.view().irradiance_volumes[0]);
    // 64 rays: enough to classify and relocate, and the bake takes milliseconds.
    const ProbeBakeSettings settings{.rays = 64, .bounces = 1, .seed = 1};
    bake_probes(scene, grid, settings, 0, grid.probe_count());
    file.header = make_probe_header({volume}, 0, 1);
    file.header.scene = "boxes";
    file.header.settings = settings;
    file.probes = grid.probes;
    path = dir.filePath("boxes.lgprobes").toStdString();
    write_probe_file(path, file);
  }
};

TEST(ProbeView, ShowsTheFilesProbesAndPicksOneByClick) {
  test::qt_app();
  const BakedProbes bake;
  size_t active = 0, moved = 0;
  for (const ProbeData& p : bake.file.probes) {
    active += p.active;
    moved += glm::length(p.offset) > 1e-6f;
  }
  ASSERT_LT(active, bake.file.probes.size()) << "the scene should leave a probe off";
  ASSERT_GT(moved, 0u) << "the scene should move a probe";

  InspectorWidget inspector;
  inspector.resize(1100, 820);
  inspector.show();
  ASSERT_TRUE(inspector.open_probes(QString::fromStdString(bake.path))) << inspector.summary().toStdString();
  test::settle();
  const std::optional<ProbeViewState> state = inspector.probe_state();
  ASSERT_TRUE(state);
  EXPECT_EQ(state->probes, 48u);
  EXPECT_EQ(state->active, active);
  EXPECT_EQ(state->relocated, moved);
  EXPECT_GT(state->slice_covered, 0u);
  EXPECT_TRUE(inspector.summary().contains(QStringLiteral("%1 on").arg(active))) << inspector.summary().toStdString();

  // The probe nearest the camera (which looks from +x +y +z), so no other sphere hides it.
  size_t nearest = 0;
  const ProbeGrid grid = probe_grids(bake.file)[0];
  for (size_t p = 0; p < grid.probe_count(); ++p) {
    auto depth = [&](size_t q) {
      const glm::dvec3 x = grid.grid_position(q) + glm::dvec3(grid.probes[q].offset);
      return x.x * 1.1 + x.y * 0.8 + x.z * 1.6;
    };
    if (grid.probes[p].active && depth(p) > depth(nearest)) nearest = p;
  }
  const std::optional<std::array<double, 2>> at = inspector.probe_display_point(nearest);
  ASSERT_TRUE(at);
  ASSERT_TRUE(inspector.select_probe_at(int(std::lround((*at)[0])), int(std::lround((*at)[1]))));
  EXPECT_EQ(inspector.probe_state()->selected, nearest);
  EXPECT_FALSE(inspector.select_probe_at(2, 2)) << "a corner of the view holds no probe";

  // The irradiance map beside the view shows the probe's stored texels, 28 screen pixels each.
  QLabel* map = nullptr;
  for (QLabel* label : inspector.findChildren<QLabel*>())
    if (!label->pixmap(Qt::ReturnByValue).isNull() && label->pixmap(Qt::ReturnByValue).width() == 168) {
      map = label;
      break;
    }
  ASSERT_NE(map, nullptr);
  const QImage shown = map->pixmap(Qt::ReturnByValue).toImage();
  for (int j = 0; j < kProbeIrradianceTexels; ++j)
    for (int i = 0; i < kProbeIrradianceTexels; ++i) {
      const glm::vec3 e = grid.probes[nearest].irradiance[size_t(j * kProbeIrradianceTexels + i)];
      EXPECT_EQ(qRed(shown.pixel(i * 28 + 14, j * 28 + 14)), display_byte(e.r, state->exposure)) << i << " " << j;
    }

  inspector.set_probe_slice(0);
  EXPECT_EQ(inspector.probe_state()->slice_height, 0.0);
  inspector.set_probe_slice(1000);
  EXPECT_EQ(inspector.probe_state()->slice, state->slices - 1);
  EXPECT_EQ(inspector.probe_state()->slice_height, 2.0);  // the top row of probes

  const QImage image = inspector.grab().toImage();
  std::set<QRgb> colours;
  for (int y = 0; y < image.height(); y += 4)
    for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
  EXPECT_GT(colours.size(), 100u) << "the view looks blank";
}

// Probes in memory, as the editor's live view hands them over: a bake of two volumes (the boxes'
// grid and a 2 x 2 x 2 one) shows the chooser, which switches volumes; showing the same source
// again (a live refresh) keeps the slice, the selected probe and the exposure, and the Save
// button is there only for live probes.
TEST(ProbeView, ChoosesAVolumeAndARefreshKeepsTheView) {
  test::qt_app();
  const BakedProbes bake;
  std::vector<ProbeGrid> grids = probe_grids(bake.file);
  IrradianceVolumeData small = bake.file.header.volumes[0];
  small.probe_counts = {2, 2, 2};
  ProbeGrid& second = grids.emplace_back(small);
  for (size_t p = 0; p < second.probe_count(); ++p) second.probes[p] = grids[0].probes[p];
  const ProbeFile two = whole_probe_file(grids, bake.file.header.settings);
  ASSERT_EQ(two.header.probes, 56u);
  EXPECT_EQ(probe_grids(two)[1].probes, second.probes);  // whole_probe_file undoes probe_grids

  auto in_memory = [&] {
    auto b = std::make_unique<ProbeBake>();
    b->path = "'volume' live in the preview";
    b->file = two;
    b->grids = probe_grids(two);
    return b;
  };
  InspectorWidget inspector;
  inspector.resize(1100, 820);
  inspector.show();
  ASSERT_TRUE(inspector.show_probes(in_memory(), 0, {true, "dynamic"}));
  test::settle();
  auto* chooser = inspector.findChild<QComboBox*>(QStringLiteral("probe_volume"));  // the slice bar has others
  ASSERT_TRUE(chooser);
  EXPECT_TRUE(chooser->isVisible());
  EXPECT_EQ(chooser->count(), 2);
  EXPECT_TRUE(inspector.summary().endsWith(" · dynamic")) << inspector.summary().toStdString();
  QPushButton* save = nullptr;
  for (QPushButton* b : inspector.findChildren<QPushButton*>())
    if (b->text().startsWith("Save probes")) save = b;
  ASSERT_TRUE(save);
  EXPECT_TRUE(save->isVisible());

  inspector.set_probe_slice(3);
  inspector.select_probe(5);
  const ProbeViewState before = *inspector.probe_state();
  ASSERT_TRUE(inspector.show_probes(in_memory(), 0, {true, "dynamic"}));
  const ProbeViewState after = *inspector.probe_state();
  EXPECT_EQ(after.slice, 3);
  EXPECT_EQ(after.selected, std::optional<size_t>(5));
  EXPECT_EQ(after.exposure, before.exposure);

  inspector.set_probe_volume(1);
  EXPECT_EQ(inspector.probe_state()->volume, 1u);
  EXPECT_EQ(inspector.probe_state()->counts, glm::ivec3(2));
  EXPECT_FALSE(inspector.probe_state()->selected) << "another volume starts afresh";

  ASSERT_TRUE(inspector.open_probes(QString::fromStdString(bake.path)));
  test::settle();
  EXPECT_FALSE(chooser->isVisible()) << "one volume needs no chooser";
  EXPECT_FALSE(save->isVisible()) << "a file is on disk already";
}

TEST(ProbeView, BrokenOrPartialBakesSayWhichFileAndWhy) {
  test::qt_app();
  const BakedProbes bake;
  InspectorWidget inspector;
  auto expect_refused = [&](const std::string& path, const char* why, int volume = 0) {
    EXPECT_FALSE(inspector.open_probes(QString::fromStdString(path), volume));
    EXPECT_FALSE(inspector.probe_state());
    EXPECT_TRUE(inspector.summary().contains(QString::fromStdString(path))) << inspector.summary().toStdString();
    EXPECT_TRUE(inspector.summary().contains(why)) << inspector.summary().toStdString();
  };
  expect_refused(bake.dir.filePath("missing.lgprobes").toStdString(), "no such file");
  expect_refused(bake.path, "no volume 2; the bake holds 1", 1);

  ProbeFile chunk = bake.file;
  chunk.header = make_probe_header(bake.file.header.volumes, 1, 2);
  chunk.probes.resize(chunk.header.range.size());
  const std::string chunk_path = bake.dir.filePath("chunk.lgprobes").toStdString();
  write_probe_file(chunk_path, chunk);
  expect_refused(chunk_path, "chunk 1 of 2 of a probe bake; merge the chunks first");

  const std::string truncated = bake.dir.filePath("truncated.lgprobes").toStdString();
  QFile::copy(QString::fromStdString(bake.path), QString::fromStdString(truncated));
  QFile(QString::fromStdString(truncated)).resize(100);
  EXPECT_FALSE(inspector.open_probes(QString::fromStdString(truncated)));
  EXPECT_TRUE(inspector.summary().contains(QString::fromStdString(truncated))) << inspector.summary().toStdString();
}

TEST(ProbeView, TheCommandShowsAProbeBake) {
  const BakedProbes bake;
  const QString png = bake.dir.filePath("probes.png");
  QProcess inspect;
  inspect.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph-inspect"),
                {"--bake", QString::fromStdString(bake.path), "--probe", "5", "--screenshot", png});
  ASSERT_TRUE(inspect.waitForFinished(60'000));
  EXPECT_EQ(inspect.exitCode(), 0) << inspect.readAllStandardError().toStdString();
  const QString summary = QString::fromUtf8(inspect.readAllStandardOutput());
  EXPECT_TRUE(summary.contains("volume 1 of 1, 4 x 3 x 4 probes")) << summary.toStdString();
  EXPECT_FALSE(QImage(png).isNull());
}

}  // namespace
}  // namespace lg
