// The inspector on a live volume: selecting examples/gi-volume.json's gi.irradiance_volume node
// while the preview renders the Cornell box shows the probes the preview's runtime baked (the
// same, probe for probe, as `lumagraph bake --mode probes` of that scene and graph: one seed gives
// one bake), saves them as a bake the inspector opens, follows a dynamic volume's updates without
// edits, and says why there is nothing to show without a preview.
#include <gtest/gtest.h>

#include <QDockWidget>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "editor/document.h"
#include "editor/graph_edits.h"
#include "editor/inspector_widget.h"
#include "editor/main_window.h"
#include "editor/probe_view.h"
#include "editor/runtime_preview.h"
#include "qt_app.h"

namespace lg::editor {
namespace {

using lg::test::settle;

const char* const kGraph = LUMAGRAPH_SOURCE_DIR "/examples/gi-volume.json";
const char* const kScene = LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json";

class LiveVolumeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    lg::test::qt_app();
    window = std::make_unique<MainWindow>(false);
    window->show();
    // A copy, so that the editor's autosave of the edits lands beside it, not in examples/.
    graph_copy = dir.filePath("gi-volume.json");
    ASSERT_TRUE(QFile::copy(kGraph, graph_copy));
    ASSERT_TRUE(window->open_file(graph_copy));
    qobject_cast<QDockWidget*>(window->inspector()->parentWidget())->raise();
    settle();
  }
  // The preview's probes of the volume node, once a frame has baked them.
  std::shared_ptr<const ProbeSnapshot> wait_for_probes(int timeout_ms = 180'000) {
    std::shared_ptr<const ProbeSnapshot> live;
    EXPECT_TRUE(QTest::qWaitFor(
        [&] {
          const auto found = window->live_probes().find("volume");
          if (found != window->live_probes().end()) live = found->second;
          return live != nullptr;
        },
        timeout_ms));
    return live;
  }
  QString summary() const { return window->inspector()->summary(); }
  QTemporaryDir dir;
  QString graph_copy;
  std::unique_ptr<MainWindow> window;
};

TEST_F(LiveVolumeTest, WithoutAPreviewTheDockSaysHowToGetOne) {
  window->canvas()->select_nodes({"volume"});
  settle();
  EXPECT_TRUE(summary().contains("No preview is running")) << summary().toStdString();
  EXPECT_FALSE(window->inspector()->probe_state());
  EXPECT_FALSE(window->save_live_probes(QDir::temp().filePath("never.lgprobes")));
}

