// The editor driven as a user would: open, add from the palette, link, refuse a bad link, edit a
// param, undo and redo, delete, copy and paste, move, and the preview: the seam, the runtime's
// image of the main output and of any port, exposure, channel and the pixel read-out.
#include <gtest/gtest.h>

#include <QComboBox>
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
#include <algorithm>
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
#include "editor/preview_panel.h"
#include "api/renderer.h"
#include "runtime/scene/default_world.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"
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

// A node whose schema lists presets shows them in a combo above its params; choosing one sets
// every param it names as one undoable step, and the combo follows the document both ways.
TEST_F(EditorTest, APresetSetsItsParamsAsOneUndoableEdit) {
  ASSERT_TRUE(window->open_file(example("post.json")));
  settle();
  window->canvas()->select_nodes({"dof"});
  settle();
  QComboBox* presets = window->params()->presets();
  ASSERT_TRUE(presets);
  const NodeSchema* schema = builtin_registry().find("post.dof");
  ASSERT_EQ(presets->count(), int(schema->presets.size()) + 1);
  const JsonValue before = find_node(graph(), "dof")->params;
  const int shown = presets->currentIndex();
  EXPECT_EQ(shown, matching_preset(*find_node(graph(), "dof"), *schema) + 1);
  const int chosen = shown == 1 ? 2 : 1;
  emit presets->activated(chosen);  // as a click on the item does
  settle();
  for (const auto& [param, value] : schema->presets[chosen - 1].values)
    EXPECT_EQ(*find_node(graph(), "dof")->params.find(schema->params[param].name), value);
  EXPECT_EQ(presets->currentIndex(), chosen);
  QUndoStack* undo = window->document()->undo_stack();
  EXPECT_EQ(undo->count(), 1);
  undo->undo();
  settle();
  EXPECT_EQ(find_node(graph(), "dof")->params, before);
  EXPECT_EQ(window->params()->presets()->currentIndex(), shown);
  undo->redo();
  settle();
  EXPECT_EQ(window->params()->presets()->currentIndex(), chosen);
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
  PreviewImage render(const Graph& graph, QSize size, const PreviewPort&, QString*) override {
    nodes = graph.nodes.size();
    renderer_thread = std::this_thread::get_id();
    PreviewImage image;
    image.width = size.width(), image.height = size.height(), image.encoding = PreviewEncoding::display;
    image.rgba.assign(size_t(size.width()) * size.height() * 4, 0.5f);
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
  // The compile view shows the preview frame's GPU times; after an edit downstream of the
  // environment its static passes came across from the last plan.
  QTableWidget* passes = window->compile_view()->passes();
  for (int row = 0; row < passes->rowCount(); ++row) {
    const QString pass = passes->item(row, 0)->text(), time = passes->item(row, 4)->text();
    if (passes->item(row, 3)->text() == QStringLiteral("static"))
      EXPECT_EQ(time, QStringLiteral("cached")) << pass.toStdString();
    else
      EXPECT_GE(time.toDouble(), 0.0) << pass.toStdString() << ": '" << time.toStdString() << "'";
    EXPECT_FALSE(time.isEmpty()) << pass.toStdString();
  }
}

// A chosen scene instead of the built-in world: the gallery renders, and differently.
TEST_F(EditorTest, TheRuntimePreviewRendersAChosenScene) {
  window->set_preview(std::make_unique<RuntimePreview>());
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() >= 1; }, 60000));
  const QImage built_in = window->preview_image()->pixmap(Qt::ReturnByValue).toImage();
  const int shown = window->previews_shown();
  window->set_preview(std::make_unique<RuntimePreview>(LUMAGRAPH_SOURCE_DIR "/examples/worlds/gallery.json"));
  ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() > shown; }, 60000));
  const QImage gallery = window->preview_image()->pixmap(Qt::ReturnByValue).toImage();
  ASSERT_FALSE(gallery.isNull()) << window->preview_image()->text().toStdString();
  EXPECT_NE(gallery, built_in);
}

// Validation and the compile view compile for the scene the preview renders: post.json's depth
// of field is bypassed for the built-in world's pinhole camera and runs for the gallery's thin
// lens, as the preview does.
TEST_F(EditorTest, ValidationCompilesForThePreviewsScene) {
  ASSERT_TRUE(window->open_file(QStringLiteral(LUMAGRAPH_SOURCE_DIR "/examples/post.json")));
  const auto dof_state = [&] {
    const Plan& plan = *window->validation().plan;
    const auto dof =
        std::find_if(plan.nodes.begin(), plan.nodes.end(), [](const PlanNode& n) { return n.id == "dof"; });
    return dof == plan.nodes.end() ? "missing" : node_state_name(dof->state);
  };
  ASSERT_TRUE(window->validation().plan);
  EXPECT_EQ(dof_state(), "bypassed");
  window->set_preview(std::make_unique<RuntimePreview>(LUMAGRAPH_SOURCE_DIR "/examples/worlds/gallery.json"));
  ASSERT_TRUE(window->validation().plan);
  EXPECT_EQ(window->validation().plan->scene, "gallery");
  EXPECT_EQ(dof_state(), "active");
  window->set_preview(std::make_unique<RuntimePreview>());
  EXPECT_EQ(dof_state(), "bypassed");
}

