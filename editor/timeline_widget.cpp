#include "editor/timeline_widget.h"

#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>
#include <cmath>
#include <map>

#include "graph/plan_format.h"

namespace lg::editor {

namespace {
constexpr double left = 110, top = 24, right = 16, bottom = 28, block_gap = 26;
}

void TimelineWidget::show_plan(const Plan* plan) {
  if (plan)
    plan_ = *plan;
  else
    plan_.reset();
  update();
}

std::vector<TimelineWidget::Box> TimelineWidget::layout_boxes() const {
  std::vector<Box> boxes;
  if (!plan_ || plan_->passes.empty()) return boxes;
  const double pass_w = (width() - left - right) / double(plan_->passes.size());
  // Each block gets height in proportion to its size, but never less than a sliver.
  double total = 0;
  for (const MemoryBlock& b : plan_->blocks) total += double(std::max<uint64_t>(b.size, 1));
  const double h = height() - top - bottom - block_gap * double(plan_->blocks.size() - 1);
  std::vector<double> y0(plan_->blocks.size()), scale(plan_->blocks.size()), weight(plan_->blocks.size());
  double weights = 0;
  for (size_t b = 0; b < plan_->blocks.size(); ++b)
    weights += weight[b] = std::max(0.15, double(std::max<uint64_t>(plan_->blocks[b].size, 1)) / total);
  double y = top;
  for (size_t b = 0; b < plan_->blocks.size(); ++b) {
    const double bh = h * weight[b] / weights;
    y0[b] = y;
    scale[b] = bh / double(std::max<uint64_t>(plan_->blocks[b].size, 1));
    y += bh + block_gap;
  }
  for (size_t r = 0; r < plan_->resources.size(); ++r) {
    const PlanResource& res = plan_->resources[r];
    if (res.placement.block < 0 || res.first < 0) continue;
    const auto b = size_t(res.placement.block);
    boxes.push_back({QRectF(left + res.first * pass_w, y0[b] + double(res.placement.offset) * scale[b],
                            (res.last - res.first + 1) * pass_w, std::max(2.0, double(res.placement.size) * scale[b])),
                     int(r)});
  }
  return boxes;
}

void TimelineWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), palette().base());
  if (!plan_) {
    p.drawText(rect(), Qt::AlignCenter, tr("No plan: the graph has errors."));
    return;
  }
  const std::vector<Box> boxes = layout_boxes();
  const double pass_w = (width() - left - right) / double(std::max<size_t>(plan_->passes.size(), 1));
  p.setPen(palette().color(QPalette::Mid));
  for (size_t i = 0; i < plan_->passes.size(); ++i) {
    const double x = left + double(i) * pass_w;
    p.drawLine(QPointF(x, top), QPointF(x, height() - bottom));
    p.drawText(QRectF(x, height() - bottom + 4, pass_w, 18), Qt::AlignHCenter, QString::number(i));
  }
  // Block labels from the first and last box of each block.
  std::map<int, QRectF> extent;
  for (const Box& box : boxes) {
    const int b = plan_->resources[size_t(box.resource)].placement.block;
    extent[b] = extent.count(b) ? extent[b].united(box.rect) : box.rect;
  }
  p.setPen(palette().color(QPalette::Text));
  for (const auto& [b, r] : extent) {
    const QString name = b == 0 ? tr("transient\n(aliased)") : tr("persistent");
    p.drawText(QRectF(4, r.top(), left - 10, std::max(r.height(), 30.0)), Qt::AlignRight | Qt::AlignVCenter,
               name + QStringLiteral("\n") + QString::fromStdString(format_bytes(plan_->blocks[size_t(b)].size)));
  }
  for (const Box& box : boxes) {
    const PlanResource& res = plan_->resources[size_t(box.resource)];
    const QColor c = QColor::fromHsvF(std::fmod(0.61803 * box.resource, 1.0), 0.45, 0.9);
    p.setPen(QPen(c.darker(160), 1));
    p.setBrush(c);
    p.drawRect(box.rect.adjusted(1, 0, -1, 0));
    if (box.rect.height() >= 13 && box.rect.width() > 40) {
      p.setPen(Qt::black);
      p.drawText(
          box.rect.adjusted(4, 0, -2, 0), Qt::AlignVCenter | Qt::AlignLeft,
          p.fontMetrics().elidedText(QString::fromStdString(res.desc.name), Qt::ElideRight, int(box.rect.width() - 6)));
    }
  }
  p.setPen(palette().color(QPalette::Text));
  p.drawText(QRectF(left, 2, width() - left, top - 4), Qt::AlignLeft | Qt::AlignVCenter,
             tr("memory offset (down) against pass (across); boxes in the same rows share bytes at different times"));
}

bool TimelineWidget::event(QEvent* e) {
  if (e->type() != QEvent::ToolTip || !plan_) return QWidget::event(e);
  auto* help = static_cast<QHelpEvent*>(e);
  for (const Box& box : layout_boxes())
    if (box.rect.contains(help->pos())) {
      const PlanResource& r = plan_->resources[size_t(box.resource)];
      QToolTip::showText(help->globalPos(),
                         tr("%1\n%2 %3x%4, %5\npasses %6 to %7, offset %8")
                             .arg(QString::fromStdString(r.desc.name), QString::fromUtf8(r.desc.format.data(), qsizetype(r.desc.format.size())))
                             .arg(r.desc.width)
                             .arg(r.desc.height)
                             .arg(QString::fromStdString(format_bytes(r.placement.size)))
                             .arg(r.first)
                             .arg(r.last)
                             .arg(QString::fromStdString(format_bytes(r.placement.offset))),
                         this);
      return true;
    }
  QToolTip::hideText();
  return true;
}

}  // namespace lg::editor
