#include "editor/disk_sync.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include "editor/document.h"
#include "graph/graph_io.h"
#include "graph/json_writer.h"

namespace lg::editor {

DiskSync::DiskSync(Document* document, QObject* parent) : QObject(parent), doc_(document) {
  connect(&watcher_, &QFileSystemWatcher::fileChanged, this, &DiskSync::check_file);
  connect(doc_, &Document::path_changed, this, &DiskSync::watch);
  autosave_.setInterval(30'000);
  connect(&autosave_, &QTimer::timeout, this, &DiskSync::write_autosave);
  autosave_.start();
  watch();
}

QString DiskSync::autosave_path(const QString& file) {
  if (file.isEmpty()) {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(dir);
    return dir + QStringLiteral("/untitled.lumagraph.json.autosave");
  }
  const QFileInfo info(file);
  return info.absolutePath() + QStringLiteral("/.") + info.fileName() + QStringLiteral(".autosave");
}

QString DiskSync::recoverable_autosave(const QString& file) {
  const QString autosave = autosave_path(file);
  const QFileInfo saved(autosave), original(file);
  if (!saved.exists()) return {};
  if (original.exists() && saved.lastModified() < original.lastModified()) return {};
  QFile a(autosave), b(file);
  if (a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly) && a.readAll() == b.readAll()) return {};
  return autosave;
}

void DiskSync::remove_autosave() {
  QFile::remove(autosave_path(doc_->path()));
}

void DiskSync::write_autosave() {
  if (!doc_->is_modified()) return;
  std::string error;
  write_file_atomically(autosave_path(doc_->path()).toStdString(), graph_to_text(doc_->graph()), &error);
}

void DiskSync::watch() {
  if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
  if (!doc_->path().isEmpty() && QFileInfo::exists(doc_->path())) watcher_.addPath(doc_->path());
}

void DiskSync::check_file() {
  // An atomic save replaces the file, which ends the watch on the old one.
  watch();
  QFile file(doc_->path());
  if (doc_->path().isEmpty() || !file.open(QIODevice::ReadOnly)) return;
  const std::string text = file.readAll().toStdString();
  if (text == doc_->disk_text()) return;  // our own save, or nothing new
  if (doc_->is_modified())
    emit conflict();
  else
    reload(text);
}

void DiskSync::reload_from_disk() {
  QFile file(doc_->path());
  if (file.open(QIODevice::ReadOnly)) reload(file.readAll().toStdString());
}

void DiskSync::reload(const std::string& text) {
  Diagnostics diagnostics(doc_->path().toStdString());
  std::optional<Graph> graph = parse_graph_text(text, diagnostics);
  if (!graph) {
    emit reload_failed(diagnostics);
    return;
  }
  doc_->take_from_disk(std::move(*graph), text);
  emit reloaded();
}

}  // namespace lg::editor
