// Editors for one parameter, chosen by its schema type: slider and spin box with range and unit
// for numbers, a combo box for enums, a check box for bools, a line with a file picker for
// paths, one spin box per component for vectors. Each reports edits as the JSON value to store.
#pragma once

#include <QWidget>

#include "graph/schema.h"

namespace lg::editor {

class ParamEditor : public QWidget {
  Q_OBJECT
 public:
  using QWidget::QWidget;
  // Shows `value` without reporting it as an edit.
  virtual void set_value(const JsonValue& value) = 0;

 signals:
  void edited(const lg::JsonValue& value);
};

// `graph_dir` is where a picked file is made relative to (empty: keep it absolute).
ParamEditor* make_param_editor(const ParamSpec& spec, const QString& graph_dir, QWidget* parent);

}  // namespace lg::editor
