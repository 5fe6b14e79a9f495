// The node palette, built from the registry: node types by category with a search box that
// matches type names and docs; double-click or Enter adds the type. The same list fills the
// canvas's right-click menu.
#pragma once

#include <QWidget>

#include "graph/registry.h"

class QLineEdit;
class QMenu;
class QTreeWidget;

namespace lg::editor {

class Palette : public QWidget {
  Q_OBJECT
 public:
  Palette(const Registry& registry, QWidget* parent = nullptr);

  void set_filter(const QString& text);
  // Node types now listed, in order (what the search leaves).
  QStringList visible_types() const;

 signals:
  void add_requested(const QString& type);

 private:
  QLineEdit* search_;
  QTreeWidget* tree_;
};

// One submenu per category, one action per type with the type name as data.
void fill_node_menu(QMenu& menu, const Registry& registry);

}  // namespace lg::editor
