#include "editor/main_window.h"

#include <QApplication>
#include <QClipboard>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <algorithm>

#include "editor/compile_view.h"
#include "editor/disk_sync.h"
#include "editor/document.h"
#include "editor/inspector_widget.h"
#include "editor/palette.h"
#include "editor/param_panel.h"
#include "editor/preview_panel.h"
#include "editor/preview_ports.h"
#include "editor/probe_view.h"
#include "editor/runtime_preview.h"
#include "graph/asset_paths.h"
#include "graph/compiler/node_states.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace lg::editor {

// The Inspector dock's width for a probe view: a 3D view of about 400 pixels beside the maps.
constexpr int kProbeDockWidth = 640;

static QString text_of(const std::string& s) {
  return QString::fromStdString(s);
}

// What the inspector calls a volume node's live probes (ProbeBake::path).
static std::string live_name(const std::string& node) {
  return "'" + node + "' live in the preview";
}

MainWindow::MainWindow(bool interactive, QWidget* parent)
    : QMainWindow(parent),
      interactive_(interactive),
      doc_(new Document(this)),
      disk_(new DiskSync(doc_, this)),
      canvas_(new Canvas(builtin_registry(), this)),
      palette_(new Palette(builtin_registry(), this)),
      params_(new ParamPanel(builtin_registry(), this)),
      compile_(new CompileView(this)),
      problems_(new QListWidget(this)),
      inspector_(new InspectorWidget(this)),
      live_timer_(new QTimer(this)) {
  setCentralWidget(canvas_);
  setDockNestingEnabled(true);
  auto dock = [this](QWidget* widget, const QString& title, Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(title);
    d->setWidget(widget);
    addDockWidget(area, d);
    return d;
  };
  QDockWidget* palette_dock = dock(palette_, tr("Nodes"), Qt::LeftDockWidgetArea);
  QDockWidget* params_dock = dock(params_, tr("Parameters"), Qt::RightDockWidgetArea);
  QDockWidget* inspector_dock = dock(inspector_, tr("Inspector"), Qt::RightDockWidgetArea);
  QDockWidget* compile_dock = dock(compile_, tr("Compile"), Qt::BottomDockWidgetArea);
  QDockWidget* problems_dock = dock(problems_, tr("Problems"), Qt::BottomDockWidgetArea);
  tabifyDockWidget(params_dock, inspector_dock);
  tabifyDockWidget(compile_dock, problems_dock);
  params_dock->raise();
  // Coming into view, the inspector shows the selected env.load node's file.
  connect(inspector_dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
    if (visible) show_selection();
  });
  compile_dock->raise();
  resizeDocks({palette_dock, params_dock}, {230, 380}, Qt::Horizontal);
  resizeDocks({compile_dock}, {270}, Qt::Vertical);

  connect(doc_, &Document::graph_changed, this, &MainWindow::refresh);
  connect(doc_, &Document::path_changed, this, &MainWindow::update_title);
  connect(doc_->undo_stack(), &QUndoStack::cleanChanged, this, &MainWindow::update_title);
  connect(palette_, &Palette::add_requested, this, [this](const QString& type) { add_node(type); });
  connect(canvas_, &Canvas::links_edited, this, &MainWindow::edit_links);
  connect(canvas_, &Canvas::link_refused, this, [this](const QString& why) { statusBar()->showMessage(why, 8000); });
  connect(canvas_, &Canvas::nodes_moved, this, &MainWindow::move_nodes);
  connect(canvas_, &Canvas::delete_requested, this, &MainWindow::delete_selection);
  connect(canvas_, &Canvas::menu_requested, this, &MainWindow::show_menu);
  connect(canvas_, &Canvas::selection_changed, this, &MainWindow::show_selection);
  connect(params_, &ParamPanel::param_edited, this, &MainWindow::set_param);
  connect(params_, &ParamPanel::preset_chosen, this, &MainWindow::apply_preset);
  connect(inspector_, &InspectorWidget::save_probes_requested, this, &MainWindow::save_live_probes_dialog);
  // A dynamic volume changes without edits: the preview renders again, at most twice a second.
  live_timer_->setSingleShot(true);
  live_timer_->setInterval(500);
  connect(live_timer_, &QTimer::timeout, this, &MainWindow::request_preview);
  connect(problems_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
    const std::string id = item->data(Qt::UserRole).toString().toStdString();
    if (id.empty()) return;
    canvas_->select_nodes({id});
    canvas_->centre_on(id);
  });
  connect(disk_, &DiskSync::reloaded, this, [this] {
    disk_problems_.clear();
    statusBar()->showMessage(tr("Reloaded %1: it changed on disk").arg(doc_->path()), 8000);
    refresh();
  });
  connect(disk_, &DiskSync::reload_failed, this, [this](const Diagnostics& d) {
    disk_problems_ = d.items();
    statusBar()->showMessage(
        tr("%1 changed on disk and no longer loads: keeping the last good graph").arg(doc_->path()));
    show_problems();
  });
  connect(disk_, &DiskSync::conflict, this, [this] {
    if (interactive_ &&
        QMessageBox::question(this, tr("File changed on disk"),
                              tr("%1 changed on disk, and you have unsaved changes.\nReload it and drop them "
                                 "(they stay undoable)?")
                                  .arg(doc_->path())) == QMessageBox::Yes)
      disk_->reload_from_disk();
    else
      statusBar()->showMessage(tr("%1 changed on disk; your unsaved changes are kept").arg(doc_->path()));
  });

  build_menus();
  new_graph();
  resize(1600, 900);
}

