#include "editor/preview_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>

namespace lg::editor {

static QString shown_name(const PreviewPort& port) {
  return port.name.empty() ? PreviewPanel::tr("main output") : QString::fromStdString(port.name);
}

PreviewPanel::PreviewPanel(QWidget* parent)
    : QWidget(parent),
      port_box_(new QComboBox(this)),
      exposure_(new QDoubleSpinBox(this)),
      channel_(new QComboBox(this)),
      label_(new QLabel(this)),
      note_(new QLabel(this)),
      readout_(new QLabel(this)) {
  port_box_->addItem(shown_name(ports_.front()));
  port_box_->setToolTip(tr("The port to show: the main output, any node's output, a G-buffer component"));
  exposure_->setRange(-16, 16);
  exposure_->setSingleStep(0.5);
  exposure_->setDecimals(1);
  exposure_->setSuffix(tr(" EV"));
  exposure_->setToolTip(tr("Scales linear images by 2^EV; display-encoded (LDR) ones show as they are"));
  channel_->addItems({tr("RGB"), tr("R"), tr("G"), tr("B"), tr("A")});
  channel_->setToolTip(tr("All channels, or one as grey"));
  label_->setAlignment(Qt::AlignCenter);
  label_->setWordWrap(true);  // for errors
  label_->setMinimumSize(320, 180);
  label_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);  // the dock sizes it, not its image
  label_->setMouseTracking(true);
  label_->installEventFilter(this);
  readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* controls = new QHBoxLayout;
  controls->addWidget(port_box_, 1);
  controls->addWidget(exposure_);
  controls->addWidget(channel_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addLayout(controls);
  layout->addWidget(label_, 1);
  auto* footer = new QHBoxLayout;
  footer->addWidget(note_);
  footer->addStretch();
  footer->addWidget(readout_);
  layout->addLayout(footer);

  connect(port_box_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] { emit port_changed(); });
  connect(exposure_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &PreviewPanel::redisplay);
  connect(channel_, qOverload<int>(&QComboBox::currentIndexChanged), this, &PreviewPanel::redisplay);
}

void PreviewPanel::set_ports(const std::vector<PreviewPort>& ports) {
  // A name says the port and component: the same names are the same list.
  const auto same_name = [](const PreviewPort& a, const PreviewPort& b) { return a.name == b.name; };
  if (std::equal(ports.begin(), ports.end(), ports_.begin(), ports_.end(), same_name)) return;
  const std::string chosen = port().name;
  ports_ = ports;
  const QSignalBlocker quiet(port_box_);
  port_box_->clear();
  int keep = 0;
  for (size_t i = 0; i < ports_.size(); ++i) {
    port_box_->addItem(shown_name(ports_[i]));
    if (ports_[i].name == chosen) keep = int(i);
  }
  port_box_->setCurrentIndex(keep);
}

const PreviewPort& PreviewPanel::port() const {
  return ports_[std::max(port_box_->currentIndex(), 0)];
}

void PreviewPanel::choose_port(const QString& name) {
  port_box_->setCurrentIndex(std::max(port_box_->findText(name), 0));
}

void PreviewPanel::set_exposure(double ev) {
  exposure_->setValue(ev);
}

void PreviewPanel::set_channel(PreviewChannel channel) {
  channel_->setCurrentIndex(int(channel));
}

QSize PreviewPanel::render_size() const {
  return label_->size();
}

void PreviewPanel::show_image(PreviewImage image, const QString& error) {
  image_ = std::move(image);
  readout_->clear();
  if (image_.empty()) {
    label_->setText(error);
    note_->clear();
    return;
  }
  note_->setText(image_.note);
  redisplay();
}

void PreviewPanel::redisplay() {
  if (image_.empty()) return;
  const auto channel = PreviewChannel(channel_->currentIndex());
  label_->setPixmap(QPixmap::fromImage(display_image(image_, exposure_->value(), channel)));
}

QPoint PreviewPanel::pixel_at(QPoint label_point) const {
  const QPoint origin((label_->width() - image_.width) / 2, (label_->height() - image_.height) / 2);
  return label_point - origin;
}

bool PreviewPanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == label_ && event->type() == QEvent::MouseMove) {
    const QPoint p = pixel_at(static_cast<QMouseEvent*>(event)->pos());
    readout_->setText(pixel_readout(image_, p.x(), p.y()));
  } else if (watched == label_ && event->type() == QEvent::Leave) {
    readout_->clear();
  }
  return QWidget::eventFilter(watched, event);
}

}  // namespace lg::editor
