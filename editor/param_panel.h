// The parameter panel of the selected node, generated from its schema: a preset combo when the
// schema lists presets (showing the preset the params match, or "custom"), one editor per param
// (param_widgets.h) with the doc line as tooltip and a reset button when the file sets the
// param. It rebuilds only when another node is shown, so a slider keeps its grab while the
// edits it makes come back through the document.
#pragma once

#include <QWidget>
#include <map>

#include "editor/param_widgets.h"
#include "editor/validation.h"
#include "graph/graph.h"
#include "graph/registry.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QToolButton;

namespace lg::editor {

class ParamPanel : public QWidget {
  Q_OBJECT
 public:
  ParamPanel(const Registry& registry, QWidget* parent = nullptr);

  // Shows node `id` of `graph` (nothing when empty or absent); params that `problems` name
  // are marked, with the message as their tooltip.
  void show_node(const Graph& graph, const std::string& id, const std::vector<Problem>& problems = {});
  ParamEditor* editor(const std::string& param) const;
  // The preset combo of the node shown: item 0 "custom", then the schema's presets; null when
  // it has none.
  QComboBox* presets() const { return presets_; }

 signals:
  // A null value means "back to the schema default".
  void param_edited(const std::string& node, const std::string& param, const lg::JsonValue& value);
  // The user chose preset `index` of the node's schema.
  void preset_chosen(const std::string& node, int index);

 private:
  void rebuild(const Graph& graph, const GraphNode* node);

  const Registry& registry_;
  std::string node_id_, node_type_;
  QLabel* title_;
  QLabel* doc_;
  // Scrolled below the title: the params, then the node's description (long ones never squash
  // the params' rows, and the params come first).
  QWidget* body_;
  QWidget* form_host_ = nullptr;
  QFormLayout* form_ = nullptr;
  QComboBox* presets_ = nullptr;
  std::map<std::string, ParamEditor*> editors_;
  std::map<std::string, QToolButton*> resets_;
  std::map<std::string, QLabel*> labels_;
};

}  // namespace lg::editor
