// Resource lifetimes drawn against memory: x is the schedule position (pass index), y the byte
// offset inside a memory block, so resources that alias are boxes stacked in the same rows at
// different times. Block 0 (frame-transient, aliased) is drawn above block 1 (persistent).
#pragma once

#include <QWidget>

#include "graph/plan.h"

namespace lg::editor {

class TimelineWidget : public QWidget {
  Q_OBJECT
 public:
  using QWidget::QWidget;
  void show_plan(const Plan* plan);
  QSize sizeHint() const override { return {800, 320}; }

 protected:
  void paintEvent(QPaintEvent*) override;
  bool event(QEvent* e) override;

 private:
  struct Box {
    QRectF rect;
    int resource;
  };
  std::vector<Box> layout_boxes() const;

  std::optional<Plan> plan_;
};

}  // namespace lg::editor
