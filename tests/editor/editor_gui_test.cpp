// The editor driven as a user would: open, add from the palette, link, refuse a bad link, edit a
// param, undo and redo, delete, copy and paste, move, and the preview seam.
#include <gtest/gtest.h>

#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QMouseEvent>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>
#include <nodes/FlowScene>
#include <nodes/FlowView>
#include <nodes/Node>
#include <atomic>
#include <set>
#include <thread>

#include "editor/compile_view.h"
#include "editor/runtime_preview.h"
#include "editor/document.h"
#include "editor/graph_edits.h"
#include "editor/inspector_widget.h"
#include "editor/main_window.h"
#include "editor/node_model.h"
#include "editor/palette.h"
#include "editor/param_panel.h"
#include "graph/graph_io.h"
#include "qt_app.h"

namespace lg::editor {
namespace {

using lg::test::settle;

QString example(const char* name) {
  return QStringLiteral(LUMAGRAPH_SOURCE_DIR "/examples/") + name;
}

class EditorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    lg::test::qt_app();
    window = std::make_unique<MainWindow>(false);
    window->show();
    ASSERT_TRUE(window->open_file(example("default.json")));
    settle();
  }
  const Graph& graph() const { return window->document()->graph(); }
  // Links two ports the way a finished drag on the canvas does.
  void drag_link(const std::string& from, int out, const std::string& to, int in) {
    Canvas* c = window->canvas();
    c->scene()->createConnection(*c->node(to), in, *c->node(from), out);
    settle();
  }
  const NodeModel* model(const std::string& id) const {
    return static_cast<const NodeModel*>(window->canvas()->node(id)->nodeDataModel());
  }
  std::unique_ptr<MainWindow> window;
};

TEST_F(EditorTest, OpensAnExampleWithEveryNodeLinkAndAPlan) {
  EXPECT_EQ(window->canvas()->scene()->nodes().size(), graph().nodes.size());
  EXPECT_EQ(window->canvas()->scene()->connections().size(), graph().links.size());
  ASSERT_TRUE(window->validation().plan);
  EXPECT_EQ(window->compile_view()->passes()->rowCount(), int(window->validation().plan->passes.size()));
  EXPECT_EQ(window->problems()->count(), 0);
  EXPECT_FALSE(window->document()->is_modified());
  EXPECT_TRUE(window->compile_view()->totals()->text().contains("with aliasing"));
}

TEST_F(EditorTest, TheCompileViewSaysWhatWasSkippedAndWhy) {
  ASSERT_TRUE(window->open_file(example("post.json")));
  QStringList skipped;
  for (int i = 0; i < window->compile_view()->skipped()->topLevelItemCount(); ++i)
    skipped << window->compile_view()->skipped()->topLevelItem(i)->text(0) + " / " +
                   window->compile_view()->skipped()->topLevelItem(i)->text(1);
  // The default scene's camera is a pinhole: depth of field has nothing to do.
  EXPECT_TRUE(skipped.join('\n').contains(QRegularExpression("bypassed: dof.*pinhole")))
      << skipped.join('\n').toStdString();
}

TEST_F(EditorTest, PaletteSearchAddsANodeThatShowsItsMissingInput) {
  window->palette()->set_filter("bloom");
  ASSERT_EQ(window->palette()->visible_types(), QStringList{"post.bloom"});
  emit window->palette()->add_requested("post.bloom");
  settle();
  ASSERT_TRUE(find_node(graph(), "bloom"));
  ASSERT_TRUE(window->canvas()->node("bloom"));
  EXPECT_TRUE(window->document()->is_modified());
  // Unlinked required input: an error on the node and in the list, which selects it.
  EXPECT_EQ(model("bloom")->validationState(), QtNodes::NodeValidationState::Error);
  QListWidgetItem* item = nullptr;
  for (int i = 0; i < window->problems()->count(); ++i)
    if (window->problems()->item(i)->data(Qt::UserRole).toString() == "bloom") item = window->problems()->item(i);
  ASSERT_TRUE(item);
  emit window->problems()->itemClicked(item);
  EXPECT_EQ(window->canvas()->selected_nodes(), std::set<std::string>{"bloom"});
}

TEST_F(EditorTest, LinkingCompatiblePortsIsOneUndoableStep) {
  emit window->palette()->add_requested("post.bloom");
  settle();
  drag_link("ibl", 0, "bloom", 0);  // texture2d:hdr -> texture2d:hdr
  EXPECT_TRUE(has_link(graph(), {"ibl", "color"}, {"bloom", "color"}));
  EXPECT_EQ(model("bloom")->validationState(), QtNodes::NodeValidationState::Valid);
  window->document()->undo_stack()->undo();
  settle();
  EXPECT_FALSE(has_link(graph(), {"ibl", "color"}, {"bloom", "color"}));
  EXPECT_EQ(window->canvas()->scene()->connections().size(), graph().links.size());
}

