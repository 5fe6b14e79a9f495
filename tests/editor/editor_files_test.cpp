// The editor and files: saving writes the runtime's format, examples round-trip untouched (an
// edit undone and saved renders the same image), a save onto a full disk keeps everything, a file
// changed on disk reloads (a broken one keeps the last good graph), autosave recovers unsaved
// work, and --screenshot writes the window.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QListWidget>
#include <QProcess>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>

#include "api/renderer.h"
#include "editor/disk_sync.h"
#include "editor/document.h"
#include "editor/graph_edits.h"
#include "editor/main_window.h"
#include "graph/fault_injection.h"
#include "graph/graph_io.h"
#include "qt_app.h"
#include "runtime/scene/default_world.h"

namespace lg::editor {
namespace {

using lg::test::settle;

QString example(const QString& name) {
  return QStringLiteral(LUMAGRAPH_SOURCE_DIR "/examples/") + name;
}

void write(const QString& path, const QByteArray& text) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
  f.write(text);
}

JsonValue json_of_file(const QString& path) {
  Diagnostics d;
  std::optional<Graph> g = load_graph_file(path.toStdString(), d);
  EXPECT_TRUE(g) << d.to_string();
  return g ? graph_to_json(*g) : JsonValue();
}

class FilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    lg::test::qt_app();
    ASSERT_TRUE(dir.isValid());
    window = std::make_unique<MainWindow>(false);
  }
  QString copy_example(const QString& name) {
    const QString path = dir.filePath(name);
    QFile::copy(example(name), path);
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    return path;
  }
  QTemporaryDir dir;
  std::unique_ptr<MainWindow> window;
};

TEST_F(FilesTest, EveryExampleRoundTripsUnedited) {
  for (const QString& name : QDir(example("")).entryList({"*.json"}, QDir::Files)) {
    ASSERT_TRUE(window->open_file(example(name))) << name.toStdString();
    const QString out = dir.filePath(name);
    ASSERT_TRUE(window->save_to(out));
    EXPECT_EQ(json_of_file(out), json_of_file(example(name))) << name.toStdString();
  }
}

// The main output of a graph file on the default world, float RGBA. One renderer serves every
// file: it makes each pipeline once (a new renderer takes about a second for its own), and a
// newly loaded graph starts from an empty history, so its first frame is what a fresh renderer's is.
std::vector<float> render_file(Renderer& renderer, const QString& path) {
  renderer.load_graph(path.toStdString());
  renderer.render(default_world(), {96, 54});
  return renderer.read_output();
}

// Saved into a folder of its own, as a project is: the example's assets (paths in params are
// relative to the graph) go with it.
TEST_F(FilesTest, EveryExampleEditedUndoneAndSavedRendersTheSameImage) {
  ASSERT_TRUE(QDir(dir.path()).mkpath(QStringLiteral("environments")));
  for (const QString& asset : QDir(example("environments")).entryList(QDir::Files))
    ASSERT_TRUE(QFile::copy(example("environments/") + asset, dir.filePath("environments/" + asset)));
  Renderer renderer;
  for (const QString& name : QDir(example("")).entryList({"*.json"}, QDir::Files)) {
    SCOPED_TRACE(name.toStdString());
    ASSERT_TRUE(window->open_file(example(name)));
    window->add_node(QStringLiteral("env.sky"));
    window->document()->undo_stack()->undo();
    const QString out = dir.filePath(name);
    ASSERT_TRUE(window->save_to(out));
    const std::vector<float> original = render_file(renderer, example(name)), saved = render_file(renderer, out);
    ASSERT_EQ(saved.size(), original.size());
    size_t differ = 0;
    for (size_t i = 0; i < saved.size(); ++i) differ += saved[i] != original[i];  // NaN counts too
    EXPECT_EQ(differ, 0u) << "identical pixels";
  }
}

TEST_F(FilesTest, SavingWritesTheExpectedJson) {
  const QString path = copy_example("minimal.json");
  ASSERT_TRUE(window->open_file(path));
  Graph g = window->document()->graph();
  set_param(g, "tonemap", "exposure", JsonValue(1.5));
  set_node_position(g, "out", {760, 40});
  window->document()->edit(g, "test edit");
  ASSERT_TRUE(window->document()->is_modified());
  ASSERT_TRUE(window->save_to(path));
  EXPECT_FALSE(window->document()->is_modified());
  const char* expected = R"({
    "format": "lumagraph/1", "name": "minimal",
    "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "light", "type": "lighting.deferred" },
      { "id": "tonemap", "type": "post.tonemap", "params": { "exposure": 1.5 } },
      { "id": "out", "type": "output.display" }
    ],
    "links": [
      { "from": "gbuf.gbuffer", "to": "light.gbuffer" },
      { "from": "light.color", "to": "tonemap.color" },
      { "from": "tonemap.color", "to": "out.color" }
    ],
    "outputs": [],
    "editor": { "positions": { "gbuf": [0, 0], "light": [240, 0], "tonemap": [480, 0], "out": [760, 40] } }
  })";
  Diagnostics d;
  std::optional<Graph> want = parse_graph_text(expected, d);
  ASSERT_TRUE(want) << d.to_string();
  EXPECT_EQ(json_of_file(path), graph_to_json(*want));
}