MainWindow::~MainWindow() = default;

void MainWindow::build_menus() {
  auto add = [this](QMenu* menu, const QString& text, QKeySequence key, auto slot) {
    QAction* a = menu->addAction(text, this, slot);
    a->setShortcut(key);
    return a;
  };
  QMenu* file = menuBar()->addMenu(tr("&File"));
  add(file, tr("&New"), QKeySequence::New, [this] {
    if (maybe_save()) new_graph();
  });
  add(file, tr("&Open…"), QKeySequence::Open, [this] { open_dialog(); });
  add(file, tr("&Save"), QKeySequence::Save, [this] { save(); });
  add(file, tr("Save &As…"), QKeySequence::SaveAs, [this] { save_as(); });
  file->addSeparator();
  add(file, tr("&Quit"), QKeySequence::Quit, [this] { close(); });

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = doc_->undo_stack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = doc_->undo_stack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  add(edit, tr("&Copy"), QKeySequence::Copy, [this] { copy_selection(); });
  add(edit, tr("Cu&t"), QKeySequence::Cut, [this] {
    copy_selection();
    delete_selection();
  });
  add(edit, tr("&Paste"), QKeySequence::Paste, [this] { paste(); });
  add(edit, tr("&Delete"), QKeySequence::Delete, [this] { delete_selection(); });
  add(edit, tr("Select &All"), QKeySequence::SelectAll, [this] {
    std::vector<std::string> ids;
    for (const GraphNode& n : doc_->graph().nodes) ids.push_back(n.id);
    canvas_->select_nodes(ids);
  });

  QMenu* view = menuBar()->addMenu(tr("&View"));
  add(view, tr("&Frame All"), QKeySequence(Qt::Key_F), [this] { canvas_->frame_all(); });
  add(view, tr("&Arrange Nodes"), QKeySequence(QStringLiteral("Ctrl+L")), [this] { arrange(); });
  view->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) view->addAction(d->toggleViewAction());

  QMenu* inspect = menuBar()->addMenu(tr("&Inspect"));
  inspect->addAction(tr("Open &Environment…"), this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Environment"), {}, tr("Environments (*.hdr *.exr)"));
    if (!file.isEmpty()) inspector_->open_environment(file);
  });
  // A new renderer for another world: its device starts afresh, which a scene change can afford.
  inspect->addAction(tr("Preview &Scene…"), this, [this] {
    const QString file =
        QFileDialog::getOpenFileName(this, tr("Preview scene"), {}, tr("Scenes (*.json *.gltf *.glb *.obj)"));
    if (!file.isEmpty()) set_preview(std::make_unique<RuntimePreview>(file.toStdString()));
  });
  inspect->addAction(tr("Preview the &Default World"), this,
                     [this] { set_preview(std::make_unique<RuntimePreview>()); });
  inspect->addAction(tr("Save Live &Probes…"), this, [this] { save_live_probes_dialog(); });
}

void MainWindow::new_graph() {
  Graph graph;
  graph.name = "untitled";
  disk_problems_.clear();
  doc_->reset(std::move(graph), {});
}

