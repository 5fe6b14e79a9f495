// The node canvas: a QtNodes scene that shows the document's Graph and turns what the user does
// there (linking ports, unlinking, dragging nodes, deleting, asking for a menu) into requests for
// the document. The scene is never the truth: after every change show_graph() brings it back in
// step with the graph by difference, so undo, redo, reload and paste all take the same path.
#pragma once

#include <QWidget>
#include <map>
#include <set>
#include <vector>

#include "editor/graph_edits.h"
#include "graph/registry.h"

namespace QtNodes {
class FlowScene;
class FlowView;
class Node;
}  // namespace QtNodes

namespace lg::editor {

struct Link {
  PortRef from, to;
};

struct NodeProblem {
  QString message;
  bool is_error = true;
};

class Canvas : public QWidget {
  Q_OBJECT
 public:
  Canvas(const Registry& registry, QWidget* parent = nullptr);
  ~Canvas() override;

  void show_graph(const Graph& graph);
  void show_problems(const std::map<std::string, NodeProblem>& problems);

  std::set<std::string> selected_nodes() const;
  std::vector<Link> selected_links() const;
  void select_nodes(const std::vector<std::string>& ids);
  void centre_on(const std::string& id);
  void frame_all();
  // Where a node pasted or added from the palette goes: the middle of what is in view.
  Position view_centre() const;
  // Positions of every node as shown (file positions, or the default layout where it has none).
  std::map<std::string, Position> shown_positions() const;
  // A tidy layout of the whole graph from the nodes' real sizes.
  std::map<std::string, Position> arranged_positions() const;

  QtNodes::FlowScene* scene() const { return scene_; }
  QtNodes::FlowView* view() const { return view_; }
  QtNodes::Node* node(const std::string& id) const;

 signals:
  // The user changed links on the canvas; refused ones (type mismatch) are not among them.
  void links_edited(std::vector<lg::editor::Link> added, std::vector<lg::editor::Link> removed);
  void link_refused(const QString& why);
  void nodes_moved(std::map<std::string, lg::editor::Position> positions);
  void delete_requested();
  void menu_requested(lg::editor::Position scene_pos, QPoint global_pos);
  void selection_changed();

 private:
  void look_at(QPointF centre);
  void schedule_link_check();
  void check_links();
  void check_moves();
  std::vector<Link> scene_links() const;
  Position node_size(const std::string& id) const;

  const Registry& registry_;
  QtNodes::FlowScene* scene_;
  QtNodes::FlowView* view_;
  std::map<std::string, QtNodes::Node*> nodes_;
  std::vector<Link> shown_links_;  // the graph's links that the scene can draw
  Graph shown_graph_;
  std::map<std::string, Position> synced_positions_;
  bool syncing_ = false, check_pending_ = false;
};

}  // namespace lg::editor