// A disk that fills up while saving (an injected ENOSPC, graph/fault_injection.h; a read-only
// folder cannot be tested as root, which CI is): the save fails and says why, the file on disk
// is what it was, no temporary file is left, and the edit is still in the document, unsaved.
TEST_F(FilesTest, ASaveOntoAFullDiskKeepsTheDocumentAndTheFileAndSaysWhy) {
  const QString path = copy_example("minimal.json");
  ASSERT_TRUE(window->open_file(path));
  QFile before(path);
  ASSERT_TRUE(before.open(QIODevice::ReadOnly));
  const QByteArray on_disk = before.readAll();
  Graph g = window->document()->graph();
  set_param(g, "tonemap", "exposure", JsonValue(1.5));
  window->document()->edit(g, "test edit");

  arm_fault(FaultSite::file_write, 1);
  EXPECT_FALSE(window->save_to(path));
  arm_fault(FaultSite::file_write, 0);
  EXPECT_TRUE(window->statusBar()->currentMessage().contains("No space left on device"))
      << window->statusBar()->currentMessage().toStdString();
  QFile after(path);
  ASSERT_TRUE(after.open(QIODevice::ReadOnly));
  EXPECT_EQ(after.readAll(), on_disk);
  EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files), QStringList{"minimal.json"});
  EXPECT_TRUE(window->document()->is_modified());
  EXPECT_EQ(*find_node(window->document()->graph(), "tonemap")->params.find("exposure"), JsonValue(1.5));

  ASSERT_TRUE(window->save_to(path));  // the disk has room again
  EXPECT_FALSE(window->document()->is_modified());
}

TEST_F(FilesTest, ABrokenFileOnDiskKeepsTheLastGoodGraph) {
  const QString path = copy_example("minimal.json");
  ASSERT_TRUE(window->open_file(path));
  write(path, "{ \"format\": \"lumagraph/1\", \"nodes\": [ { \"id\": ");
  window->disk_sync()->check_file();
  settle();
  EXPECT_EQ(window->document()->graph().nodes.size(), 4u);
  ASSERT_GT(window->problems()->count(), 0);
  EXPECT_TRUE(window->problems()->item(0)->text().startsWith("file on disk"))
      << window->problems()->item(0)->text().toStdString();

  // Fixed on disk (here: one node fewer): it reloads, and the reload is undoable.
  QFile original(example("minimal.json"));
  ASSERT_TRUE(original.open(QIODevice::ReadOnly));
  Diagnostics d;
  Graph fixed = *parse_graph_text(original.readAll().toStdString(), d);
  remove_nodes(fixed, {"out"});
  write(path, QByteArray::fromStdString(graph_to_text(fixed)));
  window->disk_sync()->check_file();
  settle();
  EXPECT_EQ(window->document()->graph().nodes.size(), 3u);
  EXPECT_FALSE(window->document()->is_modified());
  EXPECT_EQ(window->canvas()->node("out"), nullptr);
}

TEST_F(FilesTest, TheWatcherNoticesChangesOnDisk) {
  const QString path = copy_example("minimal.json");
  ASSERT_TRUE(window->open_file(path));
  Graph g = window->document()->graph();
  set_param(g, "tonemap", "curve", JsonValue("neutral"));
  write(path, QByteArray::fromStdString(graph_to_text(g)));
  // The watcher signals asynchronously; no wall-clock assertion, only a bounded wait.
  for (int i = 0; i < 200 && !find_node(window->document()->graph(), "tonemap")->params.find("curve"); ++i) {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
  }
  EXPECT_EQ(*find_node(window->document()->graph(), "tonemap")->params.find("curve"), JsonValue("neutral"));
}

TEST_F(FilesTest, AutosaveRecoversUnsavedWork) {
  const QString path = copy_example("minimal.json");
  ASSERT_TRUE(window->open_file(path));
  Graph g = window->document()->graph();
  add_node(g, "post.bloom", {100, 100});
  window->document()->edit(g, "add bloom");
  window->disk_sync()->write_autosave();
  EXPECT_EQ(DiskSync::recoverable_autosave(path), DiskSync::autosave_path(path));

  // A later session (the first one "crashed": its autosave is still there).
  MainWindow next(false);
  ASSERT_TRUE(next.open_file(path));
  EXPECT_FALSE(find_node(next.document()->graph(), "bloom"));
  ASSERT_TRUE(next.open_recovered(path));
  EXPECT_TRUE(find_node(next.document()->graph(), "bloom"));
  EXPECT_TRUE(next.document()->is_modified());
  ASSERT_TRUE(next.save_to(path));
  EXPECT_FALSE(QFile::exists(DiskSync::autosave_path(path)));
}

TEST_F(FilesTest, ScreenshotWritesTheWindow) {
  const QString png = dir.filePath("default.png");
  QProcess editor;
  editor.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph-editor"),
               {example("default.json"), "--screenshot", png});
  ASSERT_TRUE(editor.waitForFinished(120'000));
  EXPECT_EQ(editor.exitCode(), 0) << editor.readAllStandardError().toStdString();
  QImage image(png);
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.size(), QSize(1600, 900));
  std::set<QRgb> colours;
  for (int y = 0; y < image.height(); y += 7)
    for (int x = 0; x < image.width(); x += 7) colours.insert(image.pixel(x, y));
  EXPECT_GT(colours.size(), 50u);
}

}  // namespace
}  // namespace lg::editor