TEST_F(EditorTest, AnIncompatibleLinkIsRefusedSayingWhy) {
  emit window->palette()->add_requested("post.bloom");
  settle();
  const size_t links = graph().links.size();
  drag_link("tonemap", 0, "bloom", 0);  // texture2d:ldr into texture2d:hdr
  EXPECT_EQ(graph().links.size(), links);
  EXPECT_EQ(window->canvas()->scene()->connections().size(), links);
  const QString message = window->statusBar()->currentMessage();
  EXPECT_TRUE(message.contains("tonemap.color")) << message.toStdString();
  EXPECT_TRUE(message.contains("ldr")) << message.toStdString();
}

TEST_F(EditorTest, ParamEditsUndoAndRedo) {
  window->canvas()->select_nodes({"tonemap"});
  settle();
  ParamEditor* exposure = window->params()->editor("exposure");
  ASSERT_TRUE(exposure);
  auto* spin = exposure->findChild<QDoubleSpinBox*>();
  ASSERT_TRUE(spin);
  spin->setValue(1.5);
  spin->setValue(2.0);  // consecutive edits of one param are one step
  settle();
  EXPECT_EQ(*find_node(graph(), "tonemap")->params.find("exposure"), JsonValue(2.0));
  QUndoStack* undo = window->document()->undo_stack();
  EXPECT_EQ(undo->count(), 1);
  undo->undo();
  EXPECT_EQ(*find_node(graph(), "tonemap")->params.find("exposure"), JsonValue(-1.5));  // as in the file
  EXPECT_DOUBLE_EQ(spin->value(), -1.5);  // the panel follows the document
  undo->redo();
  EXPECT_EQ(*find_node(graph(), "tonemap")->params.find("exposure"), JsonValue(2.0));
  EXPECT_FALSE(window->validation().has_errors());
}

TEST_F(EditorTest, DeleteCopyAndPasteASelection) {
  window->canvas()->select_nodes({"sky", "sh"});
  EXPECT_EQ(window->canvas()->selected_nodes().size(), 2u);
  window->copy_selection();
  window->paste();
  settle();
  ASSERT_TRUE(find_node(graph(), "sky2"));
  EXPECT_TRUE(has_link(graph(), {"sky2", "cube"}, {"sh2", "env"}));
  EXPECT_EQ(window->canvas()->selected_nodes(), (std::set<std::string>{"sky2", "sh2"}));
  window->delete_selection();
  settle();
  EXPECT_FALSE(find_node(graph(), "sky2"));
  window->canvas()->select_nodes({"gtao"});
  window->delete_selection();
  settle();
  EXPECT_FALSE(find_node(graph(), "gtao"));
  EXPECT_FALSE(window->canvas()->node("gtao"));
  window->document()->undo_stack()->undo();
  settle();
  EXPECT_TRUE(window->canvas()->node("gtao"));
  EXPECT_TRUE(has_link(graph(), {"gtao", "ao"}, {"ibl", "ao"}));
}

TEST_F(EditorTest, KeyboardDeletesAndUndoes) {
  QApplication::setActiveWindow(window.get());
  window->canvas()->view()->setFocus();
  window->canvas()->select_nodes({"dfg"});
  QTest::keyClick(window->canvas()->view(), Qt::Key_Delete);
  settle();
  EXPECT_FALSE(find_node(graph(), "dfg"));
  QTest::keyClick(window->canvas()->view(), Qt::Key_Z, Qt::ControlModifier);
  settle();
  EXPECT_TRUE(find_node(graph(), "dfg"));
}