bool MainWindow::open_file(const QString& path) {
  Diagnostics diagnostics(path.toStdString());
  if (!doc_->open(path, diagnostics)) {
    disk_problems_ = diagnostics.items();
    show_problems();
    statusBar()->showMessage(tr("Could not open %1").arg(path));
    if (interactive_) QMessageBox::warning(this, tr("Could not open"), text_of(diagnostics.to_string()));
    return false;
  }
  disk_problems_.clear();
  refresh();
  canvas_->frame_all();
  offer_recovery(path);
  return true;
}

void MainWindow::offer_recovery(const QString& path) {
  if (!interactive_ || DiskSync::recoverable_autosave(path).isEmpty()) return;
  const QString what = path.isEmpty() ? tr("an untitled graph") : path;
  if (QMessageBox::question(this, tr("Recover unsaved changes?"),
                            tr("There are unsaved changes to %1 from an earlier session that did not end "
                               "normally. Recover them?")
                                .arg(what)) == QMessageBox::Yes)
    open_recovered(path);
}

bool MainWindow::open_recovered(const QString& path) {
  Diagnostics diagnostics(DiskSync::autosave_path(path).toStdString());
  std::optional<Graph> graph = load_graph_file(DiskSync::autosave_path(path).toStdString(), diagnostics);
  if (!graph) return false;
  doc_->reset(std::move(*graph), path, true);
  statusBar()->showMessage(tr("Recovered unsaved changes to %1").arg(path), 8000);
  return true;
}

bool MainWindow::save_to(const QString& path) {
  QString error;
  if (!doc_->save(path, &error)) {
    statusBar()->showMessage(tr("Could not save: %1").arg(error));
    if (interactive_) QMessageBox::warning(this, tr("Could not save"), error);
    return false;
  }
  disk_->remove_autosave();
  disk_problems_.clear();
  show_problems();
  statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  return true;
}

bool MainWindow::save() {
  return doc_->path().isEmpty() ? save_as() : save_to(doc_->path());
}

bool MainWindow::save_as() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Save graph"), doc_->path(), tr("Graphs (*.json)"));
  return !path.isEmpty() && save_to(path);
}

void MainWindow::open_dialog() {
  if (!maybe_save()) return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open graph"), QFileInfo(doc_->path()).absolutePath(),
                                                    tr("Graphs (*.json)"));
  if (!path.isEmpty()) open_file(path);
}

bool MainWindow::maybe_save() {
  if (!doc_->is_modified() || !interactive_) return true;
  const auto answer = QMessageBox::question(
      this, tr("Unsaved changes"),
      tr("Save the changes to %1?").arg(doc_->path().isEmpty() ? tr("the untitled graph") : doc_->path()),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  return answer == QMessageBox::Discard || (answer == QMessageBox::Save && save());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybe_save()) {
    event->ignore();
    return;
  }
  disk_->remove_autosave();
  event->accept();
}

void MainWindow::update_title() {
  const QString file = doc_->path().isEmpty() ? tr("untitled") : QFileInfo(doc_->path()).fileName();
  setWindowTitle(QStringLiteral("%1[*] — %2 — Lumagraph Editor").arg(file, text_of(doc_->graph().name)));
  setWindowModified(doc_->is_modified());
}

void MainWindow::refresh() {
  const Graph& graph = doc_->graph();
  canvas_->show_graph(graph);
  const bool had_errors = validation_.has_errors();
  validation_ = validate_graph(graph, scene_);
  show_problems();
  // The compile view is empty while the graph has errors: show what is wrong instead, and the
  // plan again once they are gone.
  if (validation_.has_errors() != had_errors) {
    QWidget* shown = validation_.has_errors() ? static_cast<QWidget*>(problems_) : compile_;
    if (auto* dock = qobject_cast<QDockWidget*>(shown->parentWidget())) dock->raise();
  }
  compile_->show_plan(validation_.plan ? &*validation_.plan : nullptr);
  show_selection();
  update_title();
  request_preview();
}

QLabel* MainWindow::preview_image() const {
  return preview_ ? preview_->image_label() : nullptr;
}

void MainWindow::request_preview() {
  if (!preview_runner_) return;
  preview_->set_ports(preview_ports(doc_->graph(), builtin_registry()));
  if (validation_.plan) preview_runner_->request(doc_->graph(), preview_->render_size(), preview_->port());
}

