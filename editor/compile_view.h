// The compile view: what the compiler made of the graph. The passes in execution order, the
// nodes it bypassed or culled and the passes it dropped (each with the reason), the resources'
// lifetimes and memory placement (timeline_widget.h), and the memory totals.
#pragma once

#include <QWidget>

#include "graph/plan.h"

class QLabel;
class QTableWidget;
class QTreeWidget;

namespace lg::editor {

class TimelineWidget;

class CompileView : public QWidget {
  Q_OBJECT
 public:
  explicit CompileView(QWidget* parent = nullptr);
  // Null: the graph does not compile; the view says so and keeps nothing stale.
  void show_plan(const Plan* plan);
  // Per-pass GPU times of the last preview frame (pass name, ms; negative: skipped as cached).
  void show_gpu_times(const std::vector<std::pair<std::string, double>>& pass_ms);

  QTableWidget* passes() const { return passes_; }
  QTreeWidget* skipped() const { return skipped_; }
  QLabel* totals() const { return totals_; }

 private:
  QTableWidget* passes_;
  QTreeWidget* skipped_;
  TimelineWidget* timeline_;
  QLabel* totals_;
};

}  // namespace lg::editor
