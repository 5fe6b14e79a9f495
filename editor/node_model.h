// The QtNodes model of one graph node, made from its schema: ports named and typed as the schema
// says, painted in their type's colour, and the node's current problem shown under it. The
// editor's Graph is the truth; these models only present it (canvas.h keeps them in step).
#pragma once

#include <nodes/NodeDataModel>

#include "graph/schema.h"

namespace lg::editor {

class NodeModel : public QtNodes::NodeDataModel {
  Q_OBJECT
 public:
  // `schema` is null for a type the registry does not know: the node then has no ports.
  NodeModel(std::string id, std::string type, const NodeSchema* schema);

  const std::string& id() const { return id_; }
  const NodeSchema* schema() const { return schema_; }
  // The port spec of an index on one side, or null.
  const PortSpec* port(QtNodes::PortType side, int index) const;

  // All of the node's problems, one a line; the node shows how many.
  void set_problem(const QString& message, bool is_error);
  const QString& problem() const { return problem_; }

  QString caption() const override;
  QString name() const override;
  unsigned int nPorts(QtNodes::PortType side) const override;
  QString portCaption(QtNodes::PortType side, QtNodes::PortIndex index) const override;
  bool portCaptionVisible(QtNodes::PortType, QtNodes::PortIndex) const override { return true; }
  std::shared_ptr<QtNodes::NodeDataType> dataType(QtNodes::PortType side, QtNodes::PortIndex index) const override;
  std::unique_ptr<QtNodes::NodeDataModel> clone() const override;
  void setInData(std::shared_ptr<QtNodes::NodeData>, QtNodes::PortIndex) override {}
  std::shared_ptr<QtNodes::NodeData> outData(QtNodes::PortIndex) override { return nullptr; }
  QWidget* embeddedWidget() override { return nullptr; }
  QtNodes::NodeValidationState validationState() const override { return state_; }
  QString validationMessage() const override;
  QtNodes::NodePainterDelegate* painterDelegate() const override;

 private:
  std::string id_, type_;
  const NodeSchema* schema_;
  QString problem_;
  QtNodes::NodeValidationState state_ = QtNodes::NodeValidationState::Valid;
};

}  // namespace lg::editor
