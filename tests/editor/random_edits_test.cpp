// Random sequences of edits in the editor's window (add and remove nodes, connect and disconnect
// ports, change params to values in and out of their ranges, undo, redo), each example graph
// a few hundred steps under a fixed seed: no crash, and undoing everything returns the file,
// saved again, byte for byte as it was.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QUndoStack>
#include <random>

#include "editor/document.h"
#include "editor/graph_edits.h"
#include "editor/main_window.h"
#include "nodes/builtin_schemas.h"
#include "qt_app.h"

namespace lg::editor {
namespace {

constexpr int kSteps = 300;

QByteArray read_bytes(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

class RandomEdits {
 public:
  RandomEdits(MainWindow& window, uint32_t seed) : window_(window), rng_(seed), schemas_(builtin_registry().all()) {}

  void step() {
    const Graph& g = window_.document()->graph();
    QUndoStack* undo = window_.document()->undo_stack();
    switch (pick(8)) {
      case 0:
        window_.add_node(QString::fromStdString(schemas_[pick(schemas_.size())]->type));
        break;
      case 1:
        if (!g.nodes.empty()) edit([&](Graph& e) { remove_nodes(e, {g.nodes[pick(g.nodes.size())].id}); });
        break;
      case 2:
        connect_random(g);
        break;
      case 3:
        if (!g.links.empty()) {
          const GraphLink link = g.links[pick(g.links.size())];
          edit([&](Graph& e) { remove_link(e, link.from, link.to); });
        }
        break;
      case 4:
      case 5:
        set_random_param(g);
        break;
      case 6:
        undo->undo();
        break;
      case 7:
        undo->redo();
        break;
    }
  }

 private:
  size_t pick(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng_); }

  template <typename F>
  void edit(F change) {
    Graph g = window_.document()->graph();
    change(g);
    window_.document()->edit(std::move(g), QStringLiteral("random edit"));
  }

  // Any output to any input, of matching type or not: the editor must take a wrong link too
  // and report it as a problem.
  void connect_random(const Graph& g) {
    if (g.nodes.empty()) return;
    const GraphNode& from = g.nodes[pick(g.nodes.size())];
    const GraphNode& to = g.nodes[pick(g.nodes.size())];
    const NodeSchema* a = builtin_registry().find(from.type);
    const NodeSchema* b = builtin_registry().find(to.type);
    if (!a || !b || a->outputs.empty() || b->inputs.empty()) return;
    const PortRef out{from.id, a->outputs[pick(a->outputs.size())].name};
    const PortRef in{to.id, b->inputs[pick(b->inputs.size())].name};
    if (!has_link(g, out, in)) edit([&](Graph& e) { add_link(e, out, in); });
  }

  // In range mostly; sometimes out of range or of the wrong kind, which the editor reports.
  void set_random_param(const Graph& g) {
    if (g.nodes.empty()) return;
    const GraphNode& node = g.nodes[pick(g.nodes.size())];
    const NodeSchema* schema = builtin_registry().find(node.type);
    if (!schema || schema->params.empty()) return;
    const ParamSpec& p = schema->params[pick(schema->params.size())];
    JsonValue value;
    if (pick(5) == 0) {
      value = JsonValue("not a value");
    } else if (p.type == ParamType::bool_) {
      value = JsonValue(pick(2) == 1);
    } else if (p.type == ParamType::enum_ && !p.values.empty()) {
      value = JsonValue(p.values[pick(p.values.size())]);
    } else if (p.type == ParamType::float_ || p.type == ParamType::int_) {
      const double lo = p.min.value_or(-10), hi = p.max.value_or(10);
      const double x = std::uniform_real_distribution<double>(lo - 1, hi + 1)(rng_);
      value = JsonValue(p.type == ParamType::int_ ? std::round(x) : x);
    } else {
      value = p.default_value;
    }
    edit([&](Graph& e) { set_param(e, node.id, p.name, value); });
  }

  MainWindow& window_;
  std::mt19937 rng_;
  std::vector<const NodeSchema*> schemas_;
};

TEST(RandomEditsTest, UndoingEveryRandomEditRestoresTheFileByteForByte) {
  lg::test::qt_app();
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QDir examples(QStringLiteral(LUMAGRAPH_SOURCE_DIR "/examples"));
  uint32_t seed = 1;
  for (const QString& name : examples.entryList({"*.json"}, QDir::Files)) {
    SCOPED_TRACE(name.toStdString());
    MainWindow window(false);
    // The editor's own formatting first: that file is what undoing everything must give back.
    const QString path = dir.filePath(name);
    ASSERT_TRUE(window.open_file(examples.filePath(name)));
    ASSERT_TRUE(window.save_to(path));
    const QByteArray saved = read_bytes(path);
    ASSERT_TRUE(window.open_file(path));

    RandomEdits edits(window, seed++);
    for (int i = 0; i < kSteps; ++i) edits.step();
    QCoreApplication::processEvents();
    QUndoStack* undo = window.document()->undo_stack();
    EXPECT_GT(undo->count(), kSteps / 4) << "most steps should have edited the graph";
    ASSERT_TRUE(window.save_to(dir.filePath("edited.json")));
    EXPECT_NE(read_bytes(dir.filePath("edited.json")), saved) << "the edits should have changed the file";
    undo->setIndex(0);
    ASSERT_TRUE(window.save_to(path));
    EXPECT_EQ(read_bytes(path), saved);
  }
}

}  // namespace
}  // namespace lg::editor
