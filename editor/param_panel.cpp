#include "editor/param_panel.h"

#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QStringList>
#include <QToolButton>
#include <QVBoxLayout>

#include "editor/graph_edits.h"
#include "graph/json_writer.h"

namespace lg::editor {

static QString text_of(const std::string& s) {
  return QString::fromStdString(s);
}

static QString tooltip_of(const NodeSchema& schema, const ParamPreset& preset) {
  QStringList values;
  for (const auto& [param, value] : preset.values)
    values << QStringLiteral("%1 = %2").arg(text_of(schema.params[param].name), text_of(write_json_compact(value)));
  return text_of(preset.doc) + QStringLiteral("\n") + values.join(QStringLiteral(", "));
}

static QString tooltip_of(const ParamSpec& spec) {
  QString tip = text_of(spec.doc);
  if (spec.min || spec.max)
    tip += QStringLiteral("\nRange: %1 to %2")
               .arg(spec.min ? QString::number(*spec.min) : QStringLiteral("−∞"),
                    spec.max ? QString::number(*spec.max) : QStringLiteral("∞"));
  if (!spec.unit.empty()) tip += QStringLiteral(" (%1)").arg(text_of(spec.unit));
  return tip;
}

ParamPanel::ParamPanel(const Registry& registry, QWidget* parent)
    : QWidget(parent), registry_(registry), title_(new QLabel(this)), doc_(new QLabel), body_(new QWidget) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 8, 8, 8);
  QFont bold = title_->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.15);
  title_->setFont(bold);
  title_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  doc_->setWordWrap(true);
  doc_->setForegroundRole(QPalette::PlaceholderText);
  auto* body = new QVBoxLayout(body_);
  body->setContentsMargins(0, 0, 0, 0);
  body->addWidget(doc_);
  body->addStretch(1);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setWidget(body_);
  layout->addWidget(title_);
  layout->addWidget(scroll, 1);
  show_node(Graph(), {});
}

ParamEditor* ParamPanel::editor(const std::string& param) const {
  auto it = editors_.find(param);
  return it == editors_.end() ? nullptr : it->second;
}

void ParamPanel::show_node(const Graph& graph, const std::string& id, const std::vector<Problem>& problems) {
  const GraphNode* node = id.empty() ? nullptr : find_node(graph, id);
  if (!node || node->id != node_id_ || node->type != node_type_) rebuild(graph, node);
  if (!node) return;
  const NodeSchema* schema = registry_.find(node->type);
  if (presets_ && schema) presets_->setCurrentIndex(matching_preset(*node, *schema) + 1);
  std::map<std::string, QString> wrong;
  for (const Problem& p : problems)
    if (p.node == id)
      if (const std::string param = param_of_pointer(p.diagnostic.pointer); !param.empty())
        wrong[param] += QString::fromStdString(p.diagnostic.message);
  for (const ParamSpec& spec : schema ? schema->params : std::vector<ParamSpec>{}) {
    const JsonValue* set = node->params.find(spec.name);
    editors_[spec.name]->set_value(set ? *set : spec.default_value);
    resets_[spec.name]->setVisible(set != nullptr);
    QLabel* label = labels_[spec.name];
    const bool bad = wrong.count(spec.name) > 0;
    // The editor cannot show a value outside its range: the label says the file holds one.
    label->setText(bad ? QStringLiteral("<span style='color:#e0413a'>⚠ %1</span>").arg(text_of(spec.name))
                       : text_of(spec.name));
    label->setToolTip(bad ? wrong[spec.name] : tooltip_of(spec));
  }
}

void ParamPanel::rebuild(const Graph& graph, const GraphNode* node) {
  delete form_host_;
  form_host_ = nullptr;
  presets_ = nullptr;
  editors_.clear();
  resets_.clear();
  labels_.clear();
  node_id_ = node ? node->id : std::string();
  node_type_ = node ? node->type : std::string();
  const NodeSchema* schema = node ? registry_.find(node->type) : nullptr;
  if (!node) {
    title_->setText(tr("No node selected"));
    doc_->setText(tr("Select one node to edit its parameters."));
    return;
  }
  title_->setText(QStringLiteral("%1  ·  %2").arg(text_of(node->id), text_of(node->type)));
  doc_->setText(schema ? text_of(schema->doc) : tr("Unknown node type: no parameters to show."));
  if (!schema) return;

  form_host_ = new QWidget(body_);
  form_ = new QFormLayout(form_host_);
  form_->setContentsMargins(0, 0, 0, 8);
  form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  if (!schema->presets.empty()) {
    presets_ = new QComboBox(form_host_);
    presets_->addItem(tr("custom"));
    presets_->setItemData(0, tr("The params match no preset."), Qt::ToolTipRole);
    for (const ParamPreset& preset : schema->presets) {
      presets_->addItem(text_of(preset.name));
      presets_->setItemData(presets_->count() - 1, tooltip_of(*schema, preset), Qt::ToolTipRole);
    }
    presets_->setToolTip(tr("Sets the params a preset names, as one edit."));
    // activated: the user's choice only, not the panel following the document.
    connect(presets_, qOverload<int>(&QComboBox::activated), this, [this](int item) {
      if (item > 0) emit preset_chosen(node_id_, item - 1);
    });
    form_->addRow(new QLabel(tr("preset"), form_host_), presets_);
  }
  const QString dir = graph.file.empty() ? QString() : QFileInfo(text_of(graph.file)).absolutePath();
  for (const ParamSpec& spec : schema->params) {
    ParamEditor* editor = make_param_editor(spec, dir, form_host_);
    auto* reset = new QToolButton(form_host_);
    reset->setText(QStringLiteral("↺"));
    reset->setAutoRaise(true);
    reset->setToolTip(tr("Back to the default"));
    auto* field = new QWidget(form_host_);
    auto* row = new QHBoxLayout(field);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(editor, 1);
    row->addWidget(reset);
    auto* name = new QLabel(text_of(spec.name), form_host_);
    name->setToolTip(tooltip_of(spec));
    editor->setToolTip(tooltip_of(spec));
    form_->addRow(name, field);
    editors_[spec.name] = editor;
    resets_[spec.name] = reset;
    labels_[spec.name] = name;
    const std::string param = spec.name;
    connect(editor, &ParamEditor::edited, this,
            [this, param](const JsonValue& v) { emit param_edited(node_id_, param, v); });
    connect(reset, &QToolButton::clicked, this, [this, param] { emit param_edited(node_id_, param, JsonValue()); });
  }
  static_cast<QVBoxLayout*>(body_->layout())->insertWidget(0, form_host_);
}

}  // namespace lg::editor
