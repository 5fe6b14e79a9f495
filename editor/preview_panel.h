// The Preview dock's contents: which port to show (a combo box above the image), an exposure
// in EV and a channel, the image, and the float RGBA of the pixel under the cursor. It keeps
// the last image's float pixels, so exposure and channel change what is shown at once, without
// rendering again; choosing another port asks for a render (port_changed).
#pragma once

#include <QWidget>

#include "editor/preview.h"
#include "editor/preview_display.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace lg::editor {

class PreviewPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PreviewPanel(QWidget* parent = nullptr);

  // The graph's ports; the chosen one stays chosen while the graph has it, else main output.
  void set_ports(const std::vector<PreviewPort>& ports);
  const PreviewPort& port() const;
  void choose_port(const QString& name);  // "main output" or a port's name
  void set_exposure(double ev);
  void set_channel(PreviewChannel channel);
  // The frame size to render at: the image area's.
  QSize render_size() const;

  void show_image(PreviewImage image, const QString& error);
  const PreviewImage& image() const { return image_; }
  QLabel* image_label() const { return label_; }
  QLabel* readout() const { return readout_; }
  // The pixel of the image at a point of image_label(), which shows it centred at 1:1.
  QPoint pixel_at(QPoint label_point) const;

 signals:
  void port_changed();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void redisplay();

  std::vector<PreviewPort> ports_{PreviewPort{}};
  QComboBox* port_box_;
  QDoubleSpinBox* exposure_;
  QComboBox* channel_;
  QLabel* label_;
  QLabel* note_;
  QLabel* readout_;
  PreviewImage image_;
};

}  // namespace lg::editor