void MainWindow::show_preview(const PreviewImage& image, const QString& error, double milliseconds) {
  if (!image.empty()) statusBar()->showMessage(tr("Preview rendered in %1 ms").arg(milliseconds, 0, 'f', 0), 4000);
  preview_->show_image(image, error);
  if (!image.empty()) compile_->show_gpu_times(image.pass_ms);
  live_probes_ = image.probes;
  preview_error_ = error;
  // The selected volume's probes as this frame left them (redrawn only when they changed).
  const std::set<std::string> selected = canvas_->selected_nodes();
  const GraphNode* node = selected.size() == 1 ? find_node(doc_->graph(), *selected.begin()) : nullptr;
  if (node && node->type == "gi.irradiance_volume" && inspector_->isVisible()) show_live_volume(node->id);
  if (std::any_of(live_probes_.begin(), live_probes_.end(), [](const auto& p) { return p.second->dynamic; }))
    live_timer_->start();
  ++previews_shown_;
  emit preview_shown();
}

void MainWindow::show_problems() {
  problems_->clear();
  std::map<std::string, NodeProblem> on_nodes;
  auto list = [this](const Diagnostic& d, const std::string& node, const QString& prefix) {
    auto* item =
        new QListWidgetItem(prefix + text_of(d.message) +
                                (d.pointer.empty() ? QString() : QStringLiteral("  (%1)").arg(text_of(d.pointer))),
                            problems_);
    item->setIcon(style()->standardIcon(d.severity == Severity::error ? QStyle::SP_MessageBoxCritical
                                                                      : QStyle::SP_MessageBoxWarning));
    item->setData(Qt::UserRole, text_of(node));
  };
  for (const Diagnostic& d : disk_problems_) {
    const QString where =
        d.pos.line
            ? QStringLiteral("%1:%2:%3: ").arg(QFileInfo(text_of(d.file)).fileName()).arg(d.pos.line).arg(d.pos.column)
            : QString();
    list(d, {}, tr("file on disk: ") + where);
  }
  for (const Problem& p : validation_.problems) {
    list(p.diagnostic, p.node, p.node.empty() ? QString() : text_of(p.node) + QStringLiteral(": "));
    if (p.node.empty()) continue;
    NodeProblem& np = on_nodes[p.node];
    np.message += (np.message.isEmpty() ? QString() : QStringLiteral("\n")) + text_of(p.diagnostic.message);
    np.is_error = np.is_error || p.diagnostic.severity == Severity::error;
  }
  canvas_->show_problems(on_nodes);
  const int count = problems_->count();
  if (auto* dock = qobject_cast<QDockWidget*>(problems_->parentWidget()))
    dock->setWindowTitle(count ? tr("Problems (%1)").arg(count) : tr("Problems"));
}

void MainWindow::show_selection() {
  const std::set<std::string> selected = canvas_->selected_nodes();
  const std::string id = selected.size() == 1 ? *selected.begin() : std::string();
  params_->show_node(doc_->graph(), id, validation_.problems);
  // An env.load node's environment or a volume's probes go to the inspector when it is in view.
  const GraphNode* node = id.empty() ? nullptr : find_node(doc_->graph(), id);
  if (!node || !inspector_->isVisible()) return;
  if (node->type == "gi.irradiance_volume") return show_live_volume(id);
  if (node->type != "env.load") return;
  const JsonValue* path = node->params.find("path");
  std::string error;
  if (auto file = resolve_asset_path(doc_->graph().file, path && path->is_string() ? path->as_string() : "sky.hdr",
                                     AssetRoots{}, {".hdr", ".exr"}, &error))
    inspector_->open_environment(text_of(*file));
  else
    inspector_->show_message(text_of(error));
}

