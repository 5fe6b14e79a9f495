// The editor's main window: the canvas in the middle, the palette on the left, parameters and
// the inspector on the right, problems and the compile view below; menus for files, editing and
// views. It turns requests from the views into document edits and, after every change, brings
// every view up to date (canvas, live validation, parameters, compile view, preview). The
// inspector shows the selected env.load node's file, or the selected gi.irradiance_volume node's
// probes as the preview's runtime holds them (live_probes.h), refreshed when they change.
#pragma once

#include <QMainWindow>
#include <memory>

#include "editor/async_preview.h"
#include "editor/canvas.h"
#include "editor/preview.h"
#include "editor/validation.h"

class QLabel;
class QTimer;
class QListWidget;

namespace lg {
class InspectorWidget;
}

namespace lg::editor {

class CompileView;
class DiskSync;
class Document;
class Palette;
class ParamPanel;
class PreviewPanel;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  // `interactive`: false for screenshots and tests, where nothing may wait for a person.
  explicit MainWindow(bool interactive = true, QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a file; on failure the current graph stays and Problems lists why.
  bool open_file(const QString& path);
  // Opens the autosave of `path` (after a crash) as unsaved changes to it.
  bool open_recovered(const QString& path);
  // Asks whether to recover the autosave of `path` (empty: the untitled graph), if there is one.
  void offer_recovery(const QString& path);
  bool save_to(const QString& path);
  void add_node(const QString& type, std::optional<Position> at = {});
  void copy_selection();
  void paste();
  void delete_selection();
  void arrange();
  // Adds the Preview dock; `renderer` runs off the UI thread after each edit that compiles.
  void set_preview(std::unique_ptr<PreviewRenderer> renderer);

  Document* document() const { return doc_; }
  Canvas* canvas() const { return canvas_; }
  Palette* palette() const { return palette_; }
  ParamPanel* params() const { return params_; }
  CompileView* compile_view() const { return compile_; }
  DiskSync* disk_sync() const { return disk_; }
  QListWidget* problems() const { return problems_; }
  InspectorWidget* inspector() const { return inspector_; }
  PreviewPanel* preview() const { return preview_; }
  QLabel* preview_image() const;
  int previews_shown() const { return previews_shown_; }
  // The probes of the last preview frame's volume nodes.
  const LiveProbes& live_probes() const { return live_probes_; }
  // Writes the probes of the live volume the inspector shows as a .lgprobes bake (atomically);
  // false, saying why in the status bar, when none is shown or the file cannot be written.
  bool save_live_probes(const QString& path);
  const Validation& validation() const { return validation_; }

 signals:
  void preview_shown();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void build_menus();
  void refresh();
  void show_problems();
  void show_selection();
  void edit_links(const std::vector<Link>& added, const std::vector<Link>& removed);
  void move_nodes(const std::map<std::string, Position>& positions);
  void set_param(const std::string& node, const std::string& param, const JsonValue& value);
  void apply_preset(const std::string& node, int index);
  void show_menu(Position at, QPoint global);
  void request_preview();
  void show_preview(const PreviewImage& image, const QString& error, double milliseconds);
  void show_live_volume(const std::string& node);
  void save_live_probes_dialog();
  void update_title();
  bool maybe_save();
  bool save();
  bool save_as();
  void open_dialog();
  void new_graph();

  bool interactive_;
  Document* doc_;
  DiskSync* disk_;
  Canvas* canvas_;
  Palette* palette_;
  ParamPanel* params_;
  CompileView* compile_;
  QListWidget* problems_;
  InspectorWidget* inspector_;
  PreviewPanel* preview_ = nullptr;
  AsyncPreview* preview_runner_ = nullptr;
  int previews_shown_ = 0;
  LiveProbes live_probes_;
  QString preview_error_;                         // of the last preview frame, or empty
  std::string live_node_;                         // the volume node whose probes the inspector shows, or empty
  uint64_t live_version_ = 0;                     // and the version it shows
  QTimer* live_timer_;                            // paces the preview's frames while a dynamic volume updates
  SceneSummary scene_ = default_scene_summary();  // the preview's, which validation compiles for
  Validation validation_;
  std::vector<Diagnostic> disk_problems_;  // the file on disk is broken: why
};

}  // namespace lg::editor
