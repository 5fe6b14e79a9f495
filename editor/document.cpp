#include "editor/document.h"

#include <QFile>

#include "graph/graph_io.h"
#include "graph/json_writer.h"

namespace lg::editor {

class SnapshotCommand : public QUndoCommand {
 public:
  SnapshotCommand(Document* doc, Graph before, Graph after, const QString& text, QString merge_key)
      : QUndoCommand(text),
        doc_(doc),
        before_(std::move(before)),
        after_(std::move(after)),
        key_(std::move(merge_key)) {}

  void redo() override { doc_->apply(after_); }
  void undo() override { doc_->apply(before_); }
  int id() const override { return key_.isEmpty() ? -1 : 1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = static_cast<const SnapshotCommand*>(other);
    if (next->key_ != key_) return false;
    after_ = next->after_;
    return true;
  }

 private:
  Document* doc_;
  Graph before_, after_;
  QString key_;
};

Document::Document(QObject* parent) : QObject(parent) {}

void Document::apply(const Graph& graph) {
  const std::string file = graph_.file;
  graph_ = graph;
  graph_.file = file;
  emit graph_changed();
}

void Document::reset(Graph graph, const QString& path, bool modified) {
  undo_.clear();
  graph.file = path.toStdString();
  graph_ = std::move(graph);
  path_ = path;
  if (modified) undo_.resetClean();  // an empty stack that is not clean: only a save cleans it
  emit path_changed();
  emit graph_changed();
}

bool Document::open(const QString& path, Diagnostics& diagnostics) {
  std::optional<Graph> loaded = load_graph_file(path.toStdString(), diagnostics);
  if (!loaded) return false;
  reset(std::move(*loaded), path);
  QFile file(path);
  disk_text_ = file.open(QIODevice::ReadOnly) ? file.readAll().toStdString() : std::string();
  return true;
}

bool Document::save(const QString& path, QString* error) {
  const std::string text = graph_to_text(graph_);
  std::string why;
  if (!write_file_atomically(path.toStdString(), text, &why)) {
    if (error) *error = QString::fromStdString(why);
    return false;
  }
  disk_text_ = text;
  graph_.file = path.toStdString();
  undo_.setClean();
  if (path != path_) {
    path_ = path;
    emit path_changed();
  }
  return true;
}

void Document::take_from_disk(Graph graph, std::string text) {
  edit(std::move(graph), tr("Reload from disk"));
  undo_.setClean();
  disk_text_ = std::move(text);
}

void Document::edit(Graph after, const QString& text, const QString& merge_key) {
  undo_.push(new SnapshotCommand(this, graph_, std::move(after), text, merge_key));
}

}  // namespace lg::editor