// Several volumes of the scene are one node's probes: the inspector's chooser picks among them.
// Several volume nodes each have their own, shown when that node is selected.
void MainWindow::show_live_volume(const std::string& node) {
  const std::string name = live_name(node);
  const auto found = live_probes_.find(node);
  if (found == live_probes_.end()) {
    live_node_.clear();
    const PlanNode* planned = nullptr;
    if (validation_.plan)
      for (const PlanNode& n : validation_.plan->nodes)
        if (n.id == node) planned = &n;
    QString why;
    if (!preview_runner_)
      why = tr("No preview is running, so '%1' has no probes to show. Inspect › Preview Scene… renders the graph on "
               "a scene with irradiance volumes (e.g. examples/worlds/cornell-box.json); its probes then show here.")
                .arg(text_of(node));
    else if (!validation_.plan)
      why = tr("The graph has errors, so the preview does not run '%1' (see Problems).").arg(text_of(node));
    else if (planned && planned->state != NodeState::Kind::active)
      why = tr("'%1' is %2 in the preview's plan: %3")
                .arg(text_of(node), text_of(std::string(node_state_name(planned->state))), text_of(planned->reason));
    else if (!preview_error_.isEmpty())
      why = tr("The preview failed, so '%1' has no probes: %2").arg(text_of(node), preview_error_);
    else
      why = tr("Waiting for the preview to bake the probes of '%1'…").arg(text_of(node));
    inspector_->show_message(why);
    return;
  }
  const ProbeSnapshot& live = *found->second;
  const ProbeBake* shown = inspector_->probe_bake();
  if (live_node_ == node && live_version_ == live.version && shown && shown->path == name) return;
  const std::optional<ProbeViewState> state = inspector_->probe_state();
  const int volume = shown && shown->path == name && state ? int(state->volume) : 0;
  auto bake = std::make_unique<ProbeBake>();
  bake->path = name;
  bake->file = live.file;
  bake->grids = probe_grids(bake->file);
  const QString note = live.dynamic ? tr("dynamic: %1 batches of updates since the bake").arg(live.batches_landed)
                                    : tr("static: baked again when the scene or the graph changes");
  // The probe view needs room beside its panel of maps: the dock widens once, when it opens one.
  if (live_node_.empty() && inspector_->width() < kProbeDockWidth)
    resizeDocks({qobject_cast<QDockWidget*>(inspector_->parentWidget())}, {kProbeDockWidth}, Qt::Horizontal);
  inspector_->show_probes(std::move(bake), volume, {true, note});
  live_node_ = node;
  live_version_ = live.version;
}

bool MainWindow::save_live_probes(const QString& path) {
  const auto found = live_probes_.find(live_node_);
  const ProbeBake* shown = inspector_->probe_bake();
  if (found == live_probes_.end() || !shown || shown->path != live_name(live_node_)) {
    statusBar()->showMessage(tr("No live probes to save: select a gi.irradiance_volume node while the preview runs"),
                             8000);
    return false;
  }
  try {
    write_probe_file(path.toStdString(), found->second->file);
  } catch (const BakeFileError& e) {
    statusBar()->showMessage(tr("Could not save the probes: %1").arg(text_of(e.what())));
    if (interactive_) QMessageBox::warning(this, tr("Could not save the probes"), text_of(e.what()));
    return false;
  }
  statusBar()->showMessage(
      tr("Saved the probes of '%1' to %2 (lumagraph-inspect --bake opens it)").arg(text_of(live_node_), path), 8000);
  return true;
}

