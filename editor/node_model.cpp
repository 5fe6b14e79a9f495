#include "editor/node_model.h"

#include <nodes/NodePainterDelegate>

#include "editor/port_colors.h"

namespace lg::editor {

using QtNodes::PortType;

namespace {

// Paints each port's dot in its type's colour over QtNodes' uniform ones.
class PortColorDelegate : public QtNodes::NodePainterDelegate {
 public:
  void paint(QPainter* painter, const QtNodes::NodeGeometry& geometry, const QtNodes::NodeDataModel* model) override {
    const auto* node = static_cast<const NodeModel*>(model);
    painter->setPen(QPen(QColor(20, 20, 24), 1.2));
    for (PortType side : {PortType::In, PortType::Out})
      for (unsigned i = 0; i < node->nPorts(side); ++i) {
        const PortSpec* spec = node->port(side, int(i));
        painter->setBrush(port_color(spec->type));
        const double r = spec->optional ? 4.0 : 5.0;
        painter->drawEllipse(geometry.portScenePosition(int(i), side), r, r);
      }
  }
};

// QtNodes connects only ports of equal type ids: every port shares one, and the canvas checks
// the real types itself so that a refused link can say why.
const QString any_port = QStringLiteral("lumagraph.port");

}  // namespace

NodeModel::NodeModel(std::string id, std::string type, const NodeSchema* schema)
    : id_(std::move(id)), type_(std::move(type)), schema_(schema) {}

const PortSpec* NodeModel::port(PortType side, int index) const {
  if (!schema_ || index < 0) return nullptr;
  const auto& ports = side == PortType::In ? schema_->inputs : schema_->outputs;
  return size_t(index) < ports.size() ? &ports[size_t(index)] : nullptr;
}

void NodeModel::set_problem(const QString& message, bool is_error) {
  problem_ = message;
  state_ = message.isEmpty() ? QtNodes::NodeValidationState::Valid
           : is_error        ? QtNodes::NodeValidationState::Error
                             : QtNodes::NodeValidationState::Warning;
}

QString NodeModel::validationMessage() const {
  // QtNodes draws it on one line as wide as it is: a count keeps nodes their size, and the
  // tooltip and the Problems list have the words.
  const qsizetype n = problem_.split('\n', Qt::SkipEmptyParts).size();
  if (n == 0) return {};
  const bool error = state_ == QtNodes::NodeValidationState::Error;
  return n == 1 ? (error ? tr("1 error") : tr("1 warning")) : (error ? tr("%1 errors") : tr("%1 warnings")).arg(n);
}

QString NodeModel::caption() const {
  const QString id = QString::fromStdString(id_), type = QString::fromStdString(type_);
  return schema_ ? QStringLiteral("%1  ·  %2").arg(id, type) : QStringLiteral("%1  ·  %2 (unknown type)").arg(id, type);
}

QString NodeModel::name() const {
  return QString::fromStdString(type_);
}

unsigned int NodeModel::nPorts(PortType side) const {
  if (!schema_) return 0;
  return unsigned(side == PortType::In ? schema_->inputs.size() : side == PortType::Out ? schema_->outputs.size() : 0);
}

QString NodeModel::portCaption(PortType side, QtNodes::PortIndex index) const {
  const PortSpec* spec = port(side, index);
  if (!spec) return {};
  QString text = QString::fromStdString(spec->name);
  if (spec->history) text += QStringLiteral(" (previous frame)");
  return text;
}

std::shared_ptr<QtNodes::NodeDataType> NodeModel::dataType(PortType side, QtNodes::PortIndex index) const {
  const PortSpec* spec = port(side, index);
  return std::make_shared<QtNodes::NodeDataType>(any_port,
                                                 spec ? QString::fromStdString(spec->type.name()) : QString());
}

std::unique_ptr<QtNodes::NodeDataModel> NodeModel::clone() const {
  return std::make_unique<NodeModel>(id_, type_, schema_);
}

QtNodes::NodePainterDelegate* NodeModel::painterDelegate() const {
  static PortColorDelegate delegate;
  return &delegate;
}

}  // namespace lg::editor
