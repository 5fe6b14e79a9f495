// The document the editor edits: one Graph (the truth every view shows), its file, and the undo
// history. Every change goes through edit(), which pushes a snapshot command; undo and redo swap
// whole graphs, which for graphs of tens of nodes is cheap and cannot drift from the edits.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "graph/diagnostics.h"
#include "graph/graph.h"

namespace lg::editor {

class Document : public QObject {
  Q_OBJECT
 public:
  explicit Document(QObject* parent = nullptr);

  const Graph& graph() const { return graph_; }
  const QString& path() const { return path_; }
  QUndoStack* undo_stack() { return &undo_; }
  bool is_modified() const { return !undo_.isClean(); }

  // Starts over with `graph` (new, open, recovery): no history, unmodified unless `modified`.
  void reset(Graph graph, const QString& path, bool modified = false);
  // Opens a file; on failure the document is unchanged and `diagnostics` says why.
  bool open(const QString& path, Diagnostics& diagnostics);
  // Writes the graph atomically to `path`, which becomes the document's file.
  bool save(const QString& path, QString* error);
  // The text save() last wrote or open() read, to tell our own writes from others'.
  const std::string& disk_text() const { return disk_text_; }

  // The file changed on disk and parses: an undoable step to its graph, after which the
  // document is clean.
  void take_from_disk(Graph graph, std::string text);

  // One undoable step to `after`. Consecutive edits with the same non-empty `merge_key` (a
  // slider being dragged) become one step.
  void edit(Graph after, const QString& text, const QString& merge_key = {});

 signals:
  void graph_changed();
  void path_changed();

 private:
  friend class SnapshotCommand;
  void apply(const Graph& graph);

  Graph graph_;
  QString path_;
  std::string disk_text_;
  QUndoStack undo_;
};

}  // namespace lg::editor
