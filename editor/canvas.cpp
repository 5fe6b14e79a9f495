#include "editor/canvas.h"

#include <QContextMenuEvent>
#include <QCursor>
#include <QTimer>
#include <QToolTip>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>
#include <nodes/Connection>
#include <nodes/FlowScene>
#include <nodes/FlowView>
#include <nodes/Node>
#include <nodes/internal/ConnectionGraphicsObject.hpp>

#include "editor/layout.h"
#include "editor/node_model.h"

namespace lg::editor {

using QtNodes::PortType;

namespace {

// FlowView with its own node menu and delete replaced by the canvas's, and a hook for the end
// of a drag (where moves become one undo step).
class CanvasView : public QtNodes::FlowView {
 public:
  using FlowView::FlowView;
  std::function<void(QPointF, QPoint)> on_menu;
  std::function<void()> on_delete, on_release;

  void deleteSelectedNodes() override { on_delete(); }

 protected:
  void contextMenuEvent(QContextMenuEvent* event) override {
    // A node's own menu first (QtNodes has none we use), else ours.
    if (itemAt(event->pos()) && dynamic_cast<QGraphicsObject*>(itemAt(event->pos()))) return;
    on_menu(mapToScene(event->pos()), event->globalPos());
  }
  void mouseReleaseEvent(QMouseEvent* event) override {
    FlowView::mouseReleaseEvent(event);
    on_release();
  }
};

bool same_link(const Link& a, const Link& b) {
  return a.from.node == b.from.node && a.from.port == b.from.port && a.to.node == b.to.node && a.to.port == b.to.port;
}

bool contains(const std::vector<Link>& links, const Link& l) {
  return std::any_of(links.begin(), links.end(), [&](const Link& x) { return same_link(x, l); });
}

// The schema's doc and every port with its type: what the canvas cannot spell out.
QString node_tooltip(const std::string& type, const NodeSchema* schema) {
  if (!schema) return QStringLiteral("Unknown node type %1").arg(QString::fromStdString(type));
  QString tip = QStringLiteral("<b>%1</b><br>%2")
                    .arg(QString::fromStdString(type), QString::fromStdString(schema->doc).toHtmlEscaped());
  auto ports = [&](const char* title, const std::vector<PortSpec>& list) {
    if (list.empty()) return;
    tip += QStringLiteral("<br><br><i>%1</i>").arg(QString::fromUtf8(title));
    for (const PortSpec& p : list)
      tip += QStringLiteral("<br>%1 <tt>%2</tt>%3 — %4")
                 .arg(QString::fromStdString(p.name), QString::fromStdString(p.type.name()),
                      p.optional ? QStringLiteral(" (optional)") : QString(),
                      QString::fromStdString(p.doc).toHtmlEscaped());
  };
  ports("inputs", schema->inputs);
  ports("outputs", schema->outputs);
  return tip;
}

const NodeModel* model_of(const QtNodes::Node* node) {
  return static_cast<const NodeModel*>(node->nodeDataModel());
}

std::optional<Link> link_of(const QtNodes::Connection& c) {
  if (!c.complete()) return std::nullopt;
  const NodeModel* out = model_of(c.getNode(PortType::Out));
  const NodeModel* in = model_of(c.getNode(PortType::In));
  const PortSpec* from = out->port(PortType::Out, c.getPortIndex(PortType::Out));
  const PortSpec* to = in->port(PortType::In, c.getPortIndex(PortType::In));
  if (!from || !to) return std::nullopt;
  return Link{{out->id(), from->name}, {in->id(), to->name}};
}

}  // namespace

Canvas::Canvas(const Registry& registry, QWidget* parent)
    : QWidget(parent), registry_(registry), scene_(new QtNodes::FlowScene(this)) {
  auto* view = new CanvasView(scene_, this);
  view_ = view;
  view->on_menu = [this](QPointF at, QPoint global) { emit menu_requested({at.x(), at.y()}, global); };
  view->on_delete = [this] { emit delete_requested(); };
  view->on_release = [this] { check_moves(); };
  // The window's Edit > Delete owns the key; two actions on one shortcut would both be dead.
  view->removeAction(view->deleteSelectionAction());
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view_);

  connect(scene_, &QtNodes::FlowScene::connectionCreated, this, &Canvas::schedule_link_check);
  connect(scene_, &QtNodes::FlowScene::connectionDeleted, this, &Canvas::schedule_link_check);
  connect(scene_, &QGraphicsScene::selectionChanged, this, &Canvas::selection_changed);
}