void MainWindow::save_live_probes_dialog() {
  const QString folder = doc_->path().isEmpty() ? QString() : QFileInfo(doc_->path()).absolutePath();
  QString path =
      QFileDialog::getSaveFileName(this, tr("Save probes"), QDir(folder).filePath(text_of(live_node_) + ".lgprobes"),
                                   tr("Probe bakes (*.lgprobes)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(QStringLiteral(".lgprobes"))) path += QStringLiteral(".lgprobes");
  save_live_probes(path);
}

void MainWindow::add_node(const QString& type, std::optional<Position> at) {
  Graph graph = doc_->graph();
  const std::string id = editor::add_node(graph, type.toStdString(), at.value_or(canvas_->view_centre()));
  doc_->edit(std::move(graph), tr("Add %1").arg(text_of(id)));
  canvas_->select_nodes({id});
}

void MainWindow::edit_links(const std::vector<Link>& added, const std::vector<Link>& removed) {
  Graph graph = doc_->graph();
  for (const Link& l : removed) remove_link(graph, l.from, l.to);
  for (const Link& l : added) add_link(graph, l.from, l.to);
  const Link& any = added.empty() ? removed.front() : added.front();
  const QString what = added.empty() ? tr("Unlink %1 from %2") : tr("Link %1 to %2");
  doc_->edit(std::move(graph), what.arg(text_of(any.from.text()), text_of(any.to.text())));
}

void MainWindow::move_nodes(const std::map<std::string, Position>& positions) {
  Graph graph = doc_->graph();
  for (const auto& [id, p] : positions) set_node_position(graph, id, p);
  doc_->edit(std::move(graph), positions.size() == 1 ? tr("Move %1").arg(text_of(positions.begin()->first))
                                                     : tr("Move %1 nodes").arg(positions.size()));
}

void MainWindow::set_param(const std::string& node, const std::string& param, const JsonValue& value) {
  Graph graph = doc_->graph();
  editor::set_param(graph, node, param, value);
  const QString name = text_of(node + '.' + param);
  doc_->edit(std::move(graph), value.is_null() ? tr("Reset %1").arg(name) : tr("Set %1").arg(name), name);
}

void MainWindow::apply_preset(const std::string& node, int index) {
  const GraphNode* n = find_node(doc_->graph(), node);
  const NodeSchema* schema = n ? builtin_registry().find(n->type) : nullptr;
  if (!schema || index < 0 || size_t(index) >= schema->presets.size()) return;
  Graph graph = doc_->graph();
  editor::apply_preset(graph, node, *schema, schema->presets[index]);
  doc_->edit(std::move(graph), tr("Preset %1 on %2").arg(text_of(schema->presets[index].name), text_of(node)));
}

void MainWindow::delete_selection() {
  const std::set<std::string> nodes = canvas_->selected_nodes();
  const std::vector<Link> links = canvas_->selected_links();
  if (nodes.empty() && links.empty()) return;
  Graph graph = doc_->graph();
  for (const Link& l : links) remove_link(graph, l.from, l.to);
  remove_nodes(graph, nodes);
  doc_->edit(std::move(graph), nodes.empty() ? tr("Delete links") : tr("Delete %1 nodes").arg(nodes.size()));
}

void MainWindow::copy_selection() {
  const std::set<std::string> ids = canvas_->selected_nodes();
  if (ids.empty()) return;
  QApplication::clipboard()->setText(text_of(graph_to_text(extract_nodes(doc_->graph(), ids))));
  statusBar()->showMessage(tr("Copied %1 nodes").arg(ids.size()), 3000);
}

void MainWindow::paste() {
  Diagnostics ignored;
  std::optional<Graph> fragment = parse_graph_text(QApplication::clipboard()->text().toStdString(), ignored);
  if (!fragment || fragment->nodes.empty()) {
    statusBar()->showMessage(tr("The clipboard holds no nodes"), 3000);
    return;
  }
  Graph graph = doc_->graph();
  const std::vector<std::string> added = paste_nodes(graph, *fragment, {40, 40});
  doc_->edit(std::move(graph), tr("Paste %1 nodes").arg(added.size()));
  canvas_->select_nodes(added);
}

void MainWindow::arrange() {
  Graph graph = doc_->graph();
  for (const auto& [id, p] : canvas_->arranged_positions()) set_node_position(graph, id, p);
  doc_->edit(std::move(graph), tr("Arrange nodes"));
  canvas_->frame_all();
}

void MainWindow::show_menu(Position at, QPoint global) {
  QMenu menu(this);
  fill_node_menu(menu, builtin_registry());
  if (QAction* chosen = menu.exec(global); chosen && chosen->data().isValid()) add_node(chosen->data().toString(), at);
}

void MainWindow::set_preview(std::unique_ptr<PreviewRenderer> renderer) {
  scene_ = renderer->scene_summary();
  live_probes_.clear();  // the last scene's
  delete preview_runner_;
  preview_runner_ = new AsyncPreview(std::move(renderer), this);
  connect(preview_runner_, &AsyncPreview::finished, this, &MainWindow::show_preview);
  if (!preview_) {
    preview_ = new PreviewPanel(this);
    connect(preview_, &PreviewPanel::port_changed, this, &MainWindow::request_preview);
    auto* dock = new QDockWidget(tr("Preview"), this);
    dock->setObjectName(QStringLiteral("Preview"));
    dock->setWidget(preview_);
    addDockWidget(Qt::RightDockWidgetArea, dock);
  }
  refresh();
}

}  // namespace lg::editor