// The real preview of ports other than the main output (tests below share it).
class PortPreviewTest : public EditorTest {
 protected:
  void SetUp() override {
    EditorTest::SetUp();
    window->set_preview(std::make_unique<RuntimePreview>());
    ASSERT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() >= 1; }, 60000));
  }
  // Chooses a port in the combo box and waits for its image.
  const PreviewImage& show_port(const QString& name) {
    const int shown = window->previews_shown();
    window->preview()->choose_port(name);
    EXPECT_TRUE(QTest::qWaitFor([&] { return window->previews_shown() > shown; }, 60000));
    EXPECT_EQ(window->preview()->port().name, name == "main output" ? "" : name.toStdString());
    return window->preview()->image();
  }
  QImage shown() const { return window->preview_image()->pixmap(Qt::ReturnByValue).toImage(); }
};

double mean_grey(const QImage& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) sum += qGray(image.pixel(x, y));
  return sum / (double(image.width()) * image.height());
}

TEST_F(PortPreviewTest, ListsEveryPortAndShowsTheChosenOne) {
  auto* box = window->preview()->findChild<QComboBox*>();
  ASSERT_TRUE(box);
  QStringList items;
  for (int i = 0; i < box->count(); ++i) items << box->itemText(i);
  for (const char* port : {"main output", "gbuf.gbuffer.normal", "gbuf.gbuffer.depth", "light.color", "sh.sh", "sky.cube"})
    EXPECT_TRUE(items.contains(port)) << port;
  ASSERT_FALSE(show_port("gbuf.gbuffer.normal").empty()) << window->preview_image()->text().toStdString();
  const QImage normal = shown();
  ASSERT_FALSE(show_port("main output").empty()) << window->preview_image()->text().toStdString();
  const QImage main = shown();
  ASSERT_EQ(normal.size(), main.size());
  int differ = 0;
  for (int y = 0; y < main.height(); ++y)
    for (int x = 0; x < main.width(); ++x) differ += main.pixel(x, y) != normal.pixel(x, y);
  EXPECT_GT(differ, main.width() * main.height() / 2) << "normals are not the tone-mapped image";
  // Kept for people to look at.
  QDir().mkpath(LUMAGRAPH_BINARY_DIR "/test-output");
  normal.save(LUMAGRAPH_BINARY_DIR "/test-output/preview-normal.png");
  for (const char* port : {"gbuf.gbuffer.depth", "gbuf.gbuffer.albedo", "gtao.ao", "dfg.lut"}) {
    EXPECT_FALSE(show_port(port).empty()) << port << ": " << window->preview_image()->text().toStdString();
    shown().save(QStringLiteral(LUMAGRAPH_BINARY_DIR "/test-output/preview-%1.png").arg(port));
  }
  EXPECT_TRUE(show_port("sh.sh").empty());
  EXPECT_TRUE(window->preview_image()->text().contains("no image preview for buffers"));
  EXPECT_FALSE(show_port("sky.cube").empty()) << window->preview_image()->text().toStdString();
  shown().save(LUMAGRAPH_BINARY_DIR "/test-output/preview-sky.cube.png");
}

TEST_F(PortPreviewTest, ExposureBrightensAnHdrPortAndAChannelShowsAsGrey) {
  ASSERT_FALSE(show_port("light.color").empty()) << window->preview_image()->text().toStdString();
  const QImage at_0 = shown();
  window->preview()->set_exposure(2);
  const QImage at_2 = shown();  // no render: the kept pixels are shown again
  EXPECT_GT(mean_grey(at_2), mean_grey(at_0) + 10) << "+2 EV is four times the light";
  window->preview()->set_channel(PreviewChannel::red);
  const QImage red = shown();
  ASSERT_EQ(red.size(), at_2.size());
  int wrong = 0;
  for (int y = 0; y < red.height(); ++y)
    for (int x = 0; x < red.width(); ++x) {
      const QRgb p = red.pixel(x, y);
      wrong += qRed(p) != qRed(at_2.pixel(x, y)) || qGreen(p) != qRed(p) || qBlue(p) != qRed(p);
    }
  EXPECT_EQ(wrong, 0) << "grey levels equal the red channel exactly";
}

TEST_F(PortPreviewTest, TheReadOutShowsThePixelUnderTheCursor) {
  const PreviewImage& image = show_port("light.color");
  ASSERT_FALSE(image.empty()) << window->preview_image()->text().toStdString();
  const QPoint pixel(image.width / 2, image.height * 2 / 3);
  QLabel* label = window->preview_image();
  const QPoint at = pixel - window->preview()->pixel_at({0, 0});
  ASSERT_EQ(window->preview()->pixel_at(at), pixel);
  QMouseEvent move(QEvent::MouseMove, at, Qt::NoButton, Qt::NoButton, Qt::NoModifier);
  QApplication::sendEvent(label, &move);
  const QString text = window->preview()->readout()->text();
  const QRegularExpressionMatch m =
      QRegularExpression(R"(^x (\d+), y (\d+): (\S+) (\S+) (\S+) (\S+)$)").match(text);
  ASSERT_TRUE(m.hasMatch()) << text.toStdString();
  EXPECT_EQ(m.captured(1).toInt(), pixel.x());
  EXPECT_EQ(m.captured(2).toInt(), pixel.y());
  // The same frame rendered apart from the editor and read back from the executor.
  Renderer renderer;
  renderer.set_graph(graph_showing(graph(), window->preview()->port()));
  renderer.render(default_world(), {uint32_t(image.width), uint32_t(image.height)});
  const std::vector<float> rgba = renderer.executor().read_image("light.color");
  const size_t i = (size_t(pixel.y()) * image.width + pixel.x()) * 4;
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(m.captured(3 + c).toDouble(), rgba[i + c], 1e-3) << "channel " << c;
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