Canvas::~Canvas() {
  // The scene's nodes and connections signal as they go; nobody must listen by then.
  disconnect(scene_, nullptr, this, nullptr);
}

QtNodes::Node* Canvas::node(const std::string& id) const {
  auto it = nodes_.find(id);
  return it == nodes_.end() ? nullptr : it->second;
}

Position Canvas::node_size(const std::string& id) const {
  QtNodes::Node* n = node(id);
  if (!n) return {200, 100};
  const QSizeF s = scene_->getNodeSize(*n);
  return {s.width(), s.height()};
}

void Canvas::show_graph(const Graph& graph) {
  syncing_ = true;
  shown_graph_ = graph;
  // Nodes: remove the ones gone (or whose type changed), add the new ones.
  for (auto it = nodes_.begin(); it != nodes_.end();) {
    const GraphNode* n = find_node(graph, it->first);
    if (n && model_of(it->second)->name().toStdString() == n->type) {
      ++it;
      continue;
    }
    scene_->removeNode(*it->second);
    it = nodes_.erase(it);
  }
  for (const GraphNode& n : graph.nodes)
    if (!nodes_.count(n.id)) {
      const NodeSchema* schema = registry_.find(n.type);
      nodes_[n.id] = &scene_->createNode(std::make_unique<NodeModel>(n.id, n.type, schema));
      nodes_[n.id]->nodeGraphicsObject().setToolTip(node_tooltip(n.type, schema));
    }

  // Positions: the file's, else the default layout.
  std::map<std::string, Position> layout;
  for (const GraphNode& n : graph.nodes)
    if (!node_position(graph, n.id)) {
      layout = arranged_positions();
      break;
    }
  for (const GraphNode& n : graph.nodes) {
    const Position p = node_position(graph, n.id).value_or(layout[n.id]);
    if (scene_->getNodePosition(*nodes_[n.id]) != QPointF(p[0], p[1]))
      scene_->setNodePosition(*nodes_[n.id], {p[0], p[1]});
  }

  // Links: those of the graph that name real ports.
  shown_links_.clear();
  for (const GraphLink& l : graph.links) {
    QtNodes::Node *out = node(l.from.node), *in = node(l.to.node);
    const NodeSchema *from = out ? model_of(out)->schema() : nullptr, *to = in ? model_of(in)->schema() : nullptr;
    if (from && to && from->find_output(l.from.port) >= 0 && to->find_input(l.to.port) >= 0)
      shown_links_.push_back({l.from, l.to});
  }
  std::vector<Link> present;
  std::vector<std::shared_ptr<QtNodes::Connection>> extra;
  for (const auto& [id, c] : scene_->connections()) {
    std::optional<Link> link = link_of(*c);
    if (!c->complete()) continue;  // being dragged by the user
    if (link && contains(shown_links_, *link) && !contains(present, *link))
      present.push_back(*link);
    else
      extra.push_back(c);
  }
  for (const auto& c : extra) scene_->deleteConnection(*c);
  for (const Link& l : shown_links_)
    if (!contains(present, l)) {
      QtNodes::Node *out = node(l.from.node), *in = node(l.to.node);
      scene_->createConnection(*in, model_of(in)->schema()->find_input(l.to.port), *out,
                               model_of(out)->schema()->find_output(l.from.port));
    }
  synced_positions_ = shown_positions();
  syncing_ = false;
}

void Canvas::show_problems(const std::map<std::string, NodeProblem>& problems) {
  for (auto& [id, n] : nodes_) {
    auto it = problems.find(id);
    auto* model = static_cast<NodeModel*>(n->nodeDataModel());
    const QString message = it == problems.end() ? QString() : it->second.message;
    if (model->problem() == message) continue;
    model->set_problem(message, it == problems.end() || it->second.is_error);
    n->nodeGraphicsObject().setToolTip(node_tooltip(model->name().toStdString(), model->schema()) +
                                       (message.isEmpty() ? QString()
                                                          : QStringLiteral("<br><br><b>Problems</b><br>") +
                                                                message.toHtmlEscaped().replace('\n', "<br>")));
    n->nodeGeometry().recalculateSize();
    n->nodeGraphicsObject().setGeometryChanged();
    n->nodeGraphicsObject().update();
    n->nodeGraphicsObject().moveConnections();
  }
}

std::vector<Link> Canvas::scene_links() const {
  std::vector<Link> links;
  for (const auto& [id, c] : scene_->connections())
    if (std::optional<Link> l = link_of(*c)) links.push_back(*l);
  return links;
}