TEST_F(LiveVolumeTest, SelectingTheVolumeShowsTheProbesTheCommandLineBakes) {
  window->canvas()->select_nodes({"volume"});
  window->set_preview(std::make_unique<RuntimePreview>(kScene));
  const std::shared_ptr<const ProbeSnapshot> live = wait_for_probes();
  ASSERT_TRUE(live);
  settle();
  EXPECT_FALSE(live->dynamic);
  const std::optional<ProbeViewState> state = window->inspector()->probe_state();
  ASSERT_TRUE(state) << summary().toStdString();
  EXPECT_EQ(state->probes, 512u);  // the scene's 8 x 8 x 8
  EXPECT_EQ(state->volumes, 1u);
  EXPECT_TRUE(summary().contains("'volume' live in the preview")) << summary().toStdString();
  EXPECT_TRUE(summary().contains("cornell-box.json")) << summary().toStdString();

  const QString baked = dir.filePath("cornell.lgprobes");
  QProcess bake;
  bake.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph"),
             {"bake", kScene, "--mode", "probes", "--graph", graph_copy, "--out", baked});
  ASSERT_TRUE(bake.waitForFinished(120'000));
  ASSERT_EQ(bake.exitCode(), 0) << bake.readAllStandardError().toStdString();
  const ProbeFile file = read_probe_file(baked.toStdString());
  // The same settings, seed and transport: equal to the bit, no tolerance needed.
  EXPECT_EQ(live->file.header.settings.rays, file.header.settings.rays);
  EXPECT_EQ(live->file.header.settings.seed, file.header.settings.seed);
  EXPECT_EQ(live->file.header.geometry_hash, file.header.geometry_hash);
  ASSERT_EQ(live->file.probes.size(), file.probes.size());
  size_t active = 0;
  for (size_t p = 0; p < file.probes.size(); ++p) {
    const ProbeData &a = live->file.probes[p], &b = file.probes[p];
    active += a.active;
    EXPECT_EQ(a.active, b.active) << "probe " << p;
    for (size_t t = 0; t < a.irradiance.size(); ++t) {
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(a.irradiance[t][c])) << "probe " << p;
      ASSERT_EQ(a.irradiance[t], b.irradiance[t]) << "probe " << p << ", texel " << t;
    }
    ASSERT_EQ(a, b) << "probe " << p;
  }
  EXPECT_EQ(state->active, active);

  // Saved, the live probes open as a bake.
  const QString saved = dir.filePath("live.lgprobes");
  ASSERT_TRUE(window->save_live_probes(saved));
  const ProbeBake reopened = load_probe_bake(saved.toStdString());
  EXPECT_EQ(reopened.file.probes, live->file.probes);
  EXPECT_EQ(reopened.file.header.scene, kScene);
  InspectorWidget inspector;
  EXPECT_TRUE(inspector.open_probes(saved)) << inspector.summary().toStdString();

  // Moving a node renders again on the same executor: the probes did not change, so the frame
  // hands on the same snapshot, not a new copy (and nothing baked again). The first move's frame
  // may bake again: the dock widened for the probes, and the preview's size changed with it.
  const auto move_volume = [&](Position to) {
    const int shown = window->previews_shown();
    Graph moved = window->document()->graph();
    set_node_position(moved, "volume", to);
    window->document()->edit(std::move(moved), QStringLiteral("move"));
    EXPECT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() > shown; }, 60'000));
    return window->live_probes().at("volume");
  };
  const std::shared_ptr<const ProbeSnapshot> before = move_volume({300, -300});
  EXPECT_EQ(move_volume({320, -320}), before);
}

TEST_F(LiveVolumeTest, OnAWorldWithoutVolumesTheDockSaysTheNodeIsBypassed) {
  window->canvas()->select_nodes({"volume"});
  window->set_preview(std::make_unique<RuntimePreview>());  // the built-in world
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() >= 1; }, 60'000));
  settle();
  EXPECT_TRUE(window->live_probes().empty());
  EXPECT_TRUE(summary().contains("'volume' is bypassed in the preview's plan: the scene has no irradiance volumes"))
      << summary().toStdString();
}

TEST_F(LiveVolumeTest, ADynamicVolumeRefreshesAsItsUpdatesLandWithoutEdits) {
  Graph dynamic = window->document()->graph();
  set_param(dynamic, "volume", "mode", JsonValue("dynamic"));
  set_param(dynamic, "volume", "update_rays", JsonValue(32.0));  // quick batches
  window->document()->edit(std::move(dynamic), QStringLiteral("dynamic"));
  window->canvas()->select_nodes({"volume"});
  window->set_preview(std::make_unique<RuntimePreview>(kScene));
  const std::shared_ptr<const ProbeSnapshot> first = wait_for_probes();
  ASSERT_TRUE(first);
  EXPECT_TRUE(first->dynamic);
  settle();
  ASSERT_TRUE(window->inspector()->probe_state()) << summary().toStdString();
  const double exposure = window->inspector()->probe_state()->exposure;
  // No edit from here: the preview renders again by itself while the volume updates, and the
  // inspector follows.
  const QRegularExpression batches(QStringLiteral("dynamic: (\\d+) batches"));
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        const QRegularExpressionMatch m = batches.match(summary());
        return m.hasMatch() && m.captured(1).toInt() >= 3;
      },
      180'000))
      << summary().toStdString();
  const std::shared_ptr<const ProbeSnapshot> now = window->live_probes().at("volume");
  EXPECT_GT(now->version, first->version);
  EXPECT_NE(now->file.probes, first->file.probes);
  // A refresh keeps the display's exposure, so that the light converging shows as change.
  EXPECT_EQ(window->inspector()->probe_state()->exposure, exposure);
}

}  // namespace
}  // namespace lg::editor