TEST_F(EditorTest, DraggingNodesIsRecordedOnRelease) {
  Canvas* c = window->canvas();
  c->scene()->setNodePosition(*c->node("dfg"), QPointF(333, 444));
  QMouseEvent release(QEvent::MouseButtonRelease, QPointF(5, 5), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
  QApplication::sendEvent(c->view()->viewport(), &release);
  settle();
  EXPECT_EQ(node_position(graph(), "dfg"), (Position{333, 444}));
  window->document()->undo_stack()->undo();
  settle();
  EXPECT_EQ(c->scene()->getNodePosition(*c->node("dfg")), QPointF(240, 380));
}

// Renders on the preview's worker thread: what it saw is read back after the image arrives.
class FlatPreview : public PreviewRenderer {
 public:
  QImage render(const Graph& graph, QSize size, QString*) override {
    nodes = graph.nodes.size();
    renderer_thread = std::this_thread::get_id();
    QImage image(size.expandedTo({16, 16}), QImage::Format_RGB32);
    image.fill(Qt::darkCyan);
    return image;
  }
  std::atomic<size_t> nodes = 0;
  std::thread::id renderer_thread;
};

TEST_F(EditorTest, APreviewRendererPlugsInAndFollowsEditsOffTheUiThread) {
  auto preview = std::make_unique<FlatPreview>();
  FlatPreview* p = preview.get();
  window->set_preview(std::move(preview));
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() >= 1; }, 10000));
  EXPECT_NE(p->renderer_thread, std::this_thread::get_id());
  const int shown = window->previews_shown();
  emit window->palette()->add_requested("env.sky");
  settle();
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() > shown; }, 10000));
  EXPECT_EQ(p->nodes, graph().nodes.size());
  EXPECT_FALSE(window->preview_image()->pixmap(Qt::ReturnByValue).isNull());
}

// The real preview: the default graph on the default world through the runtime (lavapipe), then
// again after a parameter edit. The image must show a scene, not a flat colour.
TEST_F(EditorTest, TheRuntimePreviewRendersTheDefaultGraph) {
  window->set_preview(std::make_unique<RuntimePreview>());
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() >= 1; }, 60000));
  QImage image = window->preview_image()->pixmap(Qt::ReturnByValue).toImage();
  ASSERT_FALSE(image.isNull()) << window->preview_image()->text().toStdString();
  std::set<QRgb> colours;
  for (int y = 0; y < image.height(); y += 4)
    for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
  EXPECT_GT(colours.size(), 50u) << "a rendered scene has many colours";
  const int shown = window->previews_shown();
  Graph edited = graph();  // the edit a slider makes
  set_param(edited, "tonemap", "exposure", JsonValue(-3.0));
  window->document()->edit(std::move(edited), QStringLiteral("exposure"), QStringLiteral("exposure"));
  settle();
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() > shown; }, 60000));
  QImage darker = window->preview_image()->pixmap(Qt::ReturnByValue).toImage();
  ASSERT_FALSE(darker.isNull());
  EXPECT_LT(qGray(darker.pixel(darker.width() / 2, darker.height() / 2)), qGray(image.pixel(image.width() / 2, image.height() / 2)));
}

TEST_F(EditorTest, TheMemoryTimelineDrawsThePlan) {
  auto* tabs = window->compile_view()->findChild<QTabWidget*>();
  ASSERT_TRUE(tabs);
  tabs->setCurrentIndex(1);
  settle();
  const QImage image = tabs->currentWidget()->grab().toImage();
  // Kept for people to look at; the test checks only that boxes were drawn.
  QDir().mkpath(LUMAGRAPH_BINARY_DIR "/test-output");
  image.save(LUMAGRAPH_BINARY_DIR "/test-output/editor-memory.png");
  std::set<QRgb> colours;
  for (int y = 0; y < image.height(); y += 3)
    for (int x = 0; x < image.width(); x += 3) colours.insert(image.pixel(x, y));
  EXPECT_GT(colours.size(), window->validation().plan->resources.size() / 2);
}

TEST_F(EditorTest, SelectingAnEnvLoadNodeInspectsItsFile) {
  const QString grace = QStringLiteral(LUMAGRAPH_SOURCE_DIR "/../shared/data/env/grace.hdr");
  if (!QFile::exists(grace)) GTEST_SKIP() << "test data missing: " << grace.toStdString();
  QTemporaryDir dir;
  ASSERT_TRUE(QFile::copy(grace, dir.filePath("grace.hdr")));
  Graph g;
  g.name = "probe";
  const std::string id = add_node(g, "env.load", {0, 0});
  set_param(g, id, "path", JsonValue("grace.hdr"));
  ASSERT_TRUE(save_graph_file(g, dir.filePath("probe.json").toStdString(), nullptr));
  ASSERT_TRUE(window->open_file(dir.filePath("probe.json")));
  qobject_cast<QDockWidget*>(window->inspector()->parentWidget())->raise();
  settle();
  window->canvas()->select_nodes({id});
  settle();
  EXPECT_TRUE(window->inspector()->summary().contains("grace.hdr")) << window->inspector()->summary().toStdString();
  EXPECT_TRUE(window->inspector()->summary().contains("L2 SH")) << window->inspector()->summary().toStdString();
}

}  // namespace
}  // namespace lg::editor