void Canvas::schedule_link_check() {
  // QtNodes signals from inside its own mouse handling: look once it is done.
  if (syncing_ || check_pending_) return;
  check_pending_ = true;
  QTimer::singleShot(0, this, &Canvas::check_links);
}

void Canvas::check_links() {
  check_pending_ = false;
  const std::vector<Link> now = scene_links();
  std::vector<Link> added, removed;
  QString refused;
  for (const Link& l : now) {
    if (contains(shown_links_, l) || contains(added, l)) continue;
    const PortSpec* from = model_of(node(l.from.node))
                               ->port(PortType::Out, model_of(node(l.from.node))->schema()->find_output(l.from.port));
    const PortSpec* to =
        model_of(node(l.to.node))->port(PortType::In, model_of(node(l.to.node))->schema()->find_input(l.to.port));
    std::string why;
    if (port_types_compatible(from->type, to->type, &why))
      added.push_back(l);
    else
      refused = QStringLiteral("Cannot link %1 to %2: %3")
                    .arg(QString::fromStdString(l.from.text()), QString::fromStdString(l.to.text()),
                         QString::fromStdString(why));
  }
  for (const Link& l : shown_links_)
    if (!contains(now, l)) removed.push_back(l);
  if (!refused.isEmpty()) {
    QToolTip::showText(QCursor::pos(), refused, view_);
    emit link_refused(refused);
  }
  if (!added.empty() || !removed.empty()) emit links_edited(added, removed);
  if (!refused.isEmpty()) show_graph(Graph(shown_graph_));
}

void Canvas::check_moves() {
  std::map<std::string, Position> moved;
  for (const auto& [id, p] : shown_positions()) {
    auto it = synced_positions_.find(id);
    if (it == synced_positions_.end() || std::abs(it->second[0] - p[0]) >= 0.5 || std::abs(it->second[1] - p[1]) >= 0.5)
      moved[id] = p;
  }
  if (!moved.empty()) emit nodes_moved(moved);
}

std::map<std::string, Position> Canvas::shown_positions() const {
  std::map<std::string, Position> p;
  for (const auto& [id, n] : nodes_) {
    const QPointF xy = scene_->getNodePosition(*n);
    p[id] = {xy.x(), xy.y()};
  }
  return p;
}

std::map<std::string, Position> Canvas::arranged_positions() const {
  return layered_layout(shown_graph_, [this](const std::string& id) { return node_size(id); });
}

std::set<std::string> Canvas::selected_nodes() const {
  std::set<std::string> ids;
  for (QtNodes::Node* n : scene_->selectedNodes()) ids.insert(model_of(n)->id());
  return ids;
}

std::vector<Link> Canvas::selected_links() const {
  std::vector<Link> links;
  for (QGraphicsItem* item : scene_->selectedItems())
    if (auto* c = dynamic_cast<QtNodes::ConnectionGraphicsObject*>(item))
      if (std::optional<Link> l = link_of(c->connection())) links.push_back(*l);
  return links;
}

void Canvas::select_nodes(const std::vector<std::string>& ids) {
  scene_->clearSelection();
  for (const std::string& id : ids)
    if (QtNodes::Node* n = node(id)) n->nodeGraphicsObject().setSelected(true);
}

// FlowView pans by moving the scene rect (it is the size of the view), so centring is that too.
void Canvas::look_at(QPointF centre) {
  const QRectF view = view_->mapToScene(view_->viewport()->rect()).boundingRect();
  QRectF rect(QPointF(), view.size());
  rect.moveCenter(centre);
  scene_->setSceneRect(rect);
  view_->centerOn(centre);
}

void Canvas::centre_on(const std::string& id) {
  if (QtNodes::Node* n = node(id)) look_at(n->nodeGraphicsObject().sceneBoundingRect().center());
}

void Canvas::frame_all() {
  QRectF bounds;
  for (const auto& [id, n] : nodes_) bounds |= n->nodeGraphicsObject().sceneBoundingRect();
  if (bounds.isEmpty()) return;
  bounds.adjust(-40, -40, 40, 40);
  const QSize port = view_->viewport()->size();
  // Small graphs stay at their natural size rather than blown up.
  const double scale = std::min({1.0, port.width() / bounds.width(), port.height() / bounds.height()});
  view_->resetTransform();
  view_->scale(scale, scale);
  look_at(bounds.center());
}

Position Canvas::view_centre() const {
  const QPointF c = view_->mapToScene(view_->viewport()->rect().center());
  return {c.x() - 100, c.y() - 50};
}

}  // namespace lg::editor
