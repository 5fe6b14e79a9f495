// Keeps a document and the disk in step: reloads the file when another program changes it (a
// file that no longer parses leaves the last good graph in place and reports why), and writes
// an autosave copy of unsaved work that a later session offers to recover after a crash.
#pragma once

#include <QFileSystemWatcher>
#include <QObject>
#include <QTimer>

#include "graph/diagnostics.h"

namespace lg::editor {

class Document;

class DiskSync : public QObject {
  Q_OBJECT
 public:
  explicit DiskSync(Document* document, QObject* parent = nullptr);

  // Beside the file: "dir/.name.json.autosave"; for an untitled graph, in the user's data folder.
  static QString autosave_path(const QString& file);
  // The autosave of `file` when it is newer than the file and says something else; empty if none.
  static QString recoverable_autosave(const QString& file);

  void remove_autosave();

 public slots:
  // Looks at the file now (the watcher calls it; tests call it directly).
  void check_file();
  void write_autosave();
  // Replaces the graph with the file's, discarding unsaved edits (they stay undoable).
  void reload_from_disk();

 signals:
  void reloaded();  // the graph was replaced from the changed file
  void reload_failed(const lg::Diagnostics& diagnostics);
  // The file changed while the document has unsaved edits: the user must choose.
  void conflict();

 private:
  void watch();
  void reload(const std::string& text);

  Document* doc_;
  QFileSystemWatcher watcher_;
  QTimer autosave_;
};

}  // namespace lg::editor
