#include "editor/compile_view.h"

#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "editor/timeline_widget.h"
#include "graph/plan_format.h"

namespace lg::editor {

static QString text_of(const std::string& s) {
  return QString::fromStdString(s);
}

CompileView::CompileView(QWidget* parent)
    : QWidget(parent),
      passes_(new QTableWidget(this)),
      skipped_(new QTreeWidget(this)),
      timeline_(new TimelineWidget(this)),
      totals_(new QLabel(this)) {
  passes_->setColumnCount(6);
  passes_->setHorizontalHeaderLabels(
      {tr("pass"), tr("node type"), tr("queue"), tr("cache"), tr("GPU ms (preview)"), tr("writes")});
  passes_->horizontalHeader()->setStretchLastSection(true);
  passes_->verticalHeader()->setDefaultSectionSize(22);
  passes_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  passes_->setSelectionBehavior(QAbstractItemView::SelectRows);
  skipped_->setColumnCount(2);
  skipped_->setHeaderLabels({tr("skipped"), tr("why")});
  skipped_->setRootIsDecorated(false);

  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(passes_);
  split->addWidget(skipped_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  auto* tabs = new QTabWidget(this);
  tabs->addTab(split, tr("Passes"));
  tabs->addTab(timeline_, tr("Memory"));
  totals_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(tabs, 1);
  layout->addWidget(totals_);
  show_plan(nullptr);
}

void CompileView::show_gpu_times(const std::vector<std::pair<std::string, double>>& pass_ms) {
  for (int row = 0; row < passes_->rowCount(); ++row) {
    const QTableWidgetItem* pass = passes_->item(row, 0);
    QTableWidgetItem* cell = passes_->item(row, 4);
    if (!pass || !cell) continue;
    cell->setText(QString());
    for (const auto& [name, ms] : pass_ms)
      if (text_of(name) == pass->text()) cell->setText(ms < 0 ? tr("cached") : QString::number(ms, 'f', 2));
  }
}

void CompileView::show_plan(const Plan* plan) {
  timeline_->show_plan(plan);
  passes_->setRowCount(0);
  skipped_->clear();
  if (!plan) {
    totals_->setText(tr("The graph does not compile: see Problems."));
    return;
  }
  passes_->setRowCount(int(plan->passes.size()));
  QStringList positions;  // schedule positions count from 0, as in the timeline and the CLI
  for (size_t i = 0; i < plan->passes.size(); ++i) positions << QString::number(i);
  passes_->setVerticalHeaderLabels(positions);
  for (size_t i = 0; i < plan->passes.size(); ++i) {
    const PlanPass& pass = plan->passes[i];
    QStringList writes;
    for (const PlanAccess& a : plan->accesses_of(pass))
      if (usage_writes(a.usage)) writes << text_of(plan->resources[size_t(a.resource)].desc.name);
    writes.removeDuplicates();
    const QStringList cells = {text_of(pass.name), text_of(plan->nodes[size_t(pass.node)].type),
                               pass.queue == Queue::graphics ? tr("graphics") : tr("compute"),
                               pass.is_static ? tr("static") : QStringLiteral("–"), QString(),
                               writes.join(QStringLiteral(", "))};
    for (int c = 0; c < cells.size(); ++c) passes_->setItem(int(i), c, new QTableWidgetItem(cells[c]));
  }
  passes_->resizeColumnsToContents();
  for (const PlanNode& n : plan->nodes) {
    const QString who = QStringLiteral("%1 (%2)").arg(text_of(n.id), text_of(n.type));
    if (n.state == NodeState::Kind::bypassed)
      new QTreeWidgetItem(skipped_, {tr("bypassed: %1").arg(who), text_of(n.reason)});
    else if (n.state == NodeState::Kind::culled)
      new QTreeWidgetItem(skipped_, {tr("culled: %1").arg(who), text_of(n.reason)});
    for (const auto& [pass, why] : n.dropped)
      new QTreeWidgetItem(skipped_, {tr("pass dropped: %1/%2").arg(text_of(n.id), text_of(pass)), text_of(why)});
  }
  if (skipped_->topLevelItemCount() == 0) new QTreeWidgetItem(skipped_, {tr("nothing skipped"), QString()});
  skipped_->resizeColumnToContents(0);
  const MemoryTotals& m = plan->memory;
  const double saved =
      m.transient_unaliased ? 100.0 * double(m.transient_unaliased - m.transient) / double(m.transient_unaliased) : 0;
  totals_->setText(
      tr("%1 passes at %2x%3 · transient %4 with aliasing, %5 without (saves %6%) · persistent %7 · %8 barriers")
          .arg(plan->passes.size())
          .arg(plan->frame.width)
          .arg(plan->frame.height)
          .arg(text_of(format_bytes(m.transient)), text_of(format_bytes(m.transient_unaliased)))
          .arg(saved, 0, 'f', 1)
          .arg(text_of(format_bytes(m.persistent)))
          .arg(plan->barriers.size()));
}

}  // namespace lg::editor
